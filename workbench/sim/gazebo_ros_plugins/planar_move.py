"""``libgazebo_ros_planar_move.so``: a model moved kinematically in the plane by ``cmd_vel``.

As gazebo_plugins' ``GazeboRosPlanarMove`` (noetic)::

    <plugin name="object_controller" filename="libgazebo_ros_planar_move.so">
      <commandTopic>cmd_vel</commandTopic>     <odometryTopic>odom</odometryTopic>
      <odometryFrame>odom</odometryFrame>      <robotBaseFrame>base_footprint</robotBaseFrame>
      <odometryRate>20</odometryRate>          <!-- Hz; 0: no odometry -->
      <cmdTimeout>-1</cmdTimeout>              <!-- s without a command before stopping; <0: never -->
      <publishOdometryTf>true</publishOdometryTf>
    </plugin>

Before every physics step the model's velocity is set from the last
``geometry_msgs/Twist``: ``linear.x``/``linear.y`` turned by the model's yaw into
the world frame (vertical velocity zero) and ``angular.z`` as the only angular
velocity; friction and collisions do not slow it. Odometry is the model's true
pose, with the twist differentiated from the pose since the last message, in the
base frame. Without ``<robotNamespace>`` the topics are global (``/cmd_vel``):
unlike ``diff_drive``, noetic's plugin defaults to the empty namespace.

``publishOdometryTf`` is not in noetic's plugin (which always broadcasts the
transform, its default here); ROS 2's plugin has it as ``publish_odom_tf``.
"""

from __future__ import annotations

import math
from typing import Any

from workbench.sim.gazebo_ros_plugins.odometry import Odometry2D, OdometryPublisher
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos
from workbench.sim.plugins import ModelPlugin, SdfElement, UpdateInfo


class GazeboRosPlanarMove(ModelPlugin):
    """Set the model's planar velocity from ``cmd_vel`` every step; publish its odometry."""

    update_rate = 0.0  # before every physics step, as Gazebo's WorldUpdateBegin

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("PlanarMovePlugin", sdf, model.name, node, default_namespace="")
        self.model = model
        rate = ros.number("odometryRate", 20.0)
        self.odometry_period = 1.0 / rate if rate > 0.0 else math.inf
        self.timeout = ros.number("cmdTimeout", -1.0)
        self.odometry = OdometryPublisher(
            ros,
            ros.string("odometryTopic", "odom"),
            ros.string("odometryFrame", "odom"),
            ros.string("robotBaseFrame", "base_footprint"),
            transform=ros.boolean("publishOdometryTf", True),
        )
        self.command = (0.0, 0.0, 0.0)
        self.command_time: float | None = model.sim_time
        self.last_publish = model.sim_time
        self.last_pose = model.pose()
        if node is not None:
            node.create_subscription(
                ros.topic(ros.string("commandTopic", "cmd_vel")),
                "geometry_msgs/Twist",
                self.on_command,
                queue_size=1,
                inline=True,
            )

    def on_command(self, message: Any) -> None:
        """A ``geometry_msgs/Twist``: ``linear.x``, ``linear.y`` (m/s), ``angular.z`` (rad/s)."""
        self.command = (float(message.linear.x), float(message.linear.y), float(message.angular.z))
        self.command_time = None  # stamped with the simulated time at the next update

    def reset(self) -> None:
        self.command = (0.0, 0.0, 0.0)
        self.command_time = self.last_publish = self.model.sim_time
        self.last_pose = self.model.pose()

    def update(self, info: UpdateInfo) -> None:
        now = info.sim_time
        if self.command_time is None:
            self.command_time = now
        if self.timeout >= 0.0 and now - self.command_time > self.timeout:
            self.command = (0.0, 0.0, 0.0)
        forward, sideways, turn = self.command
        yaw = _yaw(self.model.pose())
        c, s = math.cos(yaw), math.sin(yaw)
        self.model.set_twist(
            [forward * c - sideways * s, sideways * c + forward * s, 0.0], [0.0, 0.0, turn]
        )
        elapsed = now - self.last_publish
        if elapsed > self.odometry_period:
            self.odometry.publish(now, self._odometry(elapsed))
            self.last_publish = now

    def _odometry(self, elapsed: float) -> Odometry2D:
        """The true pose; the twist from the pose change over ``elapsed`` s, in the base frame."""
        X = self.model.pose()
        p, p0 = X.translation(), self.last_pose.translation()
        vx, vy = (p[0] - p0[0]) / elapsed, (p[1] - p0[1]) / elapsed
        yaw, last_yaw = _yaw(X), _yaw(self.last_pose)
        if self.command[2] > math.pi / elapsed:  # turned too far to tell from two poses
            turn_rate = self.command[2]
        else:
            turn_rate = math.remainder(yaw - last_yaw, 2.0 * math.pi) / elapsed
        self.last_pose = X
        q = X.rotation().ToQuaternion()
        c, s = math.cos(yaw), math.sin(yaw)
        return Odometry2D(
            (float(p[0]), float(p[1]), float(p[2])),
            (float(q.x()), float(q.y()), float(q.z()), float(q.w())),
            (c * vx + s * vy, c * vy - s * vx),
            turn_rate,
        )


def _yaw(X: Any) -> float:
    return float(X.rotation().ToRollPitchYaw().yaw_angle())
