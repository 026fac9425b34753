"""``workbench run PKG EXE [args]``: run one node (rosrun).

The lookup is lean: a declared node (entry point) is found through package
metadata and only its module is imported; the launcher's script search (and
with it the bus) is imported only when no entry point matches.
"""

from __future__ import annotations

import argparse
from pathlib import Path


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "package", nargs="?", help="package name (beginner_tutorials, turtlesim ...)"
    )
    parser.add_argument(
        "type", nargs="?", help="executable: a declared node or a script name (talker.py)"
    )
    parser.add_argument(
        "args",
        nargs=argparse.REMAINDER,
        help="the node's arguments, including remappings (chatter:=/x, __name:=n, _rate:=5)",
    )
    parser.add_argument("--near", type=Path, help=argparse.SUPPRESS)
    parser.add_argument("--list", action="store_true", help="list the declared nodes")


def run(args: argparse.Namespace) -> int:
    if args.list:
        return list_nodes()
    return run_node(args.package, args.type, list(args.args), near=args.near)


def list_nodes() -> int:
    """Print every declared node as ``package/executable  (module:function)``."""
    from workbench.entry_points import declared_nodes

    for name, target in sorted(declared_nodes().items()):
        print(f"{name}  ({target})")
    return 0


def run_node(
    package: str | None,
    executable: str | None,
    argv: list[str] | None = None,
    *,
    near: Path | None = None,
) -> int:
    """Run node ``package/executable`` in this process with ``argv``; its exit status.

    Args:
        package: The package (``turtlesim``, ``beginner_tutorials``).
        executable: A declared node (``turtlesim_node``) or a script name (``talker.py``).
        argv: The node's arguments, remappings included.
        near: A launch file's folder, where scripts are looked for first.

    Raises:
        UnknownNodeError: No package/executable given, or neither a declared node nor a
            script of that name exists (the message lists the known nodes).
    """
    from workbench.entry_points import UnknownNodeError, call_node, find_node

    if not package or not executable:
        raise UnknownNodeError(
            "give a package and an executable", hint="e.g. workbench run turtlesim turtlesim_node"
        )
    target = find_node(package, executable)
    if target is not None:
        return call_node(target, list(argv or []))
    from workbench.bus.launcher import run_script_node

    return run_script_node(package, executable, list(argv or []), near)
