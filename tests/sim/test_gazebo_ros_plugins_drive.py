"""``libgazebo_ros_diff_drive.so`` on the lab robot (urdf/custom_bot.urdf): driving, odometry, limits.

What is matched is gazebo_plugins' ``gazebo_ros_diff_drive.cpp`` (gazebo_ros_pkgs,
noetic-devel): parameter names and defaults (``Load``), rim speeds ``v -+ w b / 2``
(``getWheelVelocities``), the encoder integration (``UpdateOdometryEncoder``,
Siegwart 2011 p. 337), the odometry message (``publishOdometry``: frames through
``tf_prefix``, pose covariance 1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3), the wheel
joint states (right wheel first, positions only), the acceleration ramp
(``UpdateChild``) and ``fmax`` = ``wheelTorque`` on both wheel joints.
"""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from drive_helpers import RADIUS, SEPARATION, Rig, custom_bot, yaw_of
from sim_helpers import box_model

TRAILING = {"front_caster_of_wheel_joint": math.pi}  # the caster starts behind its pivot
AXLE_BEHIND = 0.2825  # m, the wheel joints' x in base_link


class WheelKinematics:
    """The plugin's odometry recomputed from the wheel joint *angles* after every advance,
    starting where the plugin's odometry is now; :meth:`at` is the pose at a time."""

    def __init__(self, rig: Rig) -> None:
        drive = rig.plugin("GazeboRosDiffDrive")
        self.model = drive.model
        self.x, self.y, self.theta = drive.odometer.x, drive.odometer.y, drive.odometer.theta
        self.last = self._angles()
        self.history: dict[float, tuple[float, float, float]] = {}
        rig.server.hooks.append(lambda server: self.step(server.world.time))

    def at(self, stamp: float) -> tuple[float, float, float]:
        return self.history[round(stamp, 6)]

    def _angles(self) -> tuple[float, float]:
        return (
            self.model.joint_position("left_wheel_joint"),
            self.model.joint_position("right_wheel_joint"),
        )

    def step(self, now: float) -> None:
        angles = self._angles()
        sl, sr = ((a - b) * RADIUS for a, b in zip(angles, self.last, strict=True))
        self.last = angles
        dtheta = (sr - sl) / SEPARATION
        self.x += (sl + sr) / 2 * math.cos(self.theta + dtheta / 2)
        self.y += (sl + sr) / 2 * math.sin(self.theta + dtheta / 2)
        self.theta += dtheta
        self.history[round(now, 6)] = (self.x, self.y, self.theta)


def axle_in_start_frame(pose, start):
    """custom_bot's wheel-axle midpoint (0.2825 m behind base_link) relative to where it
    started, in the frame the robot started in."""
    (x, y, yaw), (x0, y0, yaw0) = pose, start
    ax, ay = x - AXLE_BEHIND * math.cos(yaw), y - AXLE_BEHIND * math.sin(yaw)
    ax0, ay0 = x0 - AXLE_BEHIND * math.cos(yaw0), y0 - AXLE_BEHIND * math.sin(yaw0)
    c, s = math.cos(yaw0), math.sin(yaw0)
    return (c * (ax - ax0) + s * (ay - ay0), -s * (ax - ax0) + c * (ay - ay0))


@pytest.fixture
def encoder_rig():
    rig = Rig(custom_bot(odometrySource="encoder"), joint_positions=TRAILING)
    yield rig
    rig.close()


def test_cmd_vel_drives_the_robot_and_encoder_odometry_follows_the_wheels(encoder_rig):
    rig = encoder_rig
    odom = rig.record("/odom", "nav_msgs/Odometry")
    rig.run(0.3)  # settle on the wheels
    x0, y0, yaw0 = rig.pose()
    kinematics = WheelKinematics(rig)
    rig.command(0.5)
    rig.run(2.0)
    x, y, yaw = rig.pose()
    travelled = math.hypot(x - x0, y - y0)
    assert travelled == pytest.approx(0.5 * 2.0, rel=0.05)  # reaches 0.5 m/s within ~20 ms
    assert abs(yaw - yaw0) < 0.03  # the wheels slip a little while it speeds up
    pose = odom[-1][1].pose.pose
    expected = kinematics.at(odom[-1][1].header.stamp.to_sec())
    # odometry is the plugin's kinematics of the wheel angles ...
    assert (pose.position.x, pose.position.y) == pytest.approx(expected[:2], abs=1e-6)
    # ... and within a few percent of the truth
    assert pose.position.x == pytest.approx(travelled, rel=0.03)
    assert yaw_of(pose.orientation) == pytest.approx(yaw - yaw0, abs=0.01)

    # An arc of radius 1 m, left. The caster swings round first (~0.2 s); meanwhile it
    # skids and the drive wheels slip a little (the caster carries 45 % of the weight).
    rig.command(0.5, 0.5)
    rig.run(0.5)
    yaw_turning = rig.pose()[2]
    rig.run(2.5)
    x, y, yaw = rig.pose()
    assert yaw - yaw_turning == pytest.approx(0.5 * 2.5, rel=0.01)  # then turns as commanded
    pose = odom[-1][1].pose.pose
    expected = kinematics.at(odom[-1][1].header.stamp.to_sec())
    assert (pose.position.x, pose.position.y) == pytest.approx(expected[:2], abs=1e-6)
    assert yaw_of(pose.orientation) == pytest.approx(expected[2], abs=1e-6)
    turned = yaw - yaw0
    assert yaw_of(pose.orientation) == pytest.approx(turned, rel=0.03)
    # Wheel odometry follows the point between the wheels, 0.2825 m behind base_link here.
    truth = axle_in_start_frame(rig.pose(), (x0, y0, yaw0))
    error = math.hypot(pose.position.x - truth[0], pose.position.y - truth[1])
    assert error < 0.03 * (travelled + 0.5 * 3.0)


def test_odometry_and_tf_are_stamped_in_sim_time_at_the_update_rate(encoder_rig):
    rig = encoder_rig
    odom = rig.record("/odom", "nav_msgs/Odometry")
    tf = rig.record("/tf", "tf2_msgs/TFMessage")
    wheels = rig.record("/joint_states", "sensor_msgs/JointState")
    rig.command(0.3, 0.5)
    rig.run(0.5)
    stamps = np.array([m.header.stamp.to_sec() for _, m in odom])
    assert len(stamps) == pytest.approx(50, abs=1)  # <updateRate> default 100 Hz
    assert np.allclose(np.diff(stamps), 0.01, atol=1e-6)
    assert all(m.header.stamp.to_sec() == pytest.approx(t, abs=1e-9) for t, m in odom)
    message = odom[-1][1]
    assert (message.header.frame_id, message.child_frame_id) == ("odom", "base_link")
    covariance = np.asarray(message.pose.covariance).reshape(6, 6)
    assert np.array_equal(covariance, np.diag([1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3]))
    assert not np.any(message.twist.covariance)
    assert message.twist.twist.linear.x == pytest.approx(0.3, abs=0.01)
    assert message.twist.twist.angular.z == pytest.approx(0.5, abs=0.02)
    odom_tf = [
        (t, x)
        for t, m in tf
        for x in m.transforms
        if (x.header.frame_id, x.child_frame_id) == ("odom", "base_link")
    ]
    assert [x.header.stamp for _, x in odom_tf] == [m.header.stamp for _, m in odom]
    last = odom_tf[-1][1].transform
    assert last.translation.x == message.pose.pose.position.x
    assert last.rotation.z == message.pose.pose.orientation.z
    # <publishWheelJointState>true</publishWheelJointState>: the wheels, right first
    drive_states = [m for _, m in wheels if "left_wheel_joint" in m.name]
    assert drive_states[-1].name == ["right_wheel_joint", "left_wheel_joint"]
    assert len(drive_states[-1].position) == 2 and len(drive_states[-1].velocity) == 0
    assert drive_states[-1].header.stamp == message.header.stamp


def test_world_odometry_is_the_true_pose_and_wheel_tf_is_published():
    rig = Rig(custom_bot(publishWheelTF="true"), joint_positions=TRAILING)
    try:
        odom = rig.record("/odom", "nav_msgs/Odometry")
        tf = rig.record("/tf", "tf2_msgs/TFMessage")
        rig.command(0.4, -0.5)
        rig.run(0.6)
        x, y, yaw = rig.pose()
        pose = odom[-1][1].pose.pose  # <odometrySource> defaults to world
        assert (pose.position.x, pose.position.y) == pytest.approx((x, y), abs=0.005)
        assert yaw_of(pose.orientation) == pytest.approx(yaw, abs=0.005)
        wheel_tf = {
            x.child_frame_id: x
            for _, m in tf
            for x in m.transforms
            if x.header.frame_id == "base_link"
        }
        assert set(wheel_tf) == {"left_wheel", "right_wheel"}
        left = wheel_tf["left_wheel"].transform.translation
        assert (left.x, left.y, left.z) == pytest.approx((-0.2825, 0.125, -0.05), abs=1e-3)
    finally:
        rig.close()


def test_wheel_torque_limits_the_acceleration():
    """``fmax`` = ``wheelTorque``: 2 x 0.01 N m at r = 0.035 m push 1.4 kg at most 0.41 m/s^2."""
    rig = Rig(custom_bot(wheelTorque="0.01"), joint_positions=TRAILING)
    try:
        rig.run(0.3)
        drive = rig.plugin("GazeboRosDiffDrive")
        efforts: list[float] = []
        rig.server.hooks.append(lambda _s: efforts.extend(drive.model.motor_efforts().values()))
        x0 = rig.pose()[0]
        rig.command(1.0)
        rig.run(1.0)
        assert max(abs(e) for e in efforts) <= 0.01 + 1e-12
        assert max(abs(e) for e in efforts) == pytest.approx(0.01)
        travelled = rig.pose()[0] - x0
        assert 0.05 < travelled <= 0.5 * 0.41 * 1.0**2 * 1.05  # s = a t^2 / 2 at most
    finally:
        rig.close()


def test_wheel_acceleration_ramps_the_rim_speed():
    rig = Rig(custom_bot(wheelAcceleration="0.5"), joint_positions=TRAILING)
    try:
        rig.run(0.3)
        drive = rig.plugin("GazeboRosDiffDrive")
        rig.command(1.0)
        rig.run(1.0)
        rim = drive.model.joint_velocity("left_wheel_joint") * RADIUS
        assert 0.35 < rim < 0.6  # ~0.5 m/s after 1 s at 0.5 m/s^2, not 1 m/s
        rig.run(1.5)
        assert drive.model.joint_velocity("left_wheel_joint") * RADIUS == pytest.approx(
            1.0, abs=0.02
        )
    finally:
        rig.close()


def test_a_drive_naming_missing_joints_is_one_line_and_the_model_still_spawns(caplog):
    model = custom_bot(leftJoint="left_wheel_hinge")
    with caplog.at_level(logging.WARNING):
        rig = Rig(model)
    try:
        lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
        assert len(lines) == 1, lines
        assert "model 'custom_bot'" in lines[0] and "'left_wheel_hinge'" in lines[0]
        assert "custom_bot" in rig.world.model_names()
        assert [type(p).__name__ for p in rig.server.plugins] == ["GazeboRosJointStatePublisher"]
        rig.command(0.5)
        rig.run(0.3)
        assert np.all(np.isfinite(rig.pose()))
    finally:
        rig.close()


def test_legacy_mode_is_ignored_as_in_noetic_with_a_warning(caplog):
    with caplog.at_level(logging.WARNING):
        rig = Rig(custom_bot(legacyMode="true"), joint_positions=TRAILING)
    try:
        assert any("legacyMode" in r.getMessage() for r in caplog.records)
        yaw0 = rig.pose()[2]
        rig.command(0.0, 1.0)
        rig.run(0.5)
        assert rig.pose()[2] - yaw0 > 0.2  # a positive angular.z still turns left
    finally:
        rig.close()


def test_the_wheel_motors_survive_a_spawn_and_brake_after_a_reset():
    """A spawn rebuilds Drake's diagram: the motors and their targets are rebuilt with it."""
    rig = Rig(custom_bot(), joint_positions=TRAILING)
    try:
        rig.command(0.5)
        rig.run(0.5)
        x = rig.pose()[0]
        rig.server.spawn(box_model("crate"), [3.0, 3.0, 0.5])
        rig.run(0.5)
        assert rig.pose()[0] - x == pytest.approx(0.25, rel=0.03)
        rig.server.reset(time_too=False)
        rig.run(0.3)
        assert rig.pose()[0] == pytest.approx(0.0, abs=0.01)  # the command was forgotten
    finally:
        rig.close()
