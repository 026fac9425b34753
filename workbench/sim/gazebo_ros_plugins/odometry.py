"""Odometry out of a Gazebo drive plugin: ``nav_msgs/Odometry`` and the ``odom -> base`` transform.

Shared by ``diff_drive`` and ``planar_move``, which fill them alike in gazebo_plugins
(noetic): the header's frame is the odometry frame and the child frame the robot's
base frame (both through ``tf_prefix``), the stamp is the simulated time, the pose
covariance is the diagonal ``(1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3)`` (x, y certain;
z, roll, pitch unknown; yaw 1e-3) and the twist covariance is left zero. The
transform goes on ``/tf`` from the odometry frame to the base frame with the pose.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp

#: The pose covariance's diagonal, row-major 6x6 indices 0, 7, 14, 21, 28, 35.
POSE_COVARIANCE_DIAGONAL = (1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3)


@dataclass
class Odometry2D:
    """A pose and the twist in the base frame, as the plugins publish them.

    Attributes:
        position: ``(x, y, z)`` in the odometry frame, m.
        orientation: Quaternion ``(x, y, z, w)``.
        linear: ``(vx, vy)`` in the base frame, m/s.
        angular_z: Yaw rate, rad/s.
    """

    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    orientation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    linear: tuple[float, float] = (0.0, 0.0)
    angular_z: float = 0.0


class OdometryPublisher:
    """Publishes :class:`Odometry2D` on a topic and (optionally) as a transform.

    Args:
        ros: The plugin's namespace and frames.
        topic: The odometry topic (relative to the namespace), or None for none.
        odometry_frame: Frame of the pose (before ``tf_prefix``).
        base_frame: The robot's frame (before ``tf_prefix``).
        transform: Also broadcast ``odometry_frame -> base_frame`` on ``/tf``.
    """

    def __init__(
        self,
        ros: PluginRos,
        topic: str | None,
        odometry_frame: str,
        base_frame: str,
        transform: bool,
    ) -> None:
        from workbench.msgs.nav_msgs import Odometry

        self.frame = ros.frame(odometry_frame)
        self.child_frame = ros.frame(base_frame)
        self.topic = ros.topic(topic) if topic is not None else None
        self._message = Odometry
        self._publisher: Any = None
        self._broadcaster: Any = None
        if ros.node is None:
            return
        if self.topic is not None:
            self._publisher = ros.node.create_publisher(self.topic, Odometry, queue_size=1)
        if transform:
            from workbench.tf.broadcaster import TransformBroadcaster

            self._broadcaster = TransformBroadcaster(ros.node)

    def publish(self, stamp: float, odometry: Odometry2D) -> None:
        """Send ``odometry`` stamped ``stamp`` (simulated time, s)."""
        if self._broadcaster is not None:
            from workbench.tf.broadcaster import make_transform

            self._broadcaster.send_transform(
                make_transform(
                    self.frame, self.child_frame, odometry.position, odometry.orientation, stamp
                )
            )
        if self._publisher is None:
            return
        message = self._message()
        message.header.stamp = ros_stamp(stamp)
        message.header.frame_id = self.frame
        message.child_frame_id = self.child_frame
        pose = message.pose.pose
        pose.position.x, pose.position.y, pose.position.z = odometry.position
        q = pose.orientation
        q.x, q.y, q.z, q.w = odometry.orientation
        for i, value in enumerate(POSE_COVARIANCE_DIAGONAL):
            message.pose.covariance[7 * i] = value
        twist = message.twist.twist
        twist.linear.x, twist.linear.y = odometry.linear
        twist.angular.z = odometry.angular_z
        self._publisher.publish(message)
