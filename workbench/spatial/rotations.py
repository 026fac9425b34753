"""Rotations as roll-pitch-yaw, quaternions and 3x3 matrices (numpy only).

Conventions, the same as URDF, tf and REP 103:

* ``rpy`` is fixed-axis roll about x, then pitch about y, then yaw about z
  (radians), so ``R = Rz(yaw) @ Ry(pitch) @ Rx(roll)``; Drake's
  ``RollPitchYaw`` and tf's ``'sxyz'`` Euler axes mean the same rotation.
* Quaternions are ``(x, y, z, w)`` as in ROS messages and tf. Drake and Eigen
  order them ``(w, x, y, z)``: convert with :func:`wxyz_from_xyzw` and
  :func:`xyzw_from_wxyz`.
* Matrices act on column vectors: ``p_A = R_AB @ p_B``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from workbench.spatial.errors import SpatialError

#: Below this a norm or cosine is treated as zero (tf.transformations' value).
EPS = float(np.finfo(float).eps * 4.0)


def floats(values: ArrayLike, n: int, what: str) -> list[float]:
    """``values`` as a list of ``n`` floats (not checked for finiteness).

    Raises:
        SpatialError: Not ``n`` numbers.
    """
    try:
        out = np.asarray(values, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise SpatialError(f"{what} must be {n} numbers, got {values!r}") from None
    if out.size != n:
        raise SpatialError(f"{what} must be {n} numbers, got {values!r}")
    return [float(v) for v in out]


def vector3(values: Any, what: str = "a 3-vector") -> np.ndarray:
    """``values`` as a float array of shape (3,).

    Raises:
        SpatialError: Not three finite numbers.
    """
    try:
        out = np.asarray(values, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise SpatialError(f"{what} must be 3 numbers, got {values!r}") from None
    if out.shape != (3,) or not np.all(np.isfinite(out)):
        raise SpatialError(f"{what} must be 3 finite numbers, got {values!r}")
    return out


def quaternion4(values: Any, what: str = "a quaternion (x, y, z, w)") -> np.ndarray:
    """``values`` as a unit quaternion array of shape (4,), normalised.

    Raises:
        SpatialError: Not four finite numbers, or (close to) zero length.
    """
    try:
        q = np.asarray(values, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise SpatialError(f"{what} must be 4 numbers, got {values!r}") from None
    if q.shape != (4,) or not np.all(np.isfinite(q)):
        raise SpatialError(f"{what} must be 4 finite numbers, got {values!r}")
    norm = float(np.linalg.norm(q))
    if norm < EPS:
        raise SpatialError(f"{what} has zero length", hint="the identity is (0, 0, 0, 1)")
    return q / norm


def wxyz_from_xyzw(quaternion: ArrayLike) -> np.ndarray:
    """Reorder a ROS ``(x, y, z, w)`` quaternion as Drake/Eigen's ``(w, x, y, z)``."""
    x, y, z, w = floats(quaternion, 4, "a quaternion (x, y, z, w)")
    return np.array([w, x, y, z])


def xyzw_from_wxyz(quaternion: ArrayLike) -> np.ndarray:
    """Reorder a Drake/Eigen ``(w, x, y, z)`` quaternion as ROS's ``(x, y, z, w)``."""
    w, x, y, z = floats(quaternion, 4, "a quaternion (w, x, y, z)")
    return np.array([x, y, z, w])


def matrix_from_rpy(rpy: ArrayLike) -> np.ndarray:
    """The 3x3 rotation matrix of fixed-axis roll, pitch, yaw (radians)."""
    r, p, y = vector3(rpy, "rpy")
    cr, sr = math.cos(r), math.sin(r)
    cp, sp = math.cos(p), math.sin(p)
    cy, sy = math.cos(y), math.sin(y)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def rpy_from_matrix(matrix: Any) -> np.ndarray:
    """Fixed-axis roll, pitch, yaw (radians) of a 3x3 (or 4x4) rotation matrix.

    Roll and yaw are in [-pi, pi], pitch in [-pi/2, pi/2]. At gimbal lock
    (pitch = +-pi/2) only roll - yaw (or roll + yaw) is defined; yaw is then 0,
    as tf's ``euler_from_matrix`` chooses.
    """
    m = np.asarray(matrix, dtype=float)
    if m.shape not in ((3, 3), (4, 4)):
        raise SpatialError(f"a rotation matrix must be 3x3 or 4x4, got shape {m.shape}")
    c = math.hypot(m[0, 0], m[1, 0])
    pitch = math.atan2(-m[2, 0], c)
    if c > EPS:
        roll = math.atan2(m[2, 1], m[2, 2])
        yaw = math.atan2(m[1, 0], m[0, 0])
    else:
        roll = math.atan2(-m[1, 2], m[1, 1])
        yaw = 0.0
    return np.array([roll, pitch, yaw])


def quaternion_from_rpy(rpy: ArrayLike) -> np.ndarray:
    """The quaternion ``(x, y, z, w)`` of fixed-axis roll, pitch, yaw (radians)."""
    r, p, y = vector3(rpy, "rpy") / 2.0
    cr, sr = math.cos(r), math.sin(r)
    cp, sp = math.cos(p), math.sin(p)
    cy, sy = math.cos(y), math.sin(y)
    return np.array(
        [
            sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy,
        ]
    )


def rpy_from_quaternion(quaternion: ArrayLike) -> np.ndarray:
    """Fixed-axis roll, pitch, yaw (radians) of a quaternion ``(x, y, z, w)``."""
    return rpy_from_matrix(matrix_from_quaternion(quaternion))


def matrix_from_quaternion(quaternion: ArrayLike) -> np.ndarray:
    """The 3x3 rotation matrix of a quaternion ``(x, y, z, w)`` (normalised first).

    Raises:
        SpatialError: Not four finite numbers, or zero length.
    """
    x, y, z, w = quaternion4(quaternion)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def quaternion_from_matrix(matrix: Any) -> np.ndarray:
    """The quaternion ``(x, y, z, w)`` of a 3x3 (or 4x4) rotation matrix.

    A matrix that is not quite orthonormal gets the quaternion of the nearest
    rotation (scipy's method).
    """
    from scipy.spatial.transform import Rotation

    m = np.asarray(matrix, dtype=float)
    if m.shape not in ((3, 3), (4, 4)):
        raise SpatialError(f"a rotation matrix must be 3x3 or 4x4, got shape {m.shape}")
    return Rotation.from_matrix(m[:3, :3]).as_quat()


def yaw_from_quaternion(quaternion: ArrayLike) -> float:
    """The yaw (radians, about z) of a quaternion ``(x, y, z, w)``: a planar robot's heading."""
    x, y, z, w = floats(quaternion, 4, "a quaternion (x, y, z, w)")
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def quaternion_from_yaw(yaw: float) -> np.ndarray:
    """The quaternion ``(x, y, z, w)`` of a rotation by ``yaw`` (radians) about z."""
    return np.array([0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0)])
