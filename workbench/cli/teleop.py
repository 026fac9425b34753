"""``workbench teleop``: drive a turtle (turtle_teleop_key) or a robot (teleop_twist_keyboard)."""

from __future__ import annotations

import argparse


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
    from workbench.bus import Node
    from workbench.teleop.run import turtle_teleop, twist_teleop
    from workbench.teleop.terminal import RawTerminal

    # fails early, before joining the bus, without a terminal
    terminal = RawTerminal(raw=args.kind == "twist")
    if args.kind == "turtle":
        node = Node("teleop_turtle")
        for name in ("scale_linear", "scale_angular"):
            if getattr(args, name) is not None:
                node.set_param(f"~{name}", getattr(args, name))
        loop = turtle_teleop
    else:
        node = Node("teleop_twist_keyboard")
        for name in ("speed", "turn"):
            if getattr(args, name) is not None:
                node.set_param(f"~{name}", getattr(args, name))
        loop = twist_teleop
    try:
        return loop(node, terminal, args.topic)
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
