"""turtle_teleop_key's loop on the bus (the other teleops live in their own modules)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from workbench.teleop.keys import TURTLE_BANNER, TurtleKeys
from workbench.teleop.terminal import RawTerminal
from workbench.teleop.twist_keyboard import main as twist_teleop_main
from workbench.teleop.twist_keyboard import twist_teleop

__all__ = ["turtle_teleop", "turtle_teleop_main", "twist_teleop", "twist_teleop_main"]


def turtle_teleop(node: Any, terminal: RawTerminal, topic: str = "turtle1/cmd_vel") -> int:
    """turtle_teleop_key: publish one Twist per arrow key on ``topic`` until ``q``."""
    from workbench.msgs.geometry_msgs import Twist

    keys = TurtleKeys(node.get_param("~scale_linear", 2.0), node.get_param("~scale_angular", 2.0))
    pub = node.create_publisher(topic, Twist, queue_size=1)
    print(TURTLE_BANNER, flush=True)
    with terminal:
        while not keys.quit:
            chars = terminal.read(None)
            for command in keys.feed(chars):
                pub.publish(command.to_twist())
    return 0


def turtle_teleop_main(argv: Sequence[str] | None = None) -> int:
    """``turtlesim/turtle_teleop_key`` for ``workbench run`` and launch files."""
    from workbench.bus import Node

    node = Node("teleop_turtle", argv=list(argv or []))
    try:
        return turtle_teleop(node, RawTerminal())
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
