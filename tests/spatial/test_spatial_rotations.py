"""Rotations and poses of workbench.spatial against independent references.

References: hand-derived values, scipy's Rotation, the elementary-rotation
product Rz @ Ry @ Rx that URDF's rpy is defined by, and round trips.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench import spatial
from workbench.errors import WorkbenchError


def _rx(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def _ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def _rz(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _random_rpy(count: int, seed: int = 7) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.column_stack(
        [
            rng.uniform(-math.pi, math.pi, count),
            rng.uniform(-math.pi / 2 + 1e-3, math.pi / 2 - 1e-3, count),
            rng.uniform(-math.pi, math.pi, count),
        ]
    )


def _same_rotation(q1: np.ndarray, q2: np.ndarray) -> bool:
    return bool(abs(abs(float(np.dot(q1, q2))) - 1.0) < 1e-12)


def test_known_values() -> None:
    half = math.sqrt(0.5)
    np.testing.assert_allclose(spatial.quaternion_from_rpy([0, 0, 0]), [0, 0, 0, 1])
    np.testing.assert_allclose(
        spatial.quaternion_from_rpy([0, 0, math.pi / 2]), [0, 0, half, half], atol=1e-15
    )
    np.testing.assert_allclose(
        spatial.quaternion_from_rpy([math.pi, 0, 0]), [1, 0, 0, 0], atol=1e-15
    )
    # yaw of 90 degrees turns x into y
    R = spatial.matrix_from_rpy([0, 0, math.pi / 2])
    np.testing.assert_allclose(R @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    # pitch of 90 degrees turns z into x (right hand about y)
    R = spatial.matrix_from_rpy([0, math.pi / 2, 0])
    np.testing.assert_allclose(R @ [0, 0, 1], [1, 0, 0], atol=1e-15)


@pytest.mark.parametrize("rpy", _random_rpy(40))
def test_rpy_is_fixed_axis_xyz(rpy: np.ndarray) -> None:
    r, p, y = rpy
    expected = _rz(y) @ _ry(p) @ _rx(r)
    np.testing.assert_allclose(spatial.matrix_from_rpy(rpy), expected, atol=1e-14)
    reference = Rotation.from_euler("xyz", rpy)  # scipy lower case = extrinsic (fixed) axes
    assert _same_rotation(spatial.quaternion_from_rpy(rpy), reference.as_quat())
    np.testing.assert_allclose(spatial.rpy_from_matrix(expected), rpy, atol=1e-12)
    np.testing.assert_allclose(spatial.rpy_from_quaternion(reference.as_quat()), rpy, atol=1e-12)


def test_quaternion_matrix_round_trip_and_scipy() -> None:
    rotations = Rotation.random(50, random_state=3)
    for q in rotations.as_quat():
        R = spatial.matrix_from_quaternion(q)
        np.testing.assert_allclose(R, Rotation.from_quat(q).as_matrix(), atol=1e-14)
        assert _same_rotation(spatial.quaternion_from_matrix(R), q)
        # an unnormalised quaternion is the same rotation
        np.testing.assert_allclose(spatial.matrix_from_quaternion(3.0 * q), R, atol=1e-14)


@pytest.mark.parametrize("pitch", [math.pi / 2, -math.pi / 2])
def test_gimbal_lock(pitch: float) -> None:
    R = spatial.matrix_from_rpy([0.4, pitch, -0.3])
    roll, p, yaw = spatial.rpy_from_matrix(R)
    assert p == pytest.approx(pitch, abs=1e-7)
    assert yaw == 0.0  # tf's choice: the whole in-plane angle goes to roll
    np.testing.assert_allclose(spatial.matrix_from_rpy([roll, p, yaw]), R, atol=1e-12)


def test_w_first_helpers() -> None:
    q = np.array([0.1, 0.2, 0.3, 0.9])
    np.testing.assert_array_equal(spatial.wxyz_from_xyzw(q), [0.9, 0.1, 0.2, 0.3])
    np.testing.assert_array_equal(spatial.xyzw_from_wxyz(spatial.wxyz_from_xyzw(q)), q)


def test_yaw_helpers() -> None:
    for yaw in np.linspace(-3.1, 3.1, 13):
        q = spatial.quaternion_from_yaw(yaw)
        assert spatial.yaw_from_quaternion(q) == pytest.approx(yaw, abs=1e-12)
        np.testing.assert_allclose(q, spatial.quaternion_from_rpy([0, 0, yaw]), atol=1e-15)


def test_pose_matrix_round_trips() -> None:
    for rpy in _random_rpy(20, seed=11):
        X = spatial.pose_matrix([0.1, -2.0, 3.5], rpy=rpy)
        xyz, rpy_back = spatial.xyz_rpy_from_matrix(X)
        np.testing.assert_allclose(xyz, [0.1, -2.0, 3.5])
        np.testing.assert_allclose(rpy_back, rpy, atol=1e-12)
        xyz, q = spatial.xyz_quaternion_from_matrix(X)
        np.testing.assert_allclose(spatial.pose_matrix(xyz, quaternion=q), X, atol=1e-14)
        np.testing.assert_allclose(spatial.inverse_pose(X) @ X, np.eye(4), atol=1e-14)
        np.testing.assert_allclose(spatial.inverse_pose(X), np.linalg.inv(X), atol=1e-12)


@pytest.mark.parametrize(
    "call",
    [
        lambda: spatial.matrix_from_rpy([1, 2]),
        lambda: spatial.matrix_from_rpy([0, float("nan"), 0]),
        lambda: spatial.matrix_from_quaternion([0, 0, 0, 0]),
        lambda: spatial.pose_matrix([0, 0, 0], rpy=[0, 0, 0], quaternion=[0, 0, 0, 1]),
        lambda: spatial.xyz_rpy_from_matrix(np.eye(3)),
        lambda: spatial.rpy_from_matrix(np.eye(2)),
    ],
)
def test_bad_input_is_a_workbench_error(call) -> None:
    with pytest.raises(WorkbenchError):
        call()
