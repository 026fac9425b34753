"""Keyboard teleop loops on the bus (turtle_teleop_key, teleop_twist_keyboard)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from workbench.teleop.keys import TURTLE_BANNER, TWIST_BANNER, TurtleKeys, TwistKeys
from workbench.teleop.terminal import RawTerminal


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


def twist_teleop(node: Any, terminal: RawTerminal, topic: str = "cmd_vel") -> int:
    """teleop_twist_keyboard: the u/i/o block, speed keys, stop on any other key."""
    from workbench.msgs.geometry_msgs import Twist

    keys = TwistKeys(node.get_param("~speed", 0.5), node.get_param("~turn", 1.0))
    timeout = float(node.get_param("~key_timeout", 0.5))
    pub = node.create_publisher(topic, Twist, queue_size=1)
    print(TWIST_BANNER, flush=True)
    print(keys.status(), flush=True)
    with terminal:
        while not keys.quit:
            chars = terminal.read(timeout if timeout > 0 else None) or ""
            for key in chars or [""]:
                command, line = keys.press(key)
                if line:
                    print(line, flush=True)
                if command is not None:
                    pub.publish(command.to_twist())
                if keys.quit:
                    break
    pub.publish(Twist())
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


def twist_teleop_main(argv: Sequence[str] | None = None) -> int:
    """``teleop_twist_keyboard/teleop_twist_keyboard`` for ``workbench run``."""
    from workbench.bus import Node

    node = Node("teleop_twist_keyboard", argv=list(argv or []))
    try:
        return twist_teleop(node, RawTerminal(raw=True))
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
