"""``libgazebo_ros_joint_state_publisher.so``: ``sensor_msgs/JointState`` of listed joints.

As gazebo_plugins' ``GazeboRosJointStatePublisher`` (noetic)::

    <plugin name="joint_state_publisher" filename="libgazebo_ros_joint_state_publisher.so">
      <jointName>front_caster_of_wheel_joint, front_wheel_joint</jointName>
      <updateRate>100</updateRate>   <!-- Hz; 0: every physics step -->
    </plugin>

``jointName`` is a comma-separated list (spaces are dropped). Every ``1 /
updateRate`` s of simulated time the plugin publishes the joints' names, positions
and velocities, in the listed order, stamped with the simulated time, on
``joint_states`` relative to the robot's namespace (the model's name unless
``<robotNamespace>`` says otherwise; see :mod:`.ros_context`).

Where Gazebo stops with a fatal error on a joint the model lacks, this plugin
logs one error naming model and joint and publishes the others.
"""

from __future__ import annotations

import logging
from typing import Any

from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp
from workbench.sim.plugins import ModelPlugin, SdfElement, UpdateInfo

_LOG = logging.getLogger("workbench.sim.gazebo_ros_plugins")


class GazeboRosJointStatePublisher(ModelPlugin):
    """Publish the listed joints' states at ``updateRate``."""

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("GazeboRosJointStatePublisher", sdf, model.name, node)
        self.model = model
        listed = (ros.text("jointName") or "").replace(" ", "")
        self.joints = []
        for name in listed.split(",") if listed else []:
            if model.has_joint(name):
                self.joints.append(name)
            else:
                _LOG.error(
                    "model '%s': joint_state_publisher '%s': joint '%s' does not exist; "
                    "it is left out of joint_states",
                    model.name,
                    sdf.name,
                    name,
                )
        #: Hz; the server calls :meth:`update` at this rate (0: every physics step).
        self.update_rate = max(ros.number("updateRate", 100.0), 0.0)
        self.publisher: Any = None
        if node is not None:
            self.publisher = node.create_publisher(
                ros.topic("joint_states"), "sensor_msgs/JointState", queue_size=1000
            )

    def update(self, info: UpdateInfo) -> None:
        self.publish(info.sim_time)

    def publish(self, stamp: float) -> None:
        """Send the joints' states stamped ``stamp`` (simulated time, s)."""
        if self.publisher is None:
            return
        from workbench.msgs.sensor_msgs import JointState

        message = JointState()
        message.header.stamp = ros_stamp(stamp)
        message.name = list(self.joints)
        message.position = [self.model.joint_position(j) for j in self.joints]
        message.velocity = [self.model.joint_velocity(j) for j in self.joints]
        self.publisher.publish(message)
