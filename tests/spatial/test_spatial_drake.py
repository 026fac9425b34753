"""workbench.spatial's Drake and geometry_msgs conversions against Drake and message classes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from pydrake.common.eigen_geometry import Quaternion as DrakeQuaternion
from pydrake.math import RigidTransform, RollPitchYaw, RotationMatrix

from workbench import spatial
from workbench.msgs.geometry_msgs import Pose, PoseStamped, Transform, TransformStamped


def _rpys(count: int) -> np.ndarray:
    rng = np.random.default_rng(5)
    return np.column_stack(
        [
            rng.uniform(-math.pi, math.pi, count),
            rng.uniform(-1.5, 1.5, count),
            rng.uniform(-math.pi, math.pi, count),
        ]
    )


@pytest.mark.parametrize("rpy", _rpys(25))
def test_agrees_with_drake_roll_pitch_yaw(rpy: np.ndarray) -> None:
    R_drake = RotationMatrix(RollPitchYaw(rpy)).matrix()
    np.testing.assert_allclose(spatial.matrix_from_rpy(rpy), R_drake, atol=1e-14)
    np.testing.assert_allclose(spatial.rotation_matrix(rpy).matrix(), R_drake, atol=1e-14)
    np.testing.assert_allclose(
        spatial.rpy_from_matrix(R_drake), RollPitchYaw(RotationMatrix(R_drake)).vector(), atol=1e-10
    )
    q_drake = RotationMatrix(R_drake).ToQuaternion()
    q = spatial.quaternion_from_rpy(rpy)
    assert abs(abs(float(np.dot(q, spatial.xyzw_from_drake_quaternion(q_drake)))) - 1) < 1e-12


def test_rigid_transform_round_trips() -> None:
    for rpy in _rpys(10):
        X = spatial.rigid_transform([1.0, -0.5, 0.25], rpy=rpy)
        expected = RigidTransform(RollPitchYaw(rpy), [1.0, -0.5, 0.25])
        assert X.IsNearlyEqualTo(expected, 1e-14)
        xyz, q = spatial.xyz_quaternion_from_rigid_transform(X)
        assert spatial.rigid_transform(xyz, quaternion=q).IsNearlyEqualTo(X, 1e-14)
        xyz, rpy_back = spatial.xyz_rpy_from_rigid_transform(X)
        np.testing.assert_allclose(rpy_back, rpy, atol=1e-10)
        M = spatial.matrix_from_rigid_transform(X)
        np.testing.assert_allclose(M, X.GetAsMatrix4())
        assert spatial.as_rigid_transform(M).IsNearlyEqualTo(X, 1e-14)


def test_drake_quaternion_is_w_first() -> None:
    q = spatial.drake_quaternion([0.0, 0.0, 1.0, 1.0])  # normalised on the way
    assert isinstance(q, DrakeQuaternion)
    np.testing.assert_allclose(q.wxyz(), [math.sqrt(0.5), 0, 0, math.sqrt(0.5)])


def test_as_rigid_transform_forms() -> None:
    assert spatial.as_rigid_transform(None).IsExactlyIdentity()
    np.testing.assert_allclose(spatial.as_rigid_transform([1, 2, 3]).translation(), [1, 2, 3])
    X = spatial.as_rigid_transform({"xyz": [1, 0, 0], "rpy": [0, 0, math.pi / 2]})
    np.testing.assert_allclose(X.rotation().matrix() @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    Y = spatial.as_rigid_transform({"quaternion": [0, 0, math.sqrt(0.5), math.sqrt(0.5)]})
    np.testing.assert_allclose(Y.rotation().matrix(), X.rotation().matrix(), atol=1e-14)
    for bad in ("pose", [1, 2], {"xyz": [1, 2]}, {"position": [0, 0, 0]}, np.eye(3)):
        with pytest.raises(spatial.SpatialError):
            spatial.as_rigid_transform(bad)


@pytest.mark.parametrize("cls", [Pose, PoseStamped, Transform, TransformStamped])
def test_geometry_msgs_round_trip(cls) -> None:
    X = spatial.pose_matrix([0.5, -1.0, 2.0], rpy=[0.3, -0.2, 1.1])
    msg = spatial.set_msg_from_matrix(cls(), X)
    np.testing.assert_allclose(spatial.matrix_from_msg(msg), X, atol=1e-14)
    xyz, q = spatial.xyz_quaternion_from_msg(msg)
    np.testing.assert_allclose(xyz, [0.5, -1.0, 2.0])
    np.testing.assert_allclose(np.linalg.norm(q), 1.0)


def test_msg_fields_are_the_ros_ones() -> None:
    msg = spatial.set_msg_pose(TransformStamped(), [1, 2, 3], [0, 0, 0, 1])
    assert msg.transform.translation.z == 3.0 and msg.transform.rotation.w == 1.0
    with pytest.raises(spatial.SpatialError):
        spatial.xyz_quaternion_from_msg(object())
