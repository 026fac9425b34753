"""Poses as 4x4 homogeneous matrices, built from and taken apart into xyz + rpy/quaternion.

``X_AB`` (Drake's monogram notation) is the pose of frame B in frame A: its
rotation is B's axes in A and its translation is B's origin in A, metres.
The matrix maps points in B to points in A: ``p_A = X_AB @ [p_B, 1]``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from workbench.spatial.errors import SpatialError
from workbench.spatial.rotations import (
    matrix_from_quaternion,
    matrix_from_rpy,
    quaternion_from_matrix,
    rpy_from_matrix,
    vector3,
)


def pose_matrix(
    xyz: ArrayLike = (0.0, 0.0, 0.0),
    rpy: ArrayLike | None = None,
    quaternion: ArrayLike | None = None,
) -> np.ndarray:
    """The 4x4 matrix of a translation (m) and a rotation given as rpy (rad) or quaternion.

    Args:
        xyz: Translation, metres.
        rpy: Fixed-axis roll, pitch, yaw, radians (URDF ``<origin rpy>``).
        quaternion: ``(x, y, z, w)``; give rpy or quaternion, not both.

    Raises:
        SpatialError: Malformed values, or both rpy and quaternion.
    """
    if rpy is not None and quaternion is not None:
        raise SpatialError("give rpy or quaternion for a pose, not both")
    X = np.eye(4)
    if rpy is not None:
        X[:3, :3] = matrix_from_rpy(rpy)
    elif quaternion is not None:
        X[:3, :3] = matrix_from_quaternion(quaternion)
    X[:3, 3] = vector3(xyz, "xyz")
    return X


def homogeneous(matrix: Any) -> np.ndarray:
    """``matrix`` as a float 4x4 array.

    Raises:
        SpatialError: Not a 4x4 array of finite numbers.
    """
    X = np.asarray(matrix, dtype=float)
    if X.shape != (4, 4) or not np.all(np.isfinite(X)):
        raise SpatialError(f"a pose matrix must be 4x4 finite numbers, got shape {X.shape}")
    return X


def xyz_rpy_from_matrix(matrix: Any) -> tuple[np.ndarray, np.ndarray]:
    """Translation (m) and fixed-axis roll, pitch, yaw (rad) of a 4x4 pose matrix."""
    X = homogeneous(matrix)
    return X[:3, 3].copy(), rpy_from_matrix(X[:3, :3])


def xyz_quaternion_from_matrix(matrix: Any) -> tuple[np.ndarray, np.ndarray]:
    """Translation (m) and quaternion ``(x, y, z, w)`` of a 4x4 pose matrix."""
    X = homogeneous(matrix)
    return X[:3, 3].copy(), quaternion_from_matrix(X[:3, :3])


def translation_matrix(xyz: ArrayLike) -> np.ndarray:
    """A 4x4 pose that only translates by ``xyz`` (m)."""
    return pose_matrix(xyz)


def inverse_pose(matrix: Any) -> np.ndarray:
    """``X_BA`` from ``X_AB`` (uses the rotation's transpose, not a general inverse)."""
    X = homogeneous(matrix)
    out = np.eye(4)
    out[:3, :3] = X[:3, :3].T
    out[:3, 3] = -X[:3, :3].T @ X[:3, 3]
    return out
