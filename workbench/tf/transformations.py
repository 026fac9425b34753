"""Homogeneous matrices, Euler angles and quaternions with ROS ``tf.transformations`` conventions.

* Quaternions are ``[x, y, z, w]`` (ROS's order, not ``[w, x, y, z]``).
* Matrices are 4x4 homogeneous, acting on column vectors.
* Euler angles take an ``axes`` string of 4 characters: ``s`` (static/extrinsic) or
  ``r`` (rotating/intrinsic) followed by the axis order; the default ``'sxyz'`` is
  roll about x, then pitch about y, then yaw about z, all about the fixed axes
  (REP 103's roll/pitch/yaw). ``'rzyx'`` with (yaw, pitch, roll) is the same rotation.
  A ``(firstaxis, parity, repetition, frame)`` tuple is accepted as well.

Angles are radians. The default ``'sxyz'`` axes (URDF's roll-pitch-yaw) and the
quaternion/matrix conversions are :mod:`workbench.spatial`'s, the one place
workbench converts rotations; the other axis orders go through
:mod:`scipy.spatial.transform`. The matrix-to-Euler extraction follows
Shoemake's method so that angle ranges and gimbal-lock choices match ROS.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench import spatial
from workbench.tf.exceptions import InvalidArgumentException

#: Machine epsilon times 4: below this a value is treated as zero.
_EPS = np.finfo(float).eps * 4.0
_NEXT_AXIS = (1, 2, 0, 1)
#: axes string -> (first axis, parity, repetition, frame), the tf.transformations table.
_AXES2TUPLE = {
    "sxyz": (0, 0, 0, 0), "sxyx": (0, 0, 1, 0), "sxzy": (0, 1, 0, 0), "sxzx": (0, 1, 1, 0),
    "syzx": (1, 0, 0, 0), "syzy": (1, 0, 1, 0), "syxz": (1, 1, 0, 0), "syxy": (1, 1, 1, 0),
    "szxy": (2, 0, 0, 0), "szxz": (2, 0, 1, 0), "szyx": (2, 1, 0, 0), "szyz": (2, 1, 1, 0),
    "rzyx": (0, 0, 0, 1), "rxyx": (0, 0, 1, 1), "ryzx": (0, 1, 0, 1), "rxzx": (0, 1, 1, 1),
    "rxzy": (1, 0, 0, 1), "ryzy": (1, 0, 1, 1), "rzxy": (1, 1, 0, 1), "ryxy": (1, 1, 1, 1),
    "ryxz": (2, 0, 0, 1), "rzxz": (2, 0, 1, 1), "rxyz": (2, 1, 0, 1), "rzyz": (2, 1, 1, 1),
}  # fmt: skip
_TUPLE2AXES = {v: k for k, v in _AXES2TUPLE.items()}
_RNG = np.random.default_rng(0)

__all__ = [
    "concatenate_matrices",
    "euler_from_matrix",
    "euler_from_quaternion",
    "euler_matrix",
    "identity_matrix",
    "inverse_matrix",
    "is_same_transform",
    "quaternion_about_axis",
    "quaternion_conjugate",
    "quaternion_from_euler",
    "quaternion_from_matrix",
    "quaternion_inverse",
    "quaternion_matrix",
    "quaternion_multiply",
    "quaternion_slerp",
    "random_quaternion",
    "random_rotation_matrix",
    "rotation_from_matrix",
    "rotation_matrix",
    "translation_from_matrix",
    "translation_matrix",
    "unit_vector",
    "vector_norm",
]


def _axes(axes: str | Sequence[int]) -> tuple[str, tuple[int, int, int, int]]:
    if isinstance(axes, str):
        key = axes.lower()
        if key not in _AXES2TUPLE:
            raise InvalidArgumentException(
                f"unknown Euler axes {axes!r}: use 's' or 'r' and three axes, e.g. 'sxyz' or 'rzyx'"
            )
        return key, _AXES2TUPLE[key]
    tup = tuple(int(v) for v in axes)
    if tup not in _TUPLE2AXES:
        raise InvalidArgumentException(f"unknown Euler axes tuple {axes!r}")
    return _TUPLE2AXES[tup], tup


def _scipy_sequence(axes: str) -> str:
    # 's' = rotations about the fixed axes (scipy extrinsic, lower case);
    # 'r' = about the moving axes (scipy intrinsic, upper case) with the same angle order.
    return axes[1:] if axes[0] == "s" else axes[1:].upper()


def _is_rpy(name: str, *angles: float) -> bool:
    """Whether workbench.spatial's roll-pitch-yaw computes these Euler angles (finite 'sxyz')."""
    return name == "sxyz" and all(math.isfinite(float(a)) for a in angles)


def _matrix_nan(quaternion: np.ndarray) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    return Rotation.from_quat(quaternion).as_matrix()


# --- matrices -------------------------------------------------------------------


def identity_matrix() -> np.ndarray:
    """The 4x4 identity."""
    return np.identity(4)


def translation_matrix(direction: Sequence[float] | np.ndarray) -> np.ndarray:
    """A 4x4 matrix translating by ``direction`` (metres)."""
    m = np.identity(4)
    m[:3, 3] = np.asarray(direction, dtype=float)[:3]
    return m


def translation_from_matrix(matrix: Any) -> np.ndarray:
    """The translation (3,) of a 4x4 matrix."""
    return np.array(matrix, dtype=float, copy=True)[:3, 3].copy()


def rotation_matrix(
    angle: float, direction: Sequence[float] | np.ndarray, point: Any = None
) -> np.ndarray:
    """A 4x4 matrix rotating by ``angle`` (rad) about the axis ``direction`` through ``point``."""
    from scipy.spatial.transform import Rotation

    axis = unit_vector(np.asarray(direction, dtype=float)[:3])
    m = np.identity(4)
    m[:3, :3] = Rotation.from_rotvec(axis * float(angle)).as_matrix()
    if point is not None:
        p = np.asarray(point, dtype=float)[:3]
        m[:3, 3] = p - m[:3, :3] @ p
    return m


def rotation_from_matrix(matrix: Any) -> tuple[float, np.ndarray, np.ndarray]:
    """``(angle, direction, point)`` of a rotation matrix (inverse of :func:`rotation_matrix`)."""
    from scipy.spatial.transform import Rotation

    m = np.array(matrix, dtype=float)
    rotvec = Rotation.from_matrix(m[:3, :3]).as_rotvec()
    angle = float(np.linalg.norm(rotvec))
    direction = rotvec / angle if angle > _EPS else np.array([0.0, 0.0, 1.0])
    # a point on the axis: least-squares solution of (I - R) p = t
    point = np.zeros(4)
    point[3] = 1.0
    point[:3] = np.linalg.lstsq(np.identity(3) - m[:3, :3], m[:3, 3], rcond=None)[0]
    return angle, direction, point


def concatenate_matrices(*matrices: Any) -> np.ndarray:
    """The product of 4x4 matrices, left to right."""
    m = np.identity(4)
    for other in matrices:
        m = m @ np.asarray(other, dtype=float)
    return m


def inverse_matrix(matrix: Any) -> np.ndarray:
    """The inverse of a square matrix."""
    return np.linalg.inv(np.asarray(matrix, dtype=float))


def is_same_transform(matrix0: Any, matrix1: Any) -> bool:
    """Whether two homogeneous matrices describe the same transform (up to scaling)."""
    a = np.array(matrix0, dtype=float)
    b = np.array(matrix1, dtype=float)
    return bool(np.allclose(a / a[3, 3], b / b[3, 3]))


# --- Euler angles -------------------------------------------------------------------


def euler_matrix(ai: float, aj: float, ak: float, axes: str | Sequence[int] = "sxyz") -> np.ndarray:
    """The 4x4 rotation matrix of Euler angles (rad) about ``axes``."""
    from scipy.spatial.transform import Rotation

    name, _ = _axes(axes)
    m = np.identity(4)
    if _is_rpy(name, ai, aj, ak):
        m[:3, :3] = spatial.matrix_from_rpy((ai, aj, ak))
    else:
        m[:3, :3] = Rotation.from_euler(_scipy_sequence(name), [ai, aj, ak]).as_matrix()
    return m


def euler_from_matrix(
    matrix: Any, axes: str | Sequence[int] = "sxyz"
) -> tuple[float, float, float]:
    """Euler angles (rad) of a rotation matrix, for ``axes`` (Shoemake's extraction)."""
    name, (first, parity, repetition, frame) = _axes(axes)
    m = np.asarray(matrix, dtype=float)[:3, :3]
    if name == "sxyz":
        roll, pitch, yaw = spatial.rpy_from_matrix(m)
        return float(roll), float(pitch), float(yaw)
    i = first
    j = _NEXT_AXIS[i + parity]
    k = _NEXT_AXIS[i - parity + 1]
    if repetition:
        s = math.hypot(m[i, j], m[i, k])
        if s > _EPS:
            ax = math.atan2(m[i, j], m[i, k])
            ay = math.atan2(s, m[i, i])
            az = math.atan2(m[j, i], -m[k, i])
        else:
            ax = math.atan2(-m[j, k], m[j, j])
            ay = math.atan2(s, m[i, i])
            az = 0.0
    else:
        c = math.hypot(m[i, i], m[j, i])
        if c > _EPS:
            ax = math.atan2(m[k, j], m[k, k])
            ay = math.atan2(-m[k, i], c)
            az = math.atan2(m[j, i], m[i, i])
        else:
            ax = math.atan2(-m[j, k], m[j, j])
            ay = math.atan2(-m[k, i], c)
            az = 0.0
    if parity:
        ax, ay, az = -ax, -ay, -az
    if frame:
        ax, az = az, ax
    return ax, ay, az


def euler_from_quaternion(
    quaternion: Sequence[float] | np.ndarray, axes: str | Sequence[int] = "sxyz"
) -> tuple[float, float, float]:
    """Euler angles (rad) of a quaternion ``[x, y, z, w]``: ``(roll, pitch, yaw)`` for ``'sxyz'``."""
    return euler_from_matrix(quaternion_matrix(quaternion), axes)


def quaternion_from_euler(
    ai: float, aj: float, ak: float, axes: str | Sequence[int] = "sxyz"
) -> np.ndarray:
    """The quaternion ``[x, y, z, w]`` of Euler angles (rad): ``quaternion_from_euler(0, 0, yaw)``."""
    from scipy.spatial.transform import Rotation

    name, _ = _axes(axes)
    if _is_rpy(name, ai, aj, ak):
        return spatial.quaternion_from_rpy((ai, aj, ak))
    return Rotation.from_euler(_scipy_sequence(name), [ai, aj, ak]).as_quat()


# --- quaternions --------------------------------------------------------------------


def quaternion_about_axis(angle: float, axis: Sequence[float] | np.ndarray) -> np.ndarray:
    """The quaternion ``[x, y, z, w]`` rotating by ``angle`` (rad) about ``axis``."""
    v = np.asarray(axis, dtype=float)[:3]
    n = vector_norm(v)
    q = np.zeros(4)
    if n > _EPS:
        q[:3] = v * (math.sin(angle / 2.0) / n)
    q[3] = math.cos(angle / 2.0)
    return q


def quaternion_matrix(quaternion: Sequence[float] | np.ndarray) -> np.ndarray:
    """The 4x4 rotation matrix of a quaternion ``[x, y, z, w]`` (normalised first)."""
    q = np.asarray(quaternion, dtype=float)[:4]
    m = np.identity(4)
    if np.dot(q, q) < _EPS:
        return m
    m[:3, :3] = spatial.matrix_from_quaternion(q) if np.all(np.isfinite(q)) else _matrix_nan(q)
    return m


def quaternion_from_matrix(matrix: Any) -> np.ndarray:
    """The quaternion ``[x, y, z, w]`` of the rotation part of a 3x3 or 4x4 matrix."""
    return spatial.quaternion_from_matrix(np.asarray(matrix, dtype=float)[:3, :3])


def quaternion_multiply(
    quaternion1: Sequence[float] | np.ndarray, quaternion0: Sequence[float] | np.ndarray
) -> np.ndarray:
    """The Hamilton product ``quaternion1 * quaternion0`` (apply ``quaternion0`` first)."""
    x1, y1, z1, w1 = (float(v) for v in quaternion1[:4])
    x0, y0, z0, w0 = (float(v) for v in quaternion0[:4])
    return np.array(
        [
            w1 * x0 + x1 * w0 + y1 * z0 - z1 * y0,
            w1 * y0 - x1 * z0 + y1 * w0 + z1 * x0,
            w1 * z0 + x1 * y0 - y1 * x0 + z1 * w0,
            w1 * w0 - x1 * x0 - y1 * y0 - z1 * z0,
        ]
    )


def quaternion_conjugate(quaternion: Sequence[float] | np.ndarray) -> np.ndarray:
    """``[-x, -y, -z, w]``."""
    q = np.array(quaternion, dtype=float)[:4]
    q[:3] *= -1.0
    return q


def quaternion_inverse(quaternion: Sequence[float] | np.ndarray) -> np.ndarray:
    """The inverse ``conjugate / |q|^2``."""
    q = np.asarray(quaternion, dtype=float)[:4]
    return quaternion_conjugate(q) / np.dot(q, q)


def quaternion_slerp(
    quat0: Sequence[float] | np.ndarray,
    quat1: Sequence[float] | np.ndarray,
    fraction: float,
    spin: int = 0,
    shortestpath: bool = True,
) -> np.ndarray:
    """Spherical linear interpolation from ``quat0`` (fraction 0) to ``quat1`` (fraction 1)."""
    q0 = unit_vector(np.asarray(quat0, dtype=float)[:4])
    q1 = unit_vector(np.asarray(quat1, dtype=float)[:4])
    if fraction == 0.0:
        return q0
    if fraction == 1.0:
        return q1
    d = float(np.dot(q0, q1))
    if abs(abs(d) - 1.0) < _EPS:
        return q0
    if shortestpath and d < 0.0:
        d = -d
        q1 = -q1
    angle = math.acos(max(-1.0, min(1.0, d))) + spin * math.pi
    if abs(angle) < _EPS:
        return q0
    isin = 1.0 / math.sin(angle)
    return q0 * (math.sin((1.0 - fraction) * angle) * isin) + q1 * (
        math.sin(fraction * angle) * isin
    )


def random_quaternion(rand: Sequence[float] | np.ndarray | None = None) -> np.ndarray:
    """A uniformly random unit quaternion; ``rand`` is three numbers in [0, 1).

    Without ``rand`` the numbers come from a module generator seeded with 0, so a
    program draws the same sequence on every run.
    """
    if rand is None:
        rand = _RNG.random(3)
    r1, r2, r3 = (float(v) for v in rand[:3])
    a, b = math.sqrt(1.0 - r1), math.sqrt(r1)
    t1, t2 = 2.0 * math.pi * r2, 2.0 * math.pi * r3
    return np.array([math.sin(t1) * a, math.cos(t1) * a, math.sin(t2) * b, math.cos(t2) * b])


def random_rotation_matrix(rand: Sequence[float] | np.ndarray | None = None) -> np.ndarray:
    """A uniformly random 4x4 rotation matrix (see :func:`random_quaternion`)."""
    return quaternion_matrix(random_quaternion(rand))


# --- vectors --------------------------------------------------------------------------


def vector_norm(data: Any, axis: int | None = None) -> Any:
    """Euclidean length of a vector (or along ``axis`` of an array)."""
    a = np.asarray(data, dtype=float)
    if axis is None:
        return float(np.sqrt(np.dot(a.ravel(), a.ravel())))
    return np.sqrt(np.sum(a * a, axis=axis))


def unit_vector(data: Any, axis: int | None = None) -> np.ndarray:
    """``data`` divided by its length (along ``axis``)."""
    a = np.array(data, dtype=float)
    if axis is None:
        return a / vector_norm(a)
    return a / np.expand_dims(vector_norm(a, axis), axis)
