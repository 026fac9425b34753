"""A 2-D cost grid with costmap_2d's geometry (``costmap_2d/src/costmap_2d.cpp``, Noetic).

Cell ``(mx, my)`` covers ``[origin_x + mx * resolution, origin_x + (mx + 1) * resolution)``
in x (likewise y); ``costs[my, mx]`` holds its one-byte cost (see
:mod:`workbench.navigation.costs`). World to map truncates as costmap_2d's
``worldToMap`` does; map to world gives the cell centre (``mapToWorld``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass
class Costmap2D:
    """A costmap: one byte per cell in a frame.

    Attributes:
        costs: ``uint8`` costs, shape ``(size_y, size_x)``, ``costs[my, mx]``.
        resolution: Cell size (m).
        origin_x: World x of cell (0, 0)'s outer corner in ``frame`` (m).
        origin_y: World y of that corner (m).
        frame: The frame the costmap lives in (``map``, ``odom``).
    """

    costs: np.ndarray
    resolution: float
    origin_x: float
    origin_y: float
    frame: str = "map"

    @property
    def size_x(self) -> int:
        """Cells along x."""
        return int(self.costs.shape[1])

    @property
    def size_y(self) -> int:
        """Cells along y."""
        return int(self.costs.shape[0])

    def world_to_map(self, x: float, y: float) -> tuple[int, int] | None:
        """The cell ``(mx, my)`` holding world point ``(x, y)`` (m), or None outside."""
        if not (x >= self.origin_x and y >= self.origin_y):  # also refuses NaN
            return None
        fx = (x - self.origin_x) / self.resolution
        fy = (y - self.origin_y) / self.resolution
        if not (fx < self.size_x and fy < self.size_y):
            return None
        mx, my = int(fx), int(fy)
        if mx >= self.size_x or my >= self.size_y:
            return None
        return mx, my

    def map_to_world(self, mx: int, my: int) -> tuple[float, float]:
        """The world position (m) of cell ``(mx, my)``'s centre."""
        return (
            self.origin_x + (mx + 0.5) * self.resolution,
            self.origin_y + (my + 0.5) * self.resolution,
        )

    def world_to_map_array(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`world_to_map` for an ``(N, 2)`` array of world points (m).

        Returns:
            ``(mx, my, inside)``: integer cell indices (meaningful where ``inside``)
            and a boolean mask of the points inside the grid.
        """
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        fx = (xy[:, 0] - self.origin_x) / self.resolution
        fy = (xy[:, 1] - self.origin_y) / self.resolution
        inside = (fx >= 0) & (fy >= 0) & (fx < self.size_x) & (fy < self.size_y)
        mx = np.where(inside, fx, 0).astype(np.int64)
        my = np.where(inside, fy, 0).astype(np.int64)
        inside &= (mx < self.size_x) & (my < self.size_y)
        return mx, my, inside

    def copy(self) -> Costmap2D:
        """An independent copy (costs copied)."""
        return Costmap2D(
            self.costs.copy(), self.resolution, self.origin_x, self.origin_y, self.frame
        )

    # ------------------------------------------------------------------ helpers
    def cell_distance(self, world_dist: float) -> int:
        """A distance (m) in whole cells, rounded up (``cellDistance``)."""
        return int(max(0.0, math.ceil(world_dist / self.resolution)))

    def size_in_meters(self) -> tuple[float, float]:
        """``getSizeInMetersX/Y``: ``(size - 1 + 0.5) * resolution`` (m), as costmap_2d has it."""
        return (self.size_x - 0.5) * self.resolution, (self.size_y - 0.5) * self.resolution

    def resize(
        self,
        size_x: int,
        size_y: int,
        resolution: float,
        origin_x: float,
        origin_y: float,
        fill: int,
    ) -> None:
        """Make this a ``size_x`` x ``size_y`` grid filled with ``fill`` (``resizeMap``)."""
        self.costs = np.full((size_y, size_x), fill, dtype=np.uint8)
        self.resolution = float(resolution)
        self.origin_x, self.origin_y = float(origin_x), float(origin_y)

    def update_origin(self, new_origin_x: float, new_origin_y: float, fill: int) -> None:
        """Move the window to a new origin, keeping the overlap (``updateOrigin``).

        The origin moves by whole cells (grid-aligned); cells that come into view are
        set to ``fill``.
        """
        cell_ox = int((new_origin_x - self.origin_x) / self.resolution)
        cell_oy = int((new_origin_y - self.origin_y) / self.resolution)
        if cell_ox == 0 and cell_oy == 0:
            return
        sx, sy = self.size_x, self.size_y
        x0, y0 = min(max(cell_ox, 0), sx), min(max(cell_oy, 0), sy)
        x1, y1 = min(max(cell_ox + sx, 0), sx), min(max(cell_oy + sy, 0), sy)
        kept = self.costs[y0:y1, x0:x1].copy()
        self.costs[:] = fill
        self.origin_x += cell_ox * self.resolution
        self.origin_y += cell_oy * self.resolution
        tx, ty = x0 - cell_ox, y0 - cell_oy
        self.costs[ty : ty + kept.shape[0], tx : tx + kept.shape[1]] = kept


__all__ = ["Costmap2D"]
