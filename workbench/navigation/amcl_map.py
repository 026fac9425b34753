"""AMCL's map: occupancy states, free cells, the distance field and grid ray casting.

amcl converts a ``nav_msgs/OccupancyGrid`` as ``AmclNode::convertMap`` does: 0 is
free, 100 occupied, anything else unknown. ``map_update_cspace`` then stores per cell
the distance to the nearest occupied cell, capped at ``laser_likelihood_max_dist``
(cells further than ``floor(max_dist / resolution)`` cells read exactly the cap); here
that field comes from one Euclidean distance transform instead of amcl's brushfire.

Cell ``(i, j)`` covers ``[ox + i r, ox + (i + 1) r) x [oy + j r, oy + (j + 1) r)``,
as map_server writes it. (amcl's ``MAP_GXWX`` rounds to the nearest cell *corner*,
which shifts its whole map by half a cell; that bias is not reproduced.) The map's
origin yaw is ignored, as amcl ignores it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import ndimage

#: amcl's occupancy states (``map_cell_t.occ_state``).
FREE, UNKNOWN, OCCUPIED = -1, 0, 1


@dataclass
class AmclMap:
    """An occupancy map as amcl holds it.

    Attributes:
        states: ``(height, width)`` int8 occupancy states (FREE, UNKNOWN, OCCUPIED).
        resolution: Cell size (m).
        origin_x: World x of cell (0, 0)'s outer corner (m).
        origin_y: World y of that corner (m).
        max_occ_dist: The distance field's cap (m); 0 until :meth:`update_cspace`.
        occ_dist: ``(height, width)`` distance to the nearest occupied cell (m).
    """

    states: np.ndarray
    resolution: float
    origin_x: float
    origin_y: float
    max_occ_dist: float = 0.0
    occ_dist: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    _free: np.ndarray | None = field(default=None, repr=False)

    @classmethod
    def from_cells(
        cls, cells: np.ndarray, resolution: float, origin: tuple[float, float]
    ) -> AmclMap:
        """amcl's map from OccupancyGrid cells ``(height, width)`` (-1, 0..100).

        Args:
            cells: Occupancy values, row 0 at the origin.
            resolution: Cell size (m).
            origin: World ``(x, y)`` of cell (0, 0)'s outer corner (m).
        """
        cells = np.asarray(cells)
        states = np.full(cells.shape, UNKNOWN, dtype=np.int8)
        states[cells == 0] = FREE
        states[cells == 100] = OCCUPIED
        return cls(states, float(resolution), float(origin[0]), float(origin[1]))

    @classmethod
    def from_message(cls, grid: object) -> AmclMap:
        """amcl's map from a ``nav_msgs/OccupancyGrid`` message."""
        info = grid.info  # type: ignore[attr-defined]
        cells = np.asarray(grid.data, dtype=np.int16).reshape(int(info.height), int(info.width))  # type: ignore[attr-defined]
        origin = (float(info.origin.position.x), float(info.origin.position.y))
        return cls.from_cells(cells, float(info.resolution), origin)

    @property
    def size_x(self) -> int:
        """Cells along x (the message's width)."""
        return int(self.states.shape[1])

    @property
    def size_y(self) -> int:
        """Cells along y (the message's height)."""
        return int(self.states.shape[0])

    def update_cspace(self, max_occ_dist: float) -> None:
        """Fill :attr:`occ_dist`: distance to the nearest occupied cell, capped (``map_update_cspace``)."""
        self.max_occ_dist = float(max_occ_dist)
        occupied = self.states == OCCUPIED
        if not occupied.any():
            self.occ_dist = np.full(self.states.shape, self.max_occ_dist)
            return
        cells = ndimage.distance_transform_edt(~occupied)
        radius = int(self.max_occ_dist / self.resolution)
        self.occ_dist = np.where(cells > radius, self.max_occ_dist, cells * self.resolution)

    def cells_of(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Cell indices ``(i, j)`` of world points and whether they lie on the map."""
        i = np.floor((np.asarray(x) - self.origin_x) / self.resolution).astype(np.int64)
        j = np.floor((np.asarray(y) - self.origin_y) / self.resolution).astype(np.int64)
        valid = (i >= 0) & (i < self.size_x) & (j >= 0) & (j < self.size_y)
        return i, j, valid

    def free_cells(self) -> np.ndarray:
        """``(K, 2)`` indices ``(i, j)`` of the free cells (amcl's ``free_space_indices``)."""
        if self._free is None:
            rows, cols = np.nonzero(self.states == FREE)
            self._free = np.column_stack([cols, rows]).astype(np.int64)
        return self._free

    def uniform_poses(self, count: int, rng: np.random.Generator) -> np.ndarray:
        """``(count, 3)`` poses at random free cells' centres with random headings.

        amcl's ``uniformPoseGenerator`` (``NEW_UNIFORM_SAMPLING``): a free cell drawn
        uniformly, a heading uniform in ``[-pi, pi)``. A map without free cells gives
        poses over the whole map.
        """
        free = self.free_cells()
        if len(free) == 0:
            ij = np.column_stack(
                [rng.integers(0, self.size_x, count), rng.integers(0, self.size_y, count)]
            )
        else:
            ij = free[rng.integers(0, len(free), count)]
        poses = np.empty((count, 3))
        poses[:, 0] = self.origin_x + (ij[:, 0] + 0.5) * self.resolution
        poses[:, 1] = self.origin_y + (ij[:, 1] + 0.5) * self.resolution
        poses[:, 2] = rng.random(count) * 2 * np.pi - np.pi
        return poses

    def calc_ranges(
        self,
        pose: np.ndarray,
        angles: np.ndarray,
        max_range: float,
        *,
        unknown_blocks: bool = True,
    ) -> np.ndarray:
        """Ranges from ``pose`` along ``angles`` to the first non-free cell (``map_calc_range``).

        Marches each beam in steps of half a cell; a beam that leaves the map or meets
        an occupied or unknown cell stops there, one that meets nothing reads ``max_range``.

        Args:
            pose: Sensor pose ``(x, y, theta)`` in the map frame (m, rad).
            angles: Beam angles in the sensor frame (rad).
            max_range: The sensor's range (m).
            unknown_blocks: False: only occupied cells stop a beam (to simulate a laser in
                the mapped world, where unknown cells are merely unseen).
        """
        step = self.resolution / 2.0
        t = np.arange(0.0, max_range + step, step)
        direction = np.asarray(angles, dtype=float) + pose[2]
        x = pose[0] + np.cos(direction)[:, None] * t[None, :]
        y = pose[1] + np.sin(direction)[:, None] * t[None, :]
        i, j, valid = self.cells_of(x, y)
        blocked = ~valid
        state = self.states[j[valid], i[valid]]
        blocked[valid] = state != FREE if unknown_blocks else state == OCCUPIED
        hit = blocked.any(axis=1)
        first = np.argmax(blocked, axis=1)
        return np.where(hit, np.minimum(t[first], max_range), max_range)


__all__ = ["FREE", "OCCUPIED", "UNKNOWN", "AmclMap"]
