"""``workbench run PKG TYPE [args]``: run one node (rosrun)."""

from __future__ import annotations

import argparse
from pathlib import Path


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "package", nargs="?", help="package name (beginner_tutorials, turtlesim ...)"
    )
    parser.add_argument(
        "type", nargs="?", help="node type: a registered node or a script name (talker.py)"
    )
    parser.add_argument(
        "args",
        nargs=argparse.REMAINDER,
        help="the node's arguments, including remappings (chatter:=/x, __name:=n, _rate:=5)",
    )
    parser.add_argument("--near", type=Path, help=argparse.SUPPRESS)
    parser.add_argument("--list", action="store_true", help="list the registered nodes")


def run(args: argparse.Namespace) -> int:
    from workbench.bus.launcher import run_node
    from workbench.bus.registry import UnknownNodeError, registered_nodes

    if args.list:
        for name, target in sorted(registered_nodes().items()):
            print(f"{name}  ({target})")
        return 0
    if not args.package or not args.type:
        raise UnknownNodeError(
            "give a package and a node type", hint="e.g. workbench run beginner_tutorials talker.py"
        )
    return run_node(args.package, args.type, list(args.args), near=args.near)
