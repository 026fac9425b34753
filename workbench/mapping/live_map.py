"""What a live SLAM node publishes: the grid as ``nav_msgs/OccupancyGrid`` cells within
GMapping's initial bounds, planar poses from tf transforms, the pose entropy."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from workbench.mapping.grid import OccupancyGrid


def gmapping_cells(
    grid: OccupancyGrid, bounds: tuple[float, float, float, float]
) -> tuple[np.ndarray, tuple[float, float]]:
    """The grid's cells as slam_gmapping publishes them, padded to ``bounds``.

    A cell never observed is -1, one more likely occupied than free 100, else 0
    (GMapping's map is also only 100, 0 and -1). The map covers at least
    ``bounds = (xmin, ymin, xmax, ymax)`` and grows with the grid beyond them.

    Returns:
        The cells ``(height, width)`` (``int8``, row 0 at the lowest y) and the map
        origin ``(x, y)`` of cell (0, 0)'s corner.
    """
    res = grid.resolution
    ox, oy = float(grid.origin[0]), float(grid.origin[1])
    xmin, ymin, xmax, ymax = bounds
    lo_x = math.floor(min(xmin, ox) / res + 1e-6) * res
    lo_y = math.floor(min(ymin, oy) / res + 1e-6) * res
    hi_x = max(xmax, ox + grid.width * res)
    hi_y = max(ymax, oy + grid.height * res)
    width = int(math.ceil((hi_x - lo_x) / res - 1e-6))
    height = int(math.ceil((hi_y - lo_y) / res - 1e-6))
    cells = np.full((height, width), -1, dtype=np.int8)
    col, row = int(round((ox - lo_x) / res)), int(round((oy - lo_y) / res))
    known = np.where(grid.log_odds > 0, np.int8(100), np.int8(0))
    part = np.where(grid.observed, known, np.int8(-1)).astype(np.int8)
    rows = min(grid.height, height - row)
    cols = min(grid.width, width - col)
    cells[row : row + rows, col : col + cols] = part[:rows, :cols]
    return cells, (lo_x, lo_y)


def rotation_matrix(q: Any) -> np.ndarray:
    """The rotation matrix of a ``geometry_msgs/Quaternion`` (normalised first)."""
    x, y, z, w = float(q.x), float(q.y), float(q.z), float(q.w)
    n = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = x / n, y / n, z / n, w / n
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def matrix(transform: Any) -> np.ndarray:
    """The 4x4 homogeneous matrix of a ``geometry_msgs/Transform``."""
    out = np.eye(4)
    out[:3, :3] = rotation_matrix(transform.rotation)
    t = transform.translation
    out[:3, 3] = (float(t.x), float(t.y), float(t.z))
    return out


def planar_pose(m: np.ndarray) -> np.ndarray:
    """``(x, y, theta)`` of a 4x4 pose seen from above: its origin and its x axis' heading."""
    return np.array([m[0, 3], m[1, 3], math.atan2(m[1, 0], m[0, 0])])


def up_in_sensor(base_to_laser: np.ndarray) -> float:
    """The z of a point 1 m above the laser (in the base frame), in the laser's frame.

    As slam_gmapping's check: 1 for a laser mounted upwards, -1 upside down,
    anything else a tilted laser.
    """
    point = np.array([0.0, 0.0, 1.0 + base_to_laser[2, 3], 1.0])
    return float((np.linalg.inv(base_to_laser) @ point)[2])


def pose_entropy(covariance: np.ndarray) -> float:
    """Differential entropy (nats) of a Gaussian pose ``(x, y, theta)`` of this covariance."""
    sign, logdet = np.linalg.slogdet(0.5 * (covariance + covariance.T))
    if sign <= 0:
        return float("-inf")
    return float(0.5 * (3 * math.log(2 * math.pi * math.e) + logdet))


__all__ = [
    "gmapping_cells",
    "matrix",
    "planar_pose",
    "pose_entropy",
    "rotation_matrix",
    "up_in_sensor",
]
