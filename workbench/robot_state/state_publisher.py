"""``robot_state_publisher``: joint positions in, the robot's link frames out on tf.

For every joint of the robot, the pose of its child link in its parent link is
computed with Drake's forward kinematics (``Robot.forward_kinematics``):

* fixed joints once, latched, on ``/tf_static``;
* movable joints on ``/tf`` for every ``sensor_msgs/JointState`` on
  ``joint_states``, stamped with the message's stamp, at most
  ``publish_frequency`` times per second.

Bad messages are handled as ROS's node does: a message whose ``name`` and
``position`` arrays differ in length is ignored with an error; names that are
not joints of the robot are ignored (with one warning per name, which ROS does
not give); joints not named in a message keep no fresh transform.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.spatial import xyz_quaternion_from_rigid_transform
from workbench.tf.broadcaster import StaticTransformBroadcaster, TransformBroadcaster
from workbench.tf.buffer import stamp_msg
from workbench.tf.timeconv import to_ns


def _transform_msg(parent: str, child: str, X_PC: Any, stamp_ns: int) -> Any:
    from workbench.tf.buffer import _classes

    _, Header, TransformStamped, Transform, Vector3, Quaternion = _classes()  # noqa: N806
    p, q = xyz_quaternion_from_rigid_transform(X_PC)
    return TransformStamped._from_wire(
        Header._from_wire(0, stamp_msg(stamp_ns), parent),
        child,
        Transform._from_wire(
            Vector3._from_wire(float(p[0]), float(p[1]), float(p[2])),
            Quaternion._from_wire(float(q[0]), float(q[1]), float(q[2]), float(q[3])),
        ),
    )


class RobotStatePublisher:
    """Publishes a robot's link frames from its joint states.

    Args:
        robot: A loaded :class:`workbench.model.Robot` (finalized here), or a
            ``RobotDescription``, ``urdf/`` name or path to load into a plant of its own.
        node: The node to publish with; ``None`` creates ``robot_state_publisher`` on the
            default bus.
        publish_frequency: Most transforms per second for moving joints (Hz), ROS's default 50.
        tf_prefix: Prepended as ``<prefix>/<link>`` to every frame name when not empty.
        topic: The joint state topic.
    """

    def __init__(
        self,
        robot: Any,
        node: Any = None,
        publish_frequency: float = 50.0,
        tf_prefix: str = "",
        topic: str = "joint_states",
    ) -> None:
        from workbench.msgs.sensor_msgs import JointState

        if node is None:
            from workbench.bus import Node

            node = Node("robot_state_publisher")
        from workbench.model import as_robot

        robot = as_robot(robot)
        robot.finalize()
        self.robot = robot
        self.node = node
        self.publish_interval_ns = round(1e9 / publish_frequency) if publish_frequency > 0 else 0
        self.tf_prefix = tf_prefix.strip("/")
        self.fixed_joints = [j for j in robot.joints if j.type == "fixed"]
        self.moving_joints = {j.name: j for j in robot.movable_joints}
        self._q = np.asarray(robot.default_positions(), dtype=float)
        self._last_published: dict[str, int] = {}
        self._warned: set[str] = set()
        self.ignored_messages = 0
        self.published = 0
        self.broadcaster = TransformBroadcaster(node)
        self.static_broadcaster = StaticTransformBroadcaster(node)
        self.publish_fixed_transforms()
        self.sub = node.create_subscription(topic, JointState, self.on_joint_state, queue_size=10)

    def _frame(self, link: str) -> str:
        return f"{self.tf_prefix}/{link}" if self.tf_prefix else link

    def joint_transforms(self, joints: list[Any], q: Any, stamp_ns: int) -> list[Any]:
        """TransformStamped parent link -> child link for ``joints`` at positions ``q``."""
        poses = self.robot.forward_kinematics(q)
        out = []
        for joint in joints:
            X_PC = poses[joint.parent].inverse() @ poses[joint.child]
            out.append(
                _transform_msg(self._frame(joint.parent), self._frame(joint.child), X_PC, stamp_ns)
            )
        return out

    def publish_fixed_transforms(self) -> None:
        """Send every fixed joint on ``/tf_static`` (latched, valid at all times)."""
        if self.fixed_joints:
            self.static_broadcaster.send_transform(
                self.joint_transforms(self.fixed_joints, self._q, 0)
            )

    def on_joint_state(self, msg: Any) -> None:
        """Handle one ``sensor_msgs/JointState`` (also callable directly)."""
        names = list(msg.name)
        positions = np.asarray(msg.position, dtype=float)
        logger = self.node.get_logger()
        if len(names) != len(positions):
            self.ignored_messages += 1
            if len(positions) == 0:
                logger.warn(
                    "Robot state publisher ignored a JointState message about joint(s) "
                    f'"{", ".join(names)}" without position'
                )
            else:
                logger.error(
                    "Robot state publisher ignored an invalid JointState message: "
                    f"{len(names)} names but {len(positions)} positions"
                )
            return
        stamp = to_ns(msg.header.stamp)
        known: dict[str, float] = {}
        for name, value in zip(names, positions, strict=True):
            if name in self.moving_joints:
                known[name] = float(value)
            elif name not in self._warned:
                self._warned.add(name)
                logger.warn(
                    f"robot_state_publisher: '{name}' is not a movable joint of robot "
                    f"'{self.robot.name}'; ignoring it (joints: {', '.join(self.moving_joints)})"
                )
        due = []
        for name in known:
            last = self._last_published.get(name)
            if last is not None and stamp < last:
                last = None  # time went backwards (bag loop, simulation reset): republish
            if last is None or stamp >= last + self.publish_interval_ns:
                due.append(name)
        if not due:
            return
        self._q = self.robot.positions_from(known, base=self._q)
        joints = [self.moving_joints[name] for name in due]
        self.broadcaster.send_transform(self.joint_transforms(joints, self._q, stamp))
        for name in due:
            self._last_published[name] = stamp
        self.published += 1
