"""Conversions to and from pydrake's ``RigidTransform``, ``RotationMatrix`` and ``RollPitchYaw``.

pydrake is imported inside each function, so importing this module stays cheap.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from workbench.spatial.errors import SpatialError
from workbench.spatial.poses import homogeneous, pose_matrix
from workbench.spatial.rotations import quaternion4, vector3, wxyz_from_xyzw, xyzw_from_wxyz


def rigid_transform(
    xyz: ArrayLike = (0.0, 0.0, 0.0),
    rpy: ArrayLike | None = None,
    quaternion: ArrayLike | None = None,
) -> Any:
    """A ``RigidTransform`` from a translation (m) and rpy (rad) or a quaternion ``(x, y, z, w)``."""
    from pydrake.math import RigidTransform

    return RigidTransform(pose_matrix(xyz, rpy, quaternion))  # type: ignore[arg-type]


def rotation_matrix(rpy: ArrayLike | None = None, quaternion: Any = None) -> Any:
    """A Drake ``RotationMatrix`` from rpy (rad) or a quaternion ``(x, y, z, w)``."""
    from pydrake.math import RotationMatrix

    return RotationMatrix(pose_matrix((0.0, 0.0, 0.0), rpy, quaternion)[:3, :3])


def drake_quaternion(quaternion: ArrayLike) -> Any:
    """A pydrake (Eigen) ``Quaternion`` from ROS's ``(x, y, z, w)`` order, normalised."""
    from pydrake.common.eigen_geometry import Quaternion

    return Quaternion(wxyz_from_xyzw(quaternion4(quaternion)))  # type: ignore[arg-type]


def xyzw_from_drake_quaternion(quaternion: Any) -> np.ndarray:
    """ROS's ``(x, y, z, w)`` of a pydrake ``Quaternion``."""
    return xyzw_from_wxyz(quaternion.wxyz())


def matrix_from_rigid_transform(X: Any) -> np.ndarray:
    """The 4x4 homogeneous matrix of a ``RigidTransform``."""
    return np.asarray(X.GetAsMatrix4(), dtype=float)


def xyz_quaternion_from_rigid_transform(X: Any) -> tuple[np.ndarray, np.ndarray]:
    """Translation (m) and quaternion ``(x, y, z, w)`` of a ``RigidTransform``."""
    return np.array(X.translation(), dtype=float), xyzw_from_drake_quaternion(
        X.rotation().ToQuaternion()
    )


def xyz_rpy_from_rigid_transform(X: Any) -> tuple[np.ndarray, np.ndarray]:
    """Translation (m) and fixed-axis roll, pitch, yaw (rad) of a ``RigidTransform``.

    The angles are Drake's ``RollPitchYaw``, which agrees with
    :func:`workbench.spatial.rpy_from_matrix` except exactly at gimbal lock, where
    either is a valid choice.
    """
    from pydrake.math import RollPitchYaw

    return np.array(X.translation(), dtype=float), np.array(RollPitchYaw(X.rotation()).vector())


def as_rigid_transform(value: Any) -> Any:
    """A ``RigidTransform`` from the ways workbench accepts a pose.

    Accepted: None (identity), a ``RigidTransform``, ``[x, y, z]`` (m), a 4x4 matrix,
    or a mapping ``{"xyz": [...], "rpy": [...]}`` / ``{"xyz": [...], "quaternion": [x, y, z, w]}``.

    Raises:
        SpatialError: Anything else, naming what was given.
    """
    from pydrake.math import RigidTransform

    if value is None:
        return RigidTransform()
    if isinstance(value, RigidTransform):
        return value
    if isinstance(value, Mapping):
        unknown = set(value) - {"xyz", "rpy", "quaternion"}
        if unknown:
            raise SpatialError(
                f"unknown pose field(s) {sorted(unknown)}", hint="use xyz with rpy or quaternion"
            )
        try:
            return rigid_transform(
                value.get("xyz", (0.0, 0.0, 0.0)), value.get("rpy"), value.get("quaternion")
            )
        except SpatialError as error:
            raise SpatialError(
                f"pose needs xyz and rpy of 3 numbers each ({error.message}), got {dict(value)!r}"
            ) from None
    array = np.asarray(value, dtype=float) if _numeric(value) else None
    if array is not None and array.shape == (4, 4):
        return RigidTransform(homogeneous(array))  # type: ignore[arg-type]
    if array is not None and array.size == 3:
        return RigidTransform(vector3(array, "xyz"))  # type: ignore[arg-type]
    raise SpatialError(
        f"a pose is a RigidTransform, [x, y, z], a 4x4 matrix or {{xyz, rpy}}; got {value!r}"
    )


def _numeric(value: Any) -> bool:
    try:
        np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return False
    return True
