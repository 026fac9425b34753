"""``libgazebo_ros_ft_sensor.so``: the wrench a joint transmits, as ``geometry_msgs/WrenchStamped``.

Parameters, as gazebo_plugins' gazebo_ros_ft_sensor.cpp (noetic-devel) reads them::

    <plugin name="ft_sensor" filename="libgazebo_ros_ft_sensor.so">
      <jointName>joint_1</jointName>     <!-- required: a joint of the model -->
      <topicName>ft_sensor/joint_1</topicName>  <!-- required -->
      <gaussianNoise>0.0</gaussianNoise> <!-- stddev on every component -->
      <updateRate>100</updateRate>       <!-- Hz; 0: every physics step -->
    </plugin>

Only while the topic has subscribers, the plugin publishes the force and torque the
joint exerts on its child link, at the joint, expressed in the child link's frame
(``header.frame_id``, tf-resolved), stamped with simulated time: Drake's joint
reaction force (the constraint's wrench; the joint's own applied effort is not in
it). Gazebo reports the same wrench from ODE's joint feedback (``provideFeedback``),
with the torque about the joint's anchor. Names are relative to ``<robotNamespace>``
(none: global). A missing ``jointName`` or ``topicName``, or a joint the model
lacks, is one error line.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.gazebo_ros_plugins.links import noise_seed
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp
from workbench.sim.listener_count import ListenerCount
from workbench.sim.plugins import ModelPlugin, PluginSetupError, SdfElement, UpdateInfo


class GazeboRosFT(ModelPlugin):
    """Publishes the wrench of a joint on its child link (see the module docstring)."""

    publisher: Any = None

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("GazeboRosFT", sdf, model.name, node, default_namespace="")
        where = f"model '{model.name}': ft_sensor plugin '{sdf.name}'"
        joint = ros.text("jointName")
        if not joint:
            raise PluginSetupError(f"{where} needs <jointName>")
        if not model.has_joint(joint):
            raise PluginSetupError(
                f"{where}: <jointName> '{joint}' is not a joint of the model",
                hint="joints: " + (", ".join(model.joint_names) or "none"),
            )
        topic = ros.text("topicName")
        if not topic:
            raise PluginSetupError(f"{where} needs <topicName>")
        self.model = model
        self.joint = joint
        self.frame = ros.frame(model.joint_links(joint)[1])
        self.noise = ros.number("gaussianNoise", 0.0)
        self.update_rate = max(ros.number("updateRate", 0.0), 0.0)
        self.rng = np.random.default_rng(noise_seed(model.name, sdf.name))
        #: The last ``(force, torque)`` in the child frame, N and N m, or None.
        self.latest: tuple[np.ndarray, np.ndarray] | None = None
        self._listeners = ListenerCount()
        self.publisher = None
        if node is not None:
            self.publisher = node.create_publisher(
                ros.topic(topic), "geometry_msgs/WrenchStamped", queue_size=1
            )

    def active(self) -> bool:
        return self.publisher is None or self._listeners(self.publisher) > 0

    def wrench(self) -> tuple[np.ndarray, np.ndarray]:
        """``(force, torque)`` on the child link at the joint, in the child frame, now."""
        world = self.model.server.world
        joint = world.joint(self.model.name, self.joint)
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        reactions = plant.get_reaction_forces_output_port().Eval(context)
        F = reactions[int(joint.index())]
        R_CJ = joint.frame_on_child().GetFixedPoseInBodyFrame().rotation()
        return (
            np.array(R_CJ.multiply(np.asarray(F.translational()))),
            np.array(R_CJ.multiply(np.asarray(F.rotational()))),
        )

    def update(self, info: UpdateInfo) -> None:
        force, torque = self.wrench()
        if self.noise > 0:
            force = force + self.rng.normal(0.0, self.noise, 3)
            torque = torque + self.rng.normal(0.0, self.noise, 3)
        self.latest = (force, torque)
        if self.publisher is None:
            return
        from workbench.msgs.geometry_msgs import WrenchStamped

        message = WrenchStamped()
        message.header.frame_id = self.frame
        message.header.stamp = ros_stamp(info.sim_time)
        f, t = message.wrench.force, message.wrench.torque
        f.x, f.y, f.z = (float(v) for v in force)
        t.x, t.y, t.z = (float(v) for v in torque)
        self.publisher.publish(message)

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None
