"""``joint_state_publisher``: a robot's movable joints on ``joint_states``, with optional sliders.

Positions start at ROS's defaults -- 0 when 0 is inside the joint's limits,
else the middle of the limits -- or at the ``zeros`` given. With ``use_gui``
the Meshcat joint sliders (the viewer's ``add_joint_sliders``) play the part of
the joint_state_publisher_gui window. ``source_list`` topics are merged in as
ROS does: their positions override the defaults for the joints they name.
"""

from __future__ import annotations

import threading
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np


def ros_default_position(lower: float, upper: float) -> float:
    """joint_state_publisher's start value: 0 if inside [lower, upper], else the midpoint."""
    if np.isfinite(lower) and np.isfinite(upper) and (lower > 0 or upper < 0):
        return (lower + upper) / 2.0
    if np.isfinite(lower) and lower > 0:
        return float(lower)
    if np.isfinite(upper) and upper < 0:
        return float(upper)
    return 0.0


class JointStatePublisher:
    """Publishes ``sensor_msgs/JointState`` for a robot's movable joints.

    Args:
        robot: A loaded :class:`workbench.model.Robot`, or a ``RobotDescription``,
            ``urdf/`` name or path to load.
        node: The node to publish with; ``None`` creates ``joint_state_publisher``.
        rate: Publishing rate in Hz (ROS's default 10); 0 publishes only on :meth:`publish`.
        zeros: Joint name -> start position (rad or m), like the ``zeros`` parameter.
        use_gui: Read positions from Meshcat sliders on each publish.
        viewer: The viewer for the sliders (default the process-wide one).
        source_list: JointState topics whose positions are merged in.
    """

    def __init__(
        self,
        robot: Any,
        node: Any = None,
        rate: float = 10.0,
        zeros: Mapping[str, float] | None = None,
        use_gui: bool = False,
        viewer: Any = None,
        source_list: Iterable[str] = (),
    ) -> None:
        from workbench.msgs.sensor_msgs import JointState

        if node is None:
            from workbench.bus import Node

            node = Node("joint_state_publisher")
        from workbench.model import as_robot

        robot = as_robot(robot)
        robot.finalize()
        self.robot = robot
        self.node = node
        self.names = list(robot.joint_names)
        lower, upper = robot.lower_limits, robot.upper_limits
        self.positions = {
            name: ros_default_position(float(lo), float(hi))
            for name, lo, hi in zip(self.names, lower, upper, strict=True)
        }
        for name, value in (zeros or {}).items():
            if name not in self.positions:
                robot.positions_from({name: value})  # raises UnknownJointError naming the joint
            self.positions[name] = float(value)
        self._message = JointState
        self.pub = node.create_publisher("joint_states", JointState, queue_size=10)
        self.viewer = None
        self._sliders: dict[str, str] = {}
        self._gui_thread: int | None = None
        if use_gui:
            self._start_gui(viewer)
        self.sources = [
            node.create_subscription(topic, JointState, self._on_source, queue_size=10)
            for topic in source_list
        ]
        self.timer = (
            node.create_timer(1.0 / rate, lambda _event: self.publish()) if rate > 0 else None
        )

    def _start_gui(self, viewer: Any) -> None:
        if viewer is None:
            from workbench.viz import Viewer

            viewer = Viewer.instance()
        self.viewer = viewer
        # Drake's Meshcat answers only the thread that created it: remember which one
        self._gui_thread = threading.get_ident()
        q = self.robot.positions_from(self.positions)
        prefix = viewer.show_robot(self.robot, q)
        for slider, joint in zip(
            viewer.add_joint_sliders(self.robot, prefix), self.robot.joint_names, strict=True
        ):
            self._sliders[slider] = joint

    def _on_source(self, msg: Any) -> None:
        for name, value in zip(msg.name, msg.position, strict=False):
            if name in self.positions:
                self.positions[name] = float(value)

    def set_position(self, name: str, value: float) -> None:
        """Set one joint (rad or m); an unknown name raises ``UnknownJointError``."""
        if name not in self.positions:
            self.robot.positions_from({name: value})
        self.positions[name] = float(value)

    def poll_gui(self) -> None:
        """Read the sliders into the positions; call it from the thread that made the viewer.

        A node with sliders calls this in its main loop; :meth:`message` calls it too
        when it runs on that thread (a timer on the bus's threads cannot reach Meshcat).
        """
        if self.viewer is None:
            return
        for slider, value in self.viewer.poll_sliders().items():
            joint = self._sliders.get(slider)
            if joint is not None:
                self.positions[joint] = value

    def message(self) -> Any:
        """The JointState to publish now (stamped with the node's clock)."""
        if self.viewer is not None and threading.get_ident() == self._gui_thread:
            self.poll_gui()
        msg = self._message()
        msg.header.stamp = self.node.now()
        msg.name = list(self.names)
        msg.position = [self.positions[name] for name in self.names]
        return msg

    def publish(self) -> Any:
        """Publish the current positions; returns the message."""
        msg = self.message()
        self.pub.publish(msg)
        return msg
