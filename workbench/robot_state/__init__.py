"""The robot's state on tf: ``robot_state_publisher`` and ``joint_state_publisher``.

::

    from workbench.model import load_robot
    from workbench.robot_state import JointStatePublisher, RobotStatePublisher
    robot = load_robot("robot_arm")
    rsp = RobotStatePublisher(robot, node)      # /joint_states -> /tf, /tf_static
    jsp = JointStatePublisher(robot, node)      # defaults (or sliders) -> /joint_states

``workbench run robot_state_publisher robot_state_publisher`` and the
joint_state_publisher nodes are in :mod:`workbench.robot_state.nodes`.
"""

from __future__ import annotations

from workbench.robot_state.display import RobotModelDisplay
from workbench.robot_state.joint_state_publisher import JointStatePublisher, ros_default_position
from workbench.robot_state.state_publisher import RobotStatePublisher

__all__ = [
    "JointStatePublisher",
    "RobotModelDisplay",
    "RobotStatePublisher",
    "ros_default_position",
]
