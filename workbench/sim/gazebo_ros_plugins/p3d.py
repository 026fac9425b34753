"""``libgazebo_ros_p3d.so``: a link's true pose and velocity as ``nav_msgs/Odometry`` (``GazeboRosP3D``).

Parameters, as gazebo_plugins' gazebo_ros_p3d.cpp (noetic-devel) reads them::

    <plugin name="p3d_base_controller" filename="libgazebo_ros_p3d.so">
      <bodyName>base_link</bodyName>              <!-- required: a link of the model -->
      <topicName>base_pose_ground_truth</topicName> <!-- required -->
      <frameName>map</frameName>                  <!-- world (default), map, or a link -->
      <xyzOffset>0 0 0</xyzOffset>  <rpyOffset>0 0 0</rpyOffset>
      <gaussianNoise>0.01</gaussianNoise>         <!-- stddev on the twist -->
      <updateRate>100</updateRate>                <!-- Hz; 0: every physics step -->
    </plugin>

Only while the topic has subscribers, the plugin publishes the link's pose (position +
``xyzOffset``, orientation turned by ``rpyOffset``) and its world velocity and angular
velocity plus noise, ``header.frame_id`` ``frameName`` (tf-resolved, no leading slash)
and ``child_frame_id`` ``bodyName``, stamped with simulated time; covariance
diagonals are ``gaussianNoise``^2. With a link as ``frameName`` the pose is relative
to that link (``q_L * q_F^-1`` for the orientation, as the plugin composes it) and the
velocities are differences turned by the link's orientation (``RotateVector``, as the
plugin does). Names are relative to ``<robotNamespace>`` (none: global).
``<xyzOffsets>``/``<rpyOffsets>`` (plural, as PR2's URDF writes them) are not read by
gazebo_ros_p3d and are ignored here too, with a warning. A missing ``bodyName`` or
``topicName``, or a link the model lacks, is one error line.
"""

from __future__ import annotations

import logging
from typing import Any

import numpy as np

from workbench.sim.gazebo_ros_plugins.links import find_link, link_state, noise_seed, vector
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp
from workbench.sim.listener_count import ListenerCount
from workbench.sim.plugins import ModelPlugin, PluginSetupError, SdfElement, UpdateInfo

_LOG = logging.getLogger("workbench.sim.gazebo_ros_plugins")
_WORLD_FRAMES = ("/world", "world", "/map", "map")


class GazeboRosP3D(ModelPlugin):
    """Publishes ground truth odometry of a link (see the module docstring)."""

    publisher: Any = None

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("GazeboRosP3D", sdf, model.name, node, default_namespace="")
        where = f"model '{model.name}': p3d plugin '{sdf.name}'"
        body = ros.text("bodyName")
        topic = ros.text("topicName")
        if not body:
            raise PluginSetupError(f"{where} needs <bodyName> (the link it reports)")
        self.model = model
        self.body = body
        self.link = find_link(model, body, sdf.name, "bodyName")
        if topic is None:
            raise PluginSetupError(f"{where} needs <topicName>")
        frame = ros.string("frameName", "world")
        self.reference = None
        if frame not in _WORLD_FRAMES:
            self.reference = find_link(model, frame, sdf.name, "frameName")
        self.frame = ros.frame(frame)
        for plural in ("xyzOffsets", "rpyOffsets"):
            if ros.text(plural) is not None:
                _LOG.warning(
                    "%s: <%s> is not read by gazebo_ros_p3d (it reads <%s>); ignored as in Gazebo",
                    where,
                    plural,
                    plural[:-1],
                )
        self.xyz = vector(ros.text("xyzOffset"))
        from pydrake.math import RollPitchYaw

        self.rpy = RollPitchYaw(*vector(ros.text("rpyOffset"))).ToRotationMatrix()
        self.noise = ros.number("gaussianNoise", 0.0)
        self.update_rate = max(ros.number("updateRate", 0.0), 0.0)
        self.rng = np.random.default_rng(noise_seed(model.name, sdf.name))
        self.last_time = model.sim_time
        #: The last message, or None.
        self.latest_message: Any = None
        self._listeners = ListenerCount()
        self.publisher = None
        if node is not None and topic:
            self.publisher = node.create_publisher(
                ros.topic(topic), "nav_msgs/Odometry", queue_size=1
            )

    def active(self) -> bool:
        return self.publisher is None or self._listeners(self.publisher) > 0

    def update(self, info: UpdateInfo) -> None:
        if info.sim_time == self.last_time:
            return  # Gazebo waits until time has passed since the last message
        self.last_time = info.sim_time
        world = self.model.server.world
        X_WL, v, w = link_state(world, self.link)
        position = np.array(X_WL.translation())
        rotation = X_WL.rotation()
        if self.reference is not None:
            X_WF, v_F, w_F = link_state(world, self.reference)
            R_WF = X_WF.rotation()
            position = R_WF.inverse().multiply(position - np.array(X_WF.translation()))
            rotation = rotation.multiply(R_WF.inverse())
            v = R_WF.multiply(v - v_F)
            w = R_WF.multiply(w - w_F)
        position = position + self.xyz
        q = self.rpy.multiply(rotation).ToQuaternion()
        if self.noise > 0:
            v = v + self.rng.normal(0.0, self.noise, 3)
            w = w + self.rng.normal(0.0, self.noise, 3)
        self.latest_message = self._message(position, q, v, w, info.sim_time)
        if self.publisher is not None:
            self.publisher.publish(self.latest_message)

    def _message(self, p: np.ndarray, q: Any, v: np.ndarray, w: np.ndarray, seconds: float) -> Any:
        from workbench.msgs.nav_msgs import Odometry

        message = Odometry()
        message.header.frame_id = self.frame
        message.header.stamp = ros_stamp(seconds)
        message.child_frame_id = self.body
        pose, twist = message.pose.pose, message.twist.twist
        pose.position.x, pose.position.y, pose.position.z = (float(x) for x in p)
        pose.orientation.x, pose.orientation.y = float(q.x()), float(q.y())
        pose.orientation.z, pose.orientation.w = float(q.z()), float(q.w())
        twist.linear.x, twist.linear.y, twist.linear.z = (float(x) for x in v)
        twist.angular.x, twist.angular.y, twist.angular.z = (float(x) for x in w)
        variance = self.noise * self.noise
        covariance = [0.0] * 36
        for i in (0, 7, 14, 21, 28, 35):
            covariance[i] = variance
        message.pose.covariance = list(covariance)
        message.twist.covariance = list(covariance)
        return message

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None
