"""Occupancy cells as a ``nav_msgs/OccupancyGrid`` message (map_server's and gmapping's /map)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.spatial import quaternion_from_yaw


def occupancy_grid_message(
    cells: np.ndarray,
    resolution: float,
    origin: Sequence[float],
    frame_id: str,
    stamp: Any,
    *,
    load_time: Any = None,
) -> Any:
    """An OccupancyGrid of ``(height, width)`` int8 ``cells`` (row 0 at the origin).

    Args:
        cells: -1 unknown, 0..100 occupancy.
        resolution: Cell size, m (sent as the message's float32).
        origin: ``(x, y, yaw)`` of cell (0, 0)'s corner in ``frame_id``, m and rad.
        frame_id: The map's frame.
        stamp: The header's stamp (a ``Time``).
        load_time: ``info.map_load_time`` (map_server sets it; default zero).
    """
    from workbench.msgs.nav_msgs import OccupancyGrid

    grid = OccupancyGrid()
    grid.header.stamp = stamp
    grid.header.frame_id = frame_id
    info = grid.info
    if load_time is not None:
        info.map_load_time = load_time
    info.resolution = float(np.float32(resolution))
    info.height, info.width = (int(n) for n in cells.shape)
    info.origin.position.x, info.origin.position.y = float(origin[0]), float(origin[1])
    q = info.origin.orientation
    q.x, q.y, q.z, q.w = (float(v) for v in quaternion_from_yaw(float(origin[2])))
    grid.data = cells.reshape(-1)
    return grid
