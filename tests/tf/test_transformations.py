"""``workbench.tf.transformations`` follows ROS ``tf.transformations`` (quaternions x, y, z, w)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.tf import InvalidArgumentException
from workbench.tf import transformations as tft

ALL_AXES = sorted(tft._AXES2TUPLE)


def test_quaternion_from_euler_yaw_is_the_turtle_heading():
    """The lab's broadcaster: quaternion_from_euler(0, 0, theta) = (0, 0, sin(theta/2), cos(theta/2))."""
    for theta in (0.0, 1.056, -2.5, 4.0):
        q = tft.quaternion_from_euler(0, 0, theta)
        np.testing.assert_allclose(q, [0, 0, math.sin(theta / 2), math.cos(theta / 2)], atol=1e-12)


def test_tf_echo_example_from_the_manual():
    """tf_echo showed Quaternion [0, 0, 0.504, 0.864] = RPY [0, 0, 1.056] rad = 60.5 degrees."""
    roll, pitch, yaw = tft.euler_from_quaternion([0.0, 0.0, 0.504, 0.864])
    assert roll == pytest.approx(0) and pitch == pytest.approx(0)
    assert yaw == pytest.approx(1.056, abs=2e-3)
    assert math.degrees(yaw) == pytest.approx(60.504, abs=0.1)


def test_sxyz_is_roll_pitch_yaw_about_fixed_axes():
    q = tft.quaternion_from_euler(0.1, 0.2, 0.3)
    r = (
        Rotation.from_euler("z", 0.3)
        * Rotation.from_euler("y", 0.2)
        * Rotation.from_euler("x", 0.1)
    )
    np.testing.assert_allclose(tft.quaternion_matrix(q)[:3, :3], r.as_matrix(), atol=1e-12)
    # the same rotation as rotating-axes zyx with (yaw, pitch, roll)
    np.testing.assert_allclose(q, tft.quaternion_from_euler(0.3, 0.2, 0.1, "rzyx"), atol=1e-12)


@pytest.mark.parametrize("axes", ALL_AXES)
def test_euler_round_trip_for_every_axes_convention(axes):
    """transformations.py's own check: euler_matrix(euler_from_matrix(R)) reproduces R."""
    rng = np.random.default_rng(3)
    for angles in rng.uniform(-math.pi, math.pi, size=(10, 3)):
        m0 = tft.euler_matrix(*angles, axes=axes)
        back = tft.euler_from_matrix(m0, axes)
        np.testing.assert_allclose(tft.euler_matrix(*back, axes=axes), m0, atol=1e-9)
        q = tft.quaternion_from_euler(*angles, axes=axes)
        np.testing.assert_allclose(tft.quaternion_matrix(q), m0, atol=1e-9)
    # tuple form of the same axes
    tup = tft._AXES2TUPLE[axes]
    np.testing.assert_allclose(
        tft.euler_matrix(0.1, 0.2, 0.3, tup), tft.euler_matrix(0.1, 0.2, 0.3, axes)
    )


def test_euler_from_matrix_ranges_match_tait_bryan():
    """Non-repeating axes give pitch in [-pi/2, pi/2], like scipy's extraction for 'xyz'."""
    rng = np.random.default_rng(4)
    for r in Rotation.random(20, random_state=rng):
        m = np.identity(4)
        m[:3, :3] = r.as_matrix()
        np.testing.assert_allclose(tft.euler_from_matrix(m), r.as_euler("xyz"), atol=1e-9)


def test_gimbal_lock_gives_a_valid_decomposition():
    m = tft.euler_matrix(0.3, math.pi / 2, 0.2)
    ax, ay, az = tft.euler_from_matrix(m)
    assert az == 0.0
    np.testing.assert_allclose(tft.euler_matrix(ax, ay, az), m, atol=1e-9)


def test_quaternion_algebra():
    q0 = tft.quaternion_about_axis(0.5, [0, 0, 1])
    q1 = tft.quaternion_about_axis(0.25, [0, 0, 2])
    np.testing.assert_allclose(
        tft.quaternion_multiply(q1, q0), tft.quaternion_about_axis(0.75, [0, 0, 1])
    )
    qi = tft.quaternion_inverse([0.0, 0.0, 0.0, 2.0])
    np.testing.assert_allclose(qi, [0, 0, 0, 0.5])
    np.testing.assert_allclose(tft.quaternion_conjugate([1, 2, 3, 4]), [-1, -2, -3, 4])
    q = tft.random_quaternion([0.1, 0.2, 0.3])
    np.testing.assert_allclose(
        tft.quaternion_multiply(q, tft.quaternion_inverse(q)), [0, 0, 0, 1], atol=1e-12
    )
    # Hamilton order: multiply(q1, q0) applies q0 first
    a = Rotation.from_quat(tft.quaternion_from_euler(0.3, 0, 0))
    b = Rotation.from_quat(tft.quaternion_from_euler(0, 0, 1.0))
    np.testing.assert_allclose(
        tft.quaternion_matrix(tft.quaternion_multiply(b.as_quat(), a.as_quat()))[:3, :3],
        (b * a).as_matrix(),
        atol=1e-12,
    )


def test_quaternion_matrix_round_trip_and_sign():
    m = tft.rotation_matrix(0.123, [1, 0, 0])
    q = tft.quaternion_from_matrix(m)
    np.testing.assert_allclose(q, [math.sin(0.123 / 2), 0, 0, math.cos(0.123 / 2)], atol=1e-12)
    np.testing.assert_allclose(tft.quaternion_matrix(q), m, atol=1e-12)


def test_slerp_end_points_and_middle():
    q0 = tft.quaternion_about_axis(0.0, [0, 0, 1])
    q1 = tft.quaternion_about_axis(1.0, [0, 0, 1])
    np.testing.assert_allclose(tft.quaternion_slerp(q0, q1, 0.0), q0)
    np.testing.assert_allclose(tft.quaternion_slerp(q0, q1, 1.0), q1)
    np.testing.assert_allclose(
        tft.quaternion_slerp(q0, q1, 0.5), tft.quaternion_about_axis(0.5, [0, 0, 1])
    )


def test_translation_rotation_and_concatenation():
    t = tft.translation_matrix([1, 2, 3])
    np.testing.assert_allclose(tft.translation_from_matrix(t), [1, 2, 3])
    r = tft.rotation_matrix(math.pi / 2, [0, 0, 1], point=[1, 0, 0])
    np.testing.assert_allclose(r @ [1, 0, 0, 1], [1, 0, 0, 1], atol=1e-12)  # the point is fixed
    np.testing.assert_allclose(r @ [2, 0, 0, 1], [1, 1, 0, 1], atol=1e-12)
    angle, direction, point = tft.rotation_from_matrix(r)
    assert angle == pytest.approx(math.pi / 2)
    np.testing.assert_allclose(direction, [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(r @ point, point, atol=1e-9)
    m = tft.concatenate_matrices(t, r)
    np.testing.assert_allclose(m, t @ r)
    assert tft.is_same_transform(tft.inverse_matrix(m) @ m, tft.identity_matrix())
    assert tft.vector_norm([3, 4, 0]) == pytest.approx(5)
    np.testing.assert_allclose(tft.unit_vector([0, 0, 2]), [0, 0, 1])


def test_random_quaternion_is_unit_and_seeded():
    q = tft.random_quaternion()
    assert tft.vector_norm(q) == pytest.approx(1.0)
    m = tft.random_rotation_matrix([0.5, 0.5, 0.5])
    np.testing.assert_allclose(m[:3, :3] @ m[:3, :3].T, np.identity(3), atol=1e-12)


def test_unknown_axes_are_refused():
    with pytest.raises(InvalidArgumentException, match="unknown Euler axes 'xyz'"):
        tft.euler_matrix(0, 0, 0, "xyz")


def test_sxyz_agrees_with_the_generic_shoemake_path():
    """'sxyz' goes through workbench.spatial; 'rzyx' (the same rotation) through the table."""
    rng = np.random.default_rng(2)
    for roll, pitch, yaw in rng.uniform(-1.5, 1.5, (20, 3)):
        q = tft.quaternion_from_euler(roll, pitch, yaw)
        np.testing.assert_allclose(q, tft.quaternion_from_euler(yaw, pitch, roll, "rzyx"))
        m = tft.euler_matrix(roll, pitch, yaw)
        np.testing.assert_allclose(m, tft.euler_matrix(yaw, pitch, roll, "rzyx"), atol=1e-15)
        np.testing.assert_allclose(
            tft.euler_from_matrix(m), tft.euler_from_matrix(m, "rzyx")[::-1], atol=1e-12
        )
    # NaN angles keep giving NaN, as tf does, rather than an error
    assert np.isnan(tft.quaternion_from_euler(math.nan, 0.0, 0.0)).all()
