"""Occupancy grids: log-odds mapping from laser scans and the ``nav_msgs/OccupancyGrid`` layout.

Conventions follow ``nav_msgs/OccupancyGrid`` and REP 103: the grid lies in the
``map`` frame, ``origin`` ``(x, y, yaw)`` is the pose of the corner of cell
``(0, 0)``, cells are ``resolution`` metres square, and the data is row-major
starting at that cell (row index = y cell, column index = x cell). Values are
occupancy probabilities in percent, ``0..100``, with ``-1`` for unknown.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from workbench.mapping.errors import MappingError

#: Log-odds added to a cell where a beam ends (p = 0.7).
LOG_ODDS_HIT = 0.85
#: Log-odds added to each cell a beam passes through (p = 0.4).
LOG_ODDS_MISS = -0.4
#: Log-odds are clamped to this range so that a changed world can be re-mapped.
LOG_ODDS_CLAMP = 5.0
#: Largest grid :meth:`OccupancyGrid.covering` will allocate (cells).
MAX_CELLS = 100_000_000


def _cells(
    xs: np.ndarray, ys: np.ndarray, resolution: float, origin: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Cell indices ``(ix, iy)`` of world points ``(xs, ys)`` for a grid with this origin."""
    lx = xs - origin[0]
    ly = ys - origin[1]
    if origin[2] != 0.0:  # only a rotated grid needs turning
        c, s = np.cos(origin[2]), np.sin(origin[2])
        lx, ly = c * lx + s * ly, -s * lx + c * ly
    return np.floor(lx / resolution).astype(np.int64), np.floor(ly / resolution).astype(np.int64)


@dataclass
class GridMap:
    """An occupancy grid as ``nav_msgs/OccupancyGrid`` holds it.

    Attributes:
        data: ``(height, width)`` int8 array, row 0 at the origin; -1 unknown, 0..100 percent.
        resolution: Cell size in metres.
        origin: Pose ``(x, y, yaw)`` of cell (0, 0)'s corner in the map frame (m, rad).
    """

    data: np.ndarray
    resolution: float
    origin: np.ndarray = field(default_factory=lambda: np.zeros(3))

    def __post_init__(self) -> None:
        self.data = np.asarray(self.data, dtype=np.int8)
        if self.data.ndim != 2:
            raise MappingError(f"map data must be 2-D (height, width), got shape {self.data.shape}")
        if not (np.isfinite(self.resolution) and self.resolution > 0):
            raise MappingError(f"map resolution must be positive, got {self.resolution}")
        self.origin = np.asarray(self.origin, dtype=float).reshape(3)

    @property
    def width(self) -> int:
        """Number of cells along x."""
        return int(self.data.shape[1])

    @property
    def height(self) -> int:
        """Number of cells along y."""
        return int(self.data.shape[0])

    def flat(self) -> np.ndarray:
        """The row-major 1-D data array of the ``nav_msgs/OccupancyGrid`` message."""
        return self.data.reshape(-1).copy()

    @classmethod
    def from_flat(
        cls,
        data: np.ndarray | list[int],
        width: int,
        height: int,
        resolution: float,
        origin: np.ndarray | tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> GridMap:
        """Build from the message layout (``info.width``, ``info.height``, row-major ``data``)."""
        array = np.asarray(data, dtype=np.int8)
        if array.size != width * height:
            raise MappingError(
                f"map data has {array.size} cells but width*height is {width}*{height}"
            )
        return cls(array.reshape(height, width), resolution, np.asarray(origin, dtype=float))

    def world_to_cell(self, points: np.ndarray) -> np.ndarray:
        """Cell indices ``(N, 2)`` as ``(ix, iy)`` of world points ``(N, 2)``; may lie outside."""
        points = np.atleast_2d(points)
        ix, iy = _cells(points[:, 0], points[:, 1], self.resolution, self.origin)
        return np.stack([ix, iy], axis=1)

    def cell_to_world(self, cells: np.ndarray) -> np.ndarray:
        """World coordinates ``(N, 2)`` of the centres of cells ``(N, 2)`` given as ``(ix, iy)``."""
        cells = np.atleast_2d(cells).astype(float)
        lx = (cells[:, 0] + 0.5) * self.resolution
        ly = (cells[:, 1] + 0.5) * self.resolution
        c, s = np.cos(self.origin[2]), np.sin(self.origin[2])
        return np.stack(
            [self.origin[0] + c * lx - s * ly, self.origin[1] + s * lx + c * ly], axis=1
        )

    def trinary(self, free_max: int = 25, occupied_min: int = 65) -> GridMap:
        """The map reduced to 0 / 100 / -1 with map_saver's default thresholds (percent)."""
        out = np.full_like(self.data, -1)
        out[(self.data >= 0) & (self.data <= free_max)] = 0
        out[(self.data >= occupied_min) & (self.data <= 100)] = 100
        return GridMap(out, self.resolution, self.origin.copy())


class OccupancyGrid:
    """A log-odds occupancy grid updated from laser scans.

    Args:
        width: Cells along x.
        height: Cells along y.
        resolution: Cell size (m).
        origin: Pose ``(x, y, yaw)`` of cell (0, 0)'s corner in the map frame.
        hit: Log-odds added where a beam ends.
        miss: Log-odds added along a beam.
        clamp: Log-odds are kept in ``[-clamp, clamp]``.
    """

    def __init__(
        self,
        width: int,
        height: int,
        resolution: float = 0.05,
        origin: np.ndarray | tuple[float, float, float] = (0.0, 0.0, 0.0),
        *,
        hit: float = LOG_ODDS_HIT,
        miss: float = LOG_ODDS_MISS,
        clamp: float = LOG_ODDS_CLAMP,
    ) -> None:
        if width <= 0 or height <= 0:
            raise MappingError(f"grid size must be positive, got {width} x {height}")
        if not (np.isfinite(resolution) and resolution > 0):
            raise MappingError(f"grid resolution must be positive, got {resolution}")
        self.resolution = float(resolution)
        self.origin = np.asarray(origin, dtype=float).reshape(3)
        self.log_odds = np.zeros((int(height), int(width)), dtype=np.float32)
        self.observed = np.zeros((int(height), int(width)), dtype=bool)
        self.hit, self.miss, self.clamp = float(hit), float(miss), float(clamp)

    @classmethod
    def covering(
        cls,
        points: np.ndarray,
        resolution: float = 0.05,
        margin: float = 1.0,
        **kwargs: float,
    ) -> OccupancyGrid:
        """An axis-aligned grid that covers world points ``(N, 2)`` plus ``margin`` metres."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        points = points[np.all(np.isfinite(points), axis=1)]
        if len(points) == 0:
            raise MappingError("cannot size a grid from no points")
        low = np.floor((points.min(axis=0) - margin) / resolution) * resolution
        high = points.max(axis=0) + margin
        size = np.ceil((high - low) / resolution).astype(int) + 1
        if float(size[0]) * float(size[1]) > MAX_CELLS:
            raise MappingError(
                f"a grid covering {high[0] - low[0]:.0f} m x {high[1] - low[1]:.0f} m at "
                f"{resolution} m would need {size[0]} x {size[1]} cells",
                hint="use a coarser resolution or a smaller max range",
            )
        return cls(int(size[0]), int(size[1]), resolution, (low[0], low[1], 0.0), **kwargs)

    @property
    def width(self) -> int:
        """Cells along x."""
        return int(self.log_odds.shape[1])

    @property
    def height(self) -> int:
        """Cells along y."""
        return int(self.log_odds.shape[0])

    def integrate_scan(
        self,
        pose: np.ndarray,
        ranges: np.ndarray,
        angles: np.ndarray,
        *,
        max_range: float = np.inf,
        min_range: float = 0.0,
        free_range: float | None = None,
    ) -> None:
        """Update the grid with one scan taken by a sensor at ``pose``.

        Every cell a beam passes through gets a miss, the cell where it ends a
        hit (a cell both passed and hit in the same scan counts as hit). Beams
        below or at ``min_range`` or NaN mark nothing. Beams at or beyond
        ``max_range`` or infinite mark nothing unless ``free_range`` is given:
        then beams reading ``max_range`` (within 1 cm) or +inf ("no return"),
        and every beam longer than ``free_range`` but short of ``max_range``,
        mark free space up to ``free_range`` and no hit (as GMapping's
        ``maxUrange``); beams beyond ``max_range`` (error codes) mark nothing.

        Args:
            pose: Sensor pose ``(x, y, theta)`` in the map frame (m, rad).
            ranges: Beam lengths (m).
            angles: Beam directions in the sensor frame (rad), same length.
            max_range: Readings ``>= max_range`` mean "no return".
            min_range: Readings ``<= min_range`` are invalid.
            free_range: Longest free-space trace (m); None: no-return beams mark nothing.
        """
        ranges = np.asarray(ranges, dtype=float)
        angles = np.asarray(angles, dtype=float)
        with np.errstate(invalid="ignore"):
            ok = np.isfinite(ranges) & (ranges > min_range) & (ranges < max_range)
            hit = ok.copy()
            if free_range is not None:
                # At the sensor's maximum (within a centimetre) or +inf: no return. Beyond
                # it: an error code (a SICK's 81.83 m "dazzled"), which marks nothing.
                no_return = (np.abs(ranges - max_range) <= 0.01) | (ranges == np.inf)
                hit &= ranges < free_range
                ok = (ok | no_return) & ~np.isnan(ranges) & (ranges > min_range)
                ranges = np.where(hit, ranges, min(free_range, max_range))
        if not ok.any():
            return
        r = ranges[ok]
        ends_hit = hit[ok]
        direction = angles[ok] + pose[2]
        reach_x, reach_y = r * np.cos(direction), r * np.sin(direction)
        # Sample each beam every half cell from the sensor up to (not including) its end.
        steps = np.maximum(np.ceil(r / (0.5 * self.resolution)).astype(np.int64), 1)
        beam = np.repeat(np.arange(len(r)), steps)
        t = np.arange(beam.size) - np.repeat(np.cumsum(steps) - steps, steps)
        t = t * (1.0 / steps)[beam]
        free = self._flat_index(pose[0] + reach_x[beam] * t, pose[1] + reach_y[beam] * t)
        hits = self._flat_index(pose[0] + reach_x[ends_hit], pose[1] + reach_y[ends_hit])
        flat_lo = self.log_odds.reshape(-1)
        flat_obs = self.observed.reshape(-1)
        is_hit = np.zeros(flat_lo.size, dtype=bool)
        is_hit[hits] = True
        free = free[~is_hit[free]]
        # A cell listed twice changes once: fancy-indexed ``+=`` writes each cell once.
        flat_lo[free] += self.miss
        flat_lo[hits] += self.hit
        for touched in (free, hits):
            flat_lo[touched] = np.clip(flat_lo[touched], -self.clamp, self.clamp)
        flat_obs[free] = True
        flat_obs[hits] = True

    def grow_to(self, points: np.ndarray, margin: float = 1.0) -> bool:
        """Enlarge the grid (keeping its cells) so that it covers ``points`` ``(N, 2)`` plus
        ``margin`` m; only for grids whose origin has no rotation. Returns whether it grew."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        points = points[np.all(np.isfinite(points), axis=1)]
        if len(points) == 0:
            return False
        if self.origin[2] != 0.0:
            raise MappingError("only an axis-aligned grid can grow")
        res = self.resolution
        lo_cells = np.floor((points.min(axis=0) - margin - self.origin[:2]) / res).astype(int)
        hi_cells = np.ceil((points.max(axis=0) + margin - self.origin[:2]) / res).astype(int)
        add_lo = np.maximum(-lo_cells, 0)  # (x, y) cells to add below
        add_hi = np.maximum(hi_cells - np.array([self.width, self.height]), 0)
        if not (add_lo.any() or add_hi.any()):
            return False
        # Grow by at least a quarter of the size, so a moving robot does not regrow every scan.
        grow_lo = np.where(
            add_lo > 0, np.maximum(add_lo, np.array([self.width, self.height]) // 4), 0
        )
        grow_hi = np.where(
            add_hi > 0, np.maximum(add_hi, np.array([self.width, self.height]) // 4), 0
        )
        width = self.width + int(grow_lo[0] + grow_hi[0])
        height = self.height + int(grow_lo[1] + grow_hi[1])
        if float(width) * float(height) > MAX_CELLS:
            raise MappingError(f"the map would need {width} x {height} cells")
        log_odds = np.zeros((height, width), dtype=np.float32)
        observed = np.zeros((height, width), dtype=bool)
        rows = slice(int(grow_lo[1]), int(grow_lo[1]) + self.height)
        cols = slice(int(grow_lo[0]), int(grow_lo[0]) + self.width)
        log_odds[rows, cols] = self.log_odds
        observed[rows, cols] = self.observed
        self.log_odds, self.observed = log_odds, observed
        self.origin = self.origin - np.array([grow_lo[0] * res, grow_lo[1] * res, 0.0])
        return True

    def _flat_index(self, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
        """Flat cell index ``row * width + column`` of each world point inside the grid."""
        ix, iy = _cells(xs, ys, self.resolution, self.origin)
        inside = (ix >= 0) & (ix < self.width) & (iy >= 0) & (iy < self.height)
        return iy[inside] * self.width + ix[inside]

    def probabilities(self) -> np.ndarray:
        """Occupancy probability per cell, ``(height, width)``; 0.5 where never observed."""
        return 1.0 / (1.0 + np.exp(-self.log_odds.astype(float)))

    def to_map(self) -> GridMap:
        """The grid in ``nav_msgs/OccupancyGrid`` form (percent, -1 where never observed)."""
        percent = np.rint(self.probabilities() * 100.0).astype(np.int8)
        data = np.where(self.observed, percent, np.int8(-1)).astype(np.int8)
        return GridMap(data, self.resolution, self.origin.copy())
