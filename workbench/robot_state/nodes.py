"""The robot's runnable nodes for ``workbench run`` and launch files.

* ``robot_state_publisher/robot_state_publisher`` (and its old name ``state_publisher``);
* ``joint_state_publisher/joint_state_publisher`` (``_use_gui:=true`` for sliders) and
  ``joint_state_publisher_gui/joint_state_publisher_gui``.

The robot is the private parameter ``~robot`` (a ``urdf/`` name or a path) or the
XML in ``robot_description``. The nodes are declared as entry points of the
``workbench.nodes`` group in ``pyproject.toml``.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import TYPE_CHECKING

from workbench.errors import ModelError

if TYPE_CHECKING:
    from workbench.bus import Node
    from workbench.model import Robot


def load_robot_from_params(node: Node) -> Robot:
    """The robot named by ``~robot`` or described by the ``robot_description`` XML.

    Raises:
        ModelError: Neither parameter is set (or the description does not load).
    """
    from workbench.model import load_robot

    source = node.get_param("~robot", None)
    if source:
        return load_robot(source)
    xml = node.get_param("robot_description", None)
    if not xml:
        raise ModelError(
            f"{node.name}: no robot given",
            hint="set the private parameter ~robot (e.g. _robot:=robot_arm) or robot_description",
        )
    from workbench.model import RobotDescription

    return load_robot(RobotDescription.from_text(str(xml)))


def robot_state_publisher(argv: Sequence[str] = ()) -> int:
    """Run robot_state_publisher for the robot of the parameters until interrupted.

    Args:
        argv: The node's command line (remappings and ``_param:=value`` settings).
    """
    from workbench.bus import Node
    from workbench.robot_state.state_publisher import RobotStatePublisher

    node = Node("robot_state_publisher", argv=list(argv))
    robot = load_robot_from_params(node)
    RobotStatePublisher(
        robot,
        node,
        publish_frequency=float(node.get_param("~publish_frequency", 50.0)),
        tf_prefix=str(node.get_param("~tf_prefix", "")),
    )
    node.bus.spin()
    return 0


def _joint_state_publisher(argv: Sequence[str], gui: bool) -> int:
    from workbench.bus import Node
    from workbench.robot_state.joint_state_publisher import JointStatePublisher

    node = Node("joint_state_publisher", argv=list(argv))
    robot = load_robot_from_params(node)
    jsp = JointStatePublisher(
        robot,
        node,
        rate=float(node.get_param("~rate", 10.0)),
        zeros=node.get_param("~zeros", None),
        use_gui=gui or bool(node.get_param("~use_gui", False)),
        source_list=node.get_param("~source_list", []) or [],
    )
    if jsp.viewer is None:
        node.bus.spin()
        return 0
    node.get_logger().info(f"joint sliders at {jsp.viewer.url}")
    # The sliders live in Meshcat, which answers only this thread: poll them here.
    while not node.is_shutdown:
        jsp.poll_gui()
        time.sleep(0.02)
    return 0


def joint_state_publisher(argv: Sequence[str] = ()) -> int:
    """Run joint_state_publisher (defaults; ``_use_gui:=true`` for sliders)."""
    return _joint_state_publisher(argv, gui=False)


def joint_state_publisher_gui(argv: Sequence[str] = ()) -> int:
    """Run joint_state_publisher with Meshcat sliders."""
    return _joint_state_publisher(argv, gui=True)
