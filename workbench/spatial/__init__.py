"""Poses and shapes: one vocabulary for model, viz, sim, planning, tf and mapping.

A bottom-layer package: numpy (and scipy for a few conversions) only; pydrake
is imported inside the functions that build or read Drake types, and message
conversions work on any object with ``geometry_msgs`` fields.

Conventions (URDF, tf, REP 103): ``rpy`` is fixed-axis roll about x, pitch
about y, yaw about z in radians (``R = Rz @ Ry @ Rx``); quaternions are
``(x, y, z, w)``; poses are 4x4 homogeneous matrices ``X_AB`` (frame B in A)
or Drake ``RigidTransform``; lengths are metres.

Example::

    from workbench import spatial

    q = spatial.quaternion_from_rpy([0, 0, 1.57])
    X = spatial.pose_matrix([1, 0, 0], rpy=[0, 0, 1.57])
    xyz, rpy = spatial.xyz_rpy_from_matrix(X)
"""

from __future__ import annotations

from workbench.spatial.drake import (
    as_rigid_transform,
    drake_quaternion,
    matrix_from_rigid_transform,
    rigid_transform,
    rotation_matrix,
    xyz_quaternion_from_rigid_transform,
    xyz_rpy_from_rigid_transform,
    xyzw_from_drake_quaternion,
)
from workbench.spatial.errors import SpatialError
from workbench.spatial.messages import (
    matrix_from_msg,
    set_msg_from_matrix,
    set_msg_pose,
    xyz_quaternion_from_msg,
)
from workbench.spatial.poses import (
    homogeneous,
    inverse_pose,
    pose_matrix,
    translation_matrix,
    xyz_quaternion_from_matrix,
    xyz_rpy_from_matrix,
)
from workbench.spatial.rotations import (
    matrix_from_quaternion,
    matrix_from_rpy,
    quaternion_from_matrix,
    quaternion_from_rpy,
    quaternion_from_yaw,
    rpy_from_matrix,
    rpy_from_quaternion,
    wxyz_from_xyzw,
    xyzw_from_wxyz,
    yaw_from_quaternion,
)
from workbench.spatial.shapes import (
    Box,
    Cylinder,
    Mesh,
    Shape,
    Sphere,
    drake_shape,
    make_shape,
    shape_from_drake,
)

__all__ = [
    "Box",
    "Cylinder",
    "Mesh",
    "Shape",
    "SpatialError",
    "Sphere",
    "as_rigid_transform",
    "drake_quaternion",
    "drake_shape",
    "homogeneous",
    "inverse_pose",
    "make_shape",
    "matrix_from_msg",
    "matrix_from_quaternion",
    "matrix_from_rigid_transform",
    "matrix_from_rpy",
    "pose_matrix",
    "quaternion_from_matrix",
    "quaternion_from_rpy",
    "quaternion_from_yaw",
    "rigid_transform",
    "rotation_matrix",
    "rpy_from_matrix",
    "rpy_from_quaternion",
    "set_msg_from_matrix",
    "set_msg_pose",
    "shape_from_drake",
    "translation_matrix",
    "wxyz_from_xyzw",
    "xyz_quaternion_from_matrix",
    "xyz_quaternion_from_msg",
    "xyz_quaternion_from_rigid_transform",
    "xyz_rpy_from_matrix",
    "xyz_rpy_from_rigid_transform",
    "xyzw_from_drake_quaternion",
    "xyzw_from_wxyz",
    "yaw_from_quaternion",
]
