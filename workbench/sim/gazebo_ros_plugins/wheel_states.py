"""The wheels of ``diff_drive``: their transforms (``publishWheelTF``) and ``joint_states``
(``publishWheelJointState``).

As gazebo_plugins' ``publishWheelTF``/``publishWheelJointState`` (noetic): each
transform goes from the joint's parent link to its child link (names through
``tf_prefix``) and carries the child link's pose relative to the *model* frame
(Gazebo's ``Link::RelativePose``; the same thing when the parent is the root
link); ``joint_states`` (relative to the namespace) lists the wheel joints with
positions only, in the plugin's order.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp


class WheelStatePublisher:
    """Publishes wheel transforms and/or joint states (nothing when both are off)."""

    def __init__(
        self,
        ros: PluginRos,
        model: Any,
        joints: Sequence[str],
        *,
        transforms: bool,
        joint_states: bool,
    ) -> None:
        self.model = model
        self.joints = list(joints)
        self.frames = [tuple(ros.frame(link) for link in model.joint_links(j)) for j in joints]
        self._broadcaster: Any = None
        self._joint_states: Any = None
        if ros.node is None:
            return
        if transforms:
            from workbench.tf.broadcaster import TransformBroadcaster

            self._broadcaster = TransformBroadcaster(ros.node)
        if joint_states:
            self._joint_states = ros.node.create_publisher(
                ros.topic("joint_states"), "sensor_msgs/JointState", queue_size=1000
            )

    def publish(self, stamp: float) -> None:
        """Send what was asked for, stamped ``stamp`` (simulated time, s)."""
        if self._broadcaster is not None:
            self._send_transforms(stamp)
        if self._joint_states is not None:
            from workbench.msgs.sensor_msgs import JointState

            message = JointState()
            message.header.stamp = ros_stamp(stamp)
            message.name = list(self.joints)
            message.position = [self.model.joint_position(j) for j in self.joints]
            self._joint_states.publish(message)

    def _send_transforms(self, stamp: float) -> None:
        from workbench.tf.broadcaster import make_transform

        X_WM_inverse = self.model.pose().inverse()
        transforms = []
        for joint, (parent, child) in zip(self.joints, self.frames, strict=True):
            link = self.model.joint_links(joint)[1]
            X_ML = X_WM_inverse.multiply(self.model.link_pose(link))
            q = X_ML.rotation().ToQuaternion()
            transforms.append(
                make_transform(
                    parent, child, X_ML.translation(), (q.x(), q.y(), q.z(), q.w()), stamp
                )
            )
        for transform in transforms:
            self._broadcaster.send_transform(transform)
