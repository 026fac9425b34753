"""``libgazebo_ros_diff_drive.so``: a two-wheeled robot driven by ``cmd_vel``, with odometry.

Parameters, defaults and behaviour are gazebo_plugins' ``GazeboRosDiffDrive``
(noetic)::

    <plugin name="differential_drive_controller" filename="libgazebo_ros_diff_drive.so">
      <leftJoint>left_joint</leftJoint>          <rightJoint>right_joint</rightJoint>
      <wheelSeparation>0.34</wheelSeparation>    <wheelDiameter>0.15</wheelDiameter>
      <wheelTorque>5</wheelTorque>               <!-- N m, each wheel's motor limit -->
      <wheelAcceleration>0</wheelAcceleration>   <!-- m/s^2 at the rim; 0: none -->
      <commandTopic>cmd_vel</commandTopic>       <odometryTopic>odom</odometryTopic>
      <odometryFrame>odom</odometryFrame>        <robotBaseFrame>base_footprint</robotBaseFrame>
      <odometrySource>world</odometrySource>     <!-- or encoder -->
      <publishTf>true</publishTf>                <!-- false: no odometry at all -->
      <publishOdomTF>true</publishOdomTF>        <publishWheelTF>false</publishWheelTF>
      <publishWheelJointState>false</publishWheelJointState>
      <updateRate>100</updateRate>               <!-- Hz of publishing and new targets -->
      <rosDebugLevel>na</rosDebugLevel>
    </plugin>

A ``geometry_msgs/Twist`` on ``commandTopic`` (relative to the robot's namespace,
see :mod:`.ros_context`) sets ``linear.x`` and ``angular.z``. Every ``1 /
updateRate`` s of simulated time (0: every physics step) the plugin publishes
``nav_msgs/Odometry`` on ``odometryTopic``, the transform ``odometryFrame ->
robotBaseFrame``, and if asked the wheel transforms (parent link -> wheel link,
pose relative to the model) and ``joint_states`` (the two wheel positions, right
first); then it gives the wheels rim speeds ``v -+ w b / 2`` (left, right),
ramped by ``wheelAcceleration`` when that is set. The wheel joints get velocity
motors limited to ``wheelTorque`` (:mod:`workbench.sim.motors`, Gazebo's
``"vel"``/``"fmax"`` joint parameters) that hold those speeds in every physics
step, through contact. ``world`` odometry is the model's true pose; ``encoder``
odometry integrates the wheels' turns (:mod:`.encoder_odometry`).

``legacyMode`` (which swapped the wheels' roles before ROS Melodic) is gone from
noetic's plugin and is ignored here as there; ``true`` gets a warning.
"""

from __future__ import annotations

import contextlib
import logging
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.gazebo_ros_plugins.encoder_odometry import EncoderOdometry
from workbench.sim.gazebo_ros_plugins.odometry import Odometry2D, OdometryPublisher
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos
from workbench.sim.gazebo_ros_plugins.wheel_states import WheelStatePublisher
from workbench.sim.plugins import ModelPlugin, SdfElement, UpdateInfo

_LOG = logging.getLogger("workbench.sim.gazebo_ros_plugins")


class GazeboRosDiffDrive(ModelPlugin):
    """Differential drive: wheel motors from ``cmd_vel``, odometry and transforms out."""

    wheels: tuple[str, ...] = ()  # right, left; none until loaded

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("DiffDrive", sdf, model.name, node)
        self.model = model
        self.separation = ros.number("wheelSeparation", 0.34)
        self.diameter = ros.number("wheelDiameter", 0.15)
        self.acceleration = ros.number("wheelAcceleration", 0.0)
        self.torque = ros.number("wheelTorque", 5.0)
        #: Hz; the server calls :meth:`update` at this rate (0: every physics step).
        self.update_rate = max(ros.number("updateRate", 100.0), 0.0)
        self.encoder = ros.choice("odometrySource", {"encoder": True, "world": False}, False)
        if ros.boolean("legacyMode", False):
            _LOG.warning(
                "%s: <legacyMode> true is ignored, as by noetic's diff drive (swap "
                "<leftJoint> and <rightJoint> if the robot turns the wrong way)",
                ros.info,
            )
        self.wheels = (  # right first, as in Gazebo's plugin
            _wheel(model, ros, "rightJoint", "right_joint"),
            _wheel(model, ros, "leftJoint", "left_joint"),
        )
        model.add_velocity_motors({joint: self.torque for joint in self.wheels})
        publish_odometry = ros.boolean("publishTf", True)
        self.odometry = OdometryPublisher(
            ros,
            ros.string("odometryTopic", "odom") if publish_odometry else None,
            ros.string("odometryFrame", "odom"),
            ros.string("robotBaseFrame", "base_footprint"),
            transform=publish_odometry and ros.boolean("publishOdomTF", True),
        )
        self.publish_odometry = publish_odometry
        self.wheel_states = WheelStatePublisher(
            ros,
            model,
            self.wheels,
            transforms=ros.boolean("publishWheelTF", False),
            joint_states=ros.boolean("publishWheelJointState", False),
        )
        self.odometer = EncoderOdometry(self.separation, self.diameter)
        self.command = (0.0, 0.0)
        self.ramped = [0.0, 0.0]  # Gazebo's wheel_speed_instr_, right and left, m/s
        self.last: tuple[float, list[float]] | None = None  # time and wheel angles
        if node is not None:
            node.create_subscription(
                ros.topic(ros.string("commandTopic", "cmd_vel")),
                "geometry_msgs/Twist",
                self.on_command,
                queue_size=1,
                inline=True,
            )

    def on_command(self, message: Any) -> None:
        """A ``geometry_msgs/Twist``: forward speed (m/s) and yaw rate (rad/s)."""
        self.command = (float(message.linear.x), float(message.angular.z))

    def reset(self) -> None:
        self.odometer.reset()
        self.command = (0.0, 0.0)
        self.last = None
        self.model.set_motor_velocities({joint: 0.0 for joint in self.wheels})

    def close(self) -> None:
        if not self.wheels:
            return
        with contextlib.suppress(SimulationError):  # the model may be gone already
            self.model.set_motor_velocities({joint: 0.0 for joint in self.wheels})

    def update(self, info: UpdateInfo) -> None:
        now = info.sim_time
        angles = [self.model.joint_position(joint) for joint in self.wheels]
        elapsed = 0.0
        if self.last is not None:
            then, before = self.last
            elapsed = now - then
            if self.encoder:
                right, left = (a - b for a, b in zip(angles, before, strict=True))
                self.odometer.advance(left, right, elapsed)
        self.last = (now, angles)
        if self.publish_odometry:
            self.odometry.publish(now, self._odometry())
        self.wheel_states.publish(now)
        self._set_targets(elapsed)

    def _set_targets(self, elapsed: float) -> None:
        """New wheel targets from the command, ramped as Gazebo does."""
        forward, turn = self.command
        radius = self.diameter / 2.0
        wanted = (forward + turn * self.separation / 2.0, forward - turn * self.separation / 2.0)
        current = [self.model.joint_velocity(joint) * radius for joint in self.wheels]
        close = any(abs(w - c) < 0.01 for w, c in zip(wanted, current, strict=True))
        if self.acceleration == 0.0 or close:
            speeds = list(wanted)
        else:
            step = self.acceleration * elapsed
            for i in range(2):
                gap = wanted[i] - current[i]
                self.ramped[i] += min(gap, step) if gap >= 0.0 else max(gap, -step)
            speeds = list(self.ramped)
        self.model.set_motor_velocities(
            {joint: speed / radius for joint, speed in zip(self.wheels, speeds, strict=True)}
        )

    def _odometry(self) -> Odometry2D:
        if self.encoder:
            odometer = self.odometer
            return Odometry2D(
                (odometer.x, odometer.y, 0.0),
                odometer.quaternion(),
                (odometer.v, 0.0),
                odometer.w,
            )
        return world_odometry(self.model)


def world_odometry(model: Any) -> Odometry2D:
    """The model's true pose, its velocity turned into the heading's frame and its yaw rate."""
    import math

    X = model.pose()
    p = X.translation()
    q = X.rotation().ToQuaternion()
    yaw = X.rotation().ToRollPitchYaw().yaw_angle()
    v = model.linear_velocity()
    c, s = math.cos(yaw), math.sin(yaw)
    return Odometry2D(
        (float(p[0]), float(p[1]), float(p[2])),
        (float(q.x()), float(q.y()), float(q.z()), float(q.w())),
        (c * v[0] + s * v[1], c * v[1] - s * v[0]),
        float(model.angular_velocity()[2]),
    )


def _wheel(model: Any, ros: PluginRos, tag: str, default: str) -> str:
    """The joint named by ``tag``; a missing one stops the plugin with a clear message."""
    name = ros.string(tag, default)
    if not model.has_joint(name):
        joints = ", ".join(model.joint_names) or "none"
        raise SimulationError(
            f"model '{model.name}': diff drive '{ros.sdf.name}' has no wheel joint '{name}' "
            f"(<{tag}>); the model runs without the drive",
            hint=f"joints: {joints}",
        )
    return name
