"""``workbench teleop``: drive a turtle (turtle_teleop_key) or a robot (teleop_twist_keyboard)."""

from __future__ import annotations

import argparse

#: Largest speed a keyboard teleop option takes (m/s or rad/s).
MAX_SPEED = 100.0


def configure(parser: argparse.ArgumentParser) -> None:
    kinds = parser.add_subparsers(dest="kind", metavar="KIND", required=True)
    turtle = kinds.add_parser("turtle", help="arrow keys drive turtle1 (turtle_teleop_key)")
    turtle.add_argument("--topic", default="turtle1/cmd_vel", help="Twist topic (turtle1/cmd_vel)")
    turtle.add_argument("--scale-linear", type=float, help="m/s per key press (2.0)")
    turtle.add_argument("--scale-angular", type=float, help="rad/s per key press (2.0)")
    twist = kinds.add_parser("twist", help="u/i/o j/k/l m/,/. keys (teleop_twist_keyboard)")
    twist.add_argument("--topic", default="cmd_vel", help="Twist topic (cmd_vel)")
    twist.add_argument("--speed", type=float, help="linear speed, m/s (0.5)")
    twist.add_argument("--turn", type=float, help="angular speed, rad/s (1.0)")


def run(args: argparse.Namespace) -> int:
    if args.kind == "turtle":
        return turtle(
            topic=args.topic, scale_linear=args.scale_linear, scale_angular=args.scale_angular
        )
    return twist(topic=args.topic, speed=args.speed, turn=args.turn)


def turtle(
    *,
    topic: str = "turtle1/cmd_vel",
    scale_linear: float | None = None,
    scale_angular: float | None = None,
) -> int:
    """turtle_teleop_key: the arrow keys publish Twists on ``topic`` until q or a stop.

    Args:
        topic: The Twist topic.
        scale_linear: m/s per key press (default 2.0).
        scale_angular: rad/s per key press (default 2.0).

    Raises:
        TeleopError: No terminal to read keys from.
    """
    from workbench.teleop.run import turtle_teleop

    params = {"scale_linear": scale_linear, "scale_angular": scale_angular}
    return _drive("teleop_turtle", turtle_teleop, topic, params, raw=False)


def twist(*, topic: str = "cmd_vel", speed: float | None = None, turn: float | None = None) -> int:
    """teleop_twist_keyboard: u/i/o j/k/l m/,/. publish Twists on ``topic`` until a stop.

    Args:
        topic: The Twist topic.
        speed: Linear speed, m/s (default 0.5).
        turn: Angular speed, rad/s (default 1.0).

    Raises:
        TeleopError: No terminal to read keys from.
    """
    from workbench.teleop.run import twist_teleop

    return _drive(
        "teleop_twist_keyboard", twist_teleop, topic, {"speed": speed, "turn": turn}, raw=True
    )


def _drive(name: str, loop, topic: str, params: dict[str, float | None], *, raw: bool) -> int:
    from workbench.bus import Node
    from workbench.bus.names import check_name
    from workbench.errors import WorkbenchError
    from workbench.teleop.terminal import RawTerminal

    for key, value in params.items():
        if value is not None and not abs(value) <= MAX_SPEED:  # NaN fails the comparison
            option = "--" + key.replace("_", "-")
            raise WorkbenchError(
                f"{option} must be a finite speed within ±{MAX_SPEED:g}, got {value:g}",
                hint="m/s for linear speeds, rad/s for turning",
            )
    check_name(topic, "topic name")  # before joining: a typo must not replace a running teleop
    terminal = RawTerminal(raw=raw)  # fails early, before joining the bus, without a terminal
    node = Node(name)
    for key, value in params.items():
        if value is not None:
            node.set_param(f"~{key}", value)
    try:
        return loop(node, terminal, topic)
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
