"""Conversions between amcl's planar poses and ROS messages (tf, poses, scans)."""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.mapping.geometry import compose, inverse
from workbench.spatial import matrix_from_quaternion, quaternion_from_yaw, yaw_from_quaternion


def _xyzw(q: Any) -> tuple[float, float, float, float]:
    return float(q.x), float(q.y), float(q.z), float(q.w)


def planar(translation: Any, rotation: Any) -> np.ndarray:
    """``(x, y, yaw)`` of a 3-D position and quaternion (tf2's ``getYaw``)."""
    return np.array(
        [float(translation.x), float(translation.y), yaw_from_quaternion(_xyzw(rotation))]
    )


def transform_pose(t: Any) -> np.ndarray:
    """``(x, y, yaw)`` of a ``geometry_msgs/TransformStamped``."""
    return planar(t.transform.translation, t.transform.rotation)


def set_planar(position: Any, orientation: Any, pose: np.ndarray) -> None:
    """Write ``(x, y, yaw)`` into a position (or translation) and a quaternion."""
    position.x, position.y, position.z = float(pose[0]), float(pose[1]), 0.0
    orientation.x, orientation.y, orientation.z, orientation.w = (
        float(v) for v in quaternion_from_yaw(float(pose[2]))
    )


def pose_list(poses: np.ndarray) -> list[Any]:
    """``geometry_msgs/Pose`` messages of planar poses ``(N, 3)`` (a PoseArray's ``poses``)."""
    from workbench.msgs.geometry_msgs import Point, Pose, Quaternion

    half = np.asarray(poses[:, 2], dtype=float) / 2.0
    columns = (
        poses[:, 0].tolist(),
        poses[:, 1].tolist(),
        np.sin(half).tolist(),
        np.cos(half).tolist(),
    )
    return [
        Pose(position=Point(x=x, y=y, z=0.0), orientation=Quaternion(x=0.0, y=0.0, z=z, w=w))
        for x, y, z, w in zip(*columns, strict=True)
    ]


def yaw_in_base(mounting: Any, angle: float) -> float:
    """The yaw in the base frame of a laser beam at ``angle`` in the laser frame.

    ``mounting`` is the laser's rotation (``geometry_msgs/Quaternion``) in the base
    frame; an upside-down laser turns its angles the other way (amcl transforms the
    quaternions of ``angle_min`` and ``angle_min + angle_increment`` likewise).
    """
    rotation = matrix_from_quaternion(_xyzw(mounting))
    beam = rotation @ np.array([np.cos(angle), np.sin(angle), 0.0])
    return float(np.arctan2(beam[1], beam[0]))


def map_to_odom(pose: np.ndarray, odom_pose: np.ndarray) -> np.ndarray:
    """``map -> odom`` from the robot's pose in the map and in odom: ``pose ⊕ odom_pose⁻¹``."""
    return compose(np.asarray(pose, dtype=float), inverse(np.asarray(odom_pose, dtype=float)))


def covariance_36(cov: np.ndarray) -> np.ndarray:
    """A 6x6 row-major covariance with amcl's x/y block and yaw variance from a 3x3."""
    out = np.zeros(36)
    out[0], out[1], out[6], out[7] = cov[0, 0], cov[0, 1], cov[1, 0], cov[1, 1]
    out[35] = cov[2, 2]
    return out


def covariance_3(cov36: Any) -> np.ndarray:
    """The 3x3 x/y/yaw covariance amcl takes from a 6x6 message covariance."""
    c = np.asarray(cov36, dtype=float).reshape(-1)
    out = np.zeros((3, 3))
    out[0, 0], out[0, 1], out[1, 0], out[1, 1] = c[0], c[1], c[6], c[7]
    out[2, 2] = c[35]
    return out


__all__ = [
    "covariance_3",
    "covariance_36",
    "map_to_odom",
    "planar",
    "pose_list",
    "set_planar",
    "transform_pose",
    "yaw_in_base",
]
