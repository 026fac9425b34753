"""``workbench turtlesim``: run the turtlesim simulator (turtlesim_node)."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from types import SimpleNamespace


def configure(parser: argparse.ArgumentParser) -> None:
    from workbench.turtlesim.node import add_arguments

    add_arguments(parser)
    parser.add_argument(
        "ros_args", nargs="*", metavar="NAME:=VALUE", help="remappings and _param:=value"
    )
    parser.epilog = "Ctrl-C, SIGINT or SIGTERM stops it (writing the --png canvas a last time)."


def run(args: argparse.Namespace) -> int:
    return turtlesim(
        png=args.png, view=args.view, port=args.port, seed=args.seed, ros_args=args.ros_args
    )


def turtlesim(
    *,
    png: str | None = None,
    view: bool = False,
    port: int = 0,
    seed: int = 0,
    ros_args: Sequence[str] = (),
) -> int:
    """Run turtlesim_node on the default bus until interrupted.

    Args:
        png: Write the canvas here every second and when stopping.
        view: Show the canvas live in the browser.
        port: Port of the live view (0: any free one).
        seed: Seed of the turtle drawings.
        ros_args: ``from:=to`` remappings and ``_param:=value`` settings.

    Raises:
        TurtleError: A port outside 0..65535, or a --png that cannot be written.
    """
    from workbench.turtlesim.node import TurtleError, run_node

    if not 0 <= port < 65536:
        raise TurtleError(f"--port must be in 0..65535, got {port}")
    if png is not None:
        from workbench.output_files import check_output

        check_output(png, "png", option="--png", error=TurtleError)
    options = SimpleNamespace(png=png, view=view, port=port, seed=seed)
    return run_node(options, list(ros_args))
