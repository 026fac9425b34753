"""The global plan as a local planner sees it: 2-D poses, frames, pruning and goal checks.

Facts of ``base_local_planner/src/goal_functions.cpp`` (Noetic): the plan is transformed
into the local costmap's frame keeping the points from the first one within half the local
costmap's larger side of the robot until the plan leaves that distance
(``transformGlobalPlan``); the points the robot has passed are pruned up to the first point
within 1 m (``prunePlan``); the goal is the plan's last pose (``getGoalPose``); it is reached
when the robot is within ``xy_goal_tolerance`` of it (``goalPositionReached``), its heading
within ``yaw_goal_tolerance`` (``goalOrientationReached``) and it has stopped
(``stopped``: below 0.01 rad/s and 0.01 m/s).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: ``rot_stopped_velocity`` and ``trans_stopped_velocity`` of the planners (rad/s, m/s).
STOPPED_ROT = 1e-2
STOPPED_TRANS = 1e-2


def yaw_of(q: Any) -> float:
    """The yaw (rad) of a quaternion message or ``(x, y, z, w)``."""
    x, y, z, w = (q.x, q.y, q.z, q.w) if hasattr(q, "w") else q
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def quaternion_msg(yaw: float) -> Any:
    """``geometry_msgs/Quaternion`` of a planar heading."""
    from workbench.msgs.geometry_msgs import Quaternion

    return Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))


def planar_transform(buffer: Any, target: str, source: str) -> tuple[float, float, float]:
    """The latest ``source`` -> ``target`` transform as (x, y, yaw).

    Raises:
        tf's exceptions: The transform is not available.
    """
    if target == source:
        return (0.0, 0.0, 0.0)
    st = buffer.lookup(target, source, 0)
    return (float(st.translation[0]), float(st.translation[1]), yaw_of(st.rotation))


def apply(tf2d: tuple[float, float, float], poses: np.ndarray) -> np.ndarray:
    """Apply a planar transform to ``(n, 3)`` poses."""
    x, y, th = tf2d
    c, s = math.cos(th), math.sin(th)
    out = np.empty_like(poses)
    out[:, 0] = x + c * poses[:, 0] - s * poses[:, 1]
    out[:, 1] = y + s * poses[:, 0] + c * poses[:, 1]
    out[:, 2] = poses[:, 2] + th
    return out


def poses_array(plan: list[Any]) -> np.ndarray:
    """``(n, 3)`` (x, y, yaw) of a list of PoseStamped."""
    return np.array(
        [(p.pose.position.x, p.pose.position.y, yaw_of(p.pose.orientation)) for p in plan],
        dtype=float,
    ).reshape(-1, 3)


def local_window(plan: np.ndarray, robot_xy: tuple[float, float], threshold: float) -> np.ndarray:
    """The plan's run of points within ``threshold`` m of the robot (``transformGlobalPlan``)."""
    d2 = (plan[:, 0] - robot_xy[0]) ** 2 + (plan[:, 1] - robot_xy[1]) ** 2
    near = d2 <= threshold * threshold
    if not near.any():
        return plan[:0]
    first = int(np.argmax(near))
    gone = np.flatnonzero(~near[first:])
    return plan[first : first + int(gone[0])] if len(gone) else plan[first:]


def prune(plan: np.ndarray, robot_xy: tuple[float, float]) -> int:
    """How many leading points ``prunePlan`` drops (those before the first within 1 m)."""
    d2 = (plan[:, 0] - robot_xy[0]) ** 2 + (plan[:, 1] - robot_xy[1]) ** 2
    near = np.flatnonzero(d2 < 1.0)
    return int(near[0]) if len(near) else len(plan)


def angle_diff(a: float, b: float) -> float:
    """Shortest signed angle from ``a`` to ``b`` (rad)."""
    return math.remainder(b - a, 2 * math.pi)


def stopped(vel: np.ndarray) -> bool:
    """Whether odometry says the base has stopped."""
    return (
        abs(vel[2]) <= STOPPED_ROT and abs(vel[0]) <= STOPPED_TRANS and abs(vel[1]) <= STOPPED_TRANS
    )


def inside_polygon(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Whether each point ``(n, 2)`` lies inside ``polygon`` ``(m, 2)`` (even-odd rule)."""
    inside = np.zeros(len(points), dtype=bool)
    px, py = points[:, 0], points[:, 1]
    for (x0, y0), (x1, y1) in zip(polygon, np.roll(polygon, -1, axis=0), strict=True):
        crosses = (y0 > py) != (y1 > py)
        with np.errstate(divide="ignore", invalid="ignore"):
            at = x0 + (py - y0) * (x1 - x0) / (y1 - y0)
        inside ^= crosses & (px < at)
    return inside


def footprint_cells(
    shape: tuple[int, int],
    resolution: float,
    origin: tuple[float, float],
    pose: np.ndarray,
    footprint: np.ndarray,
) -> np.ndarray:
    """Mask ``[my, mx]`` of cells whose centres lie under the footprint at ``pose``."""
    mask = np.zeros(shape, dtype=bool)
    fp = apply(
        (float(pose[0]), float(pose[1]), float(pose[2])), np.c_[footprint, np.zeros(len(footprint))]
    )[:, :2]
    lo = np.floor((fp.min(axis=0) - origin) / resolution).astype(int)
    hi = np.floor((fp.max(axis=0) - origin) / resolution).astype(int)
    lo = np.maximum(lo, 0)
    hi = np.minimum(hi, [shape[1] - 1, shape[0] - 1])
    if (hi < lo).any():
        return mask
    xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1))
    centres = np.c_[
        (xs.ravel() + 0.5) * resolution + origin[0], (ys.ravel() + 0.5) * resolution + origin[1]
    ]
    mask[ys.ravel(), xs.ravel()] = inside_polygon(centres, fp)
    return mask
