"""Costmaps as messages: costmap_2d's ``Costmap2DPublisher`` translation and the footprint.

Costs become OccupancyGrid values through costmap_2d's table: 0 -> 0, 253
(inscribed) -> 99, 254 (lethal) -> 100, 255 (unknown) -> -1, and 1..252 ->
``1 + 97 * (cost - 1) // 251`` (1..98).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.navigation.costmap_grid import Costmap2D


def _table() -> np.ndarray:
    table = np.zeros(256, dtype=np.int8)
    cost = np.arange(1, 253)
    table[1:253] = 1 + (97 * (cost - 1)) // 251
    table[253], table[254], table[255] = 99, 100, -1
    return table


#: Cost (index) to OccupancyGrid value.
COST_TRANSLATION = _table()


def translate(costs: np.ndarray) -> np.ndarray:
    """OccupancyGrid values (int8) of costs (uint8)."""
    return COST_TRANSLATION[np.asarray(costs, dtype=np.uint8)]


def costmap_message(costmap: Costmap2D, stamp: Any) -> Any:
    """A ``nav_msgs/OccupancyGrid`` of ``costmap`` (``prepareGrid``)."""
    from workbench.msgs.nav_msgs import OccupancyGrid

    grid = OccupancyGrid()
    grid.header.frame_id = costmap.frame
    grid.header.stamp = stamp
    info = grid.info
    info.resolution = float(np.float32(costmap.resolution))
    info.width, info.height = costmap.size_x, costmap.size_y
    wx, wy = costmap.map_to_world(0, 0)
    info.origin.position.x = wx - costmap.resolution / 2
    info.origin.position.y = wy - costmap.resolution / 2
    info.origin.orientation.w = 1.0
    grid.data = translate(costmap.costs).reshape(-1)
    return grid


def footprint_message(polygon: np.ndarray, frame: str, stamp: Any) -> Any:
    """A ``geometry_msgs/PolygonStamped`` of an ``(N, 2)`` polygon (m) in ``frame``."""
    from workbench.msgs.geometry_msgs import Point32, PolygonStamped

    msg = PolygonStamped()
    msg.header.frame_id = frame
    msg.header.stamp = stamp
    msg.polygon.points = [Point32(x=float(x), y=float(y), z=0.0) for x, y in polygon]
    return msg


__all__ = ["COST_TRANSLATION", "costmap_message", "footprint_message", "translate"]
