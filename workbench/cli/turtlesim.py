"""``workbench turtlesim``: run the turtlesim simulator (turtlesim_node)."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    from workbench.turtlesim.node import add_arguments

    add_arguments(parser)
    parser.add_argument(
        "ros_args", nargs="*", metavar="NAME:=VALUE", help="remappings and _param:=value"
    )


def run(args: argparse.Namespace) -> int:
    from workbench.turtlesim.node import run_node

    return run_node(args, args.ros_args)
