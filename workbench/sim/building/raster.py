"""A building's pieces as an occupancy raster: which cells of a grid hold something at a height.

For comparing a map (a SLAM result, a map_server map) with the true walls, or for
checking that a robot fits through a plan.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from workbench.sim.building.plan import Piece


def blocked_cells(
    pieces: Iterable[Piece], xs: np.ndarray, ys: np.ndarray, band: tuple[float, float]
) -> np.ndarray:
    """Cells (rows along ``ys``, columns along ``xs``, cell centres in m) whose centre lies in
    a piece that reaches into the height ``band`` (low, high; m); shape ``(len(ys), len(xs))``."""
    gx, gy = np.meshgrid(np.asarray(xs, dtype=float), np.asarray(ys, dtype=float))
    blocked = np.zeros(gx.shape, dtype=bool)
    for piece in pieces:
        x, y, z, yaw = piece.pose
        half_z = piece.size[2] / 2
        if z + half_z < band[0] or z - half_z > band[1]:
            continue
        dx, dy = gx - x, gy - y
        if piece.shape == "cylinder":
            blocked |= dx * dx + dy * dy <= piece.radius**2
            continue
        c, s = np.cos(yaw), np.sin(yaw)
        u, v = c * dx + s * dy, -s * dx + c * dy
        blocked |= (np.abs(u) <= piece.size[0] / 2) & (np.abs(v) <= piece.size[1] / 2)
    return blocked
