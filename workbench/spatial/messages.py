"""Poses to and from ``geometry_msgs`` Pose, Transform and TransformStamped (duck-typed).

The functions read and write the fields of message objects (``position`` /
``orientation`` of a Pose, ``translation`` / ``rotation`` of a Transform,
``transform`` of a TransformStamped, ``pose`` of a PoseStamped); they never
import the message or bus packages, so any object with those fields works.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from workbench.spatial.errors import SpatialError
from workbench.spatial.poses import pose_matrix, xyz_quaternion_from_matrix
from workbench.spatial.rotations import floats


def _parts(msg: Any) -> tuple[Any, Any]:
    """The (point-like, quaternion-like) fields of a Pose/Transform or their stamped forms."""
    if hasattr(msg, "transform"):
        msg = msg.transform
    elif hasattr(msg, "pose") and hasattr(msg.pose, "position"):
        msg = msg.pose
    if hasattr(msg, "position") and hasattr(msg, "orientation"):
        return msg.position, msg.orientation
    if hasattr(msg, "translation") and hasattr(msg, "rotation"):
        return msg.translation, msg.rotation
    raise SpatialError(
        f"{type(msg).__name__} is not a geometry_msgs Pose, Transform or their stamped forms"
    )


def xyz_quaternion_from_msg(msg: Any) -> tuple[np.ndarray, np.ndarray]:
    """Translation (m) and quaternion ``(x, y, z, w)`` of a Pose, Transform, or stamped one."""
    point, rotation = _parts(msg)
    return (
        np.array([point.x, point.y, point.z], dtype=float),
        np.array([rotation.x, rotation.y, rotation.z, rotation.w], dtype=float),
    )


def matrix_from_msg(msg: Any) -> np.ndarray:
    """The 4x4 pose matrix of a Pose, Transform, or stamped one."""
    xyz, quaternion = xyz_quaternion_from_msg(msg)
    return pose_matrix(xyz, quaternion=quaternion)


def set_msg_pose(msg: Any, xyz: ArrayLike, quaternion: ArrayLike) -> Any:
    """Write a translation (m) and quaternion ``(x, y, z, w)`` into a message; returns it."""
    point, rotation = _parts(msg)
    point.x, point.y, point.z = floats(xyz, 3, "xyz")
    rotation.x, rotation.y, rotation.z, rotation.w = floats(quaternion, 4, "a quaternion")
    return msg


def set_msg_from_matrix(msg: Any, matrix: Any) -> Any:
    """Write a 4x4 pose matrix into a Pose, Transform, or stamped one; returns it."""
    xyz, quaternion = xyz_quaternion_from_matrix(matrix)
    return set_msg_pose(msg, xyz, quaternion)
