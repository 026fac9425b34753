"""``workbench sim``: the simulation server with the Gazebo ROS API (gzserver)."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    from workbench.sim.gzserver import add_arguments

    add_arguments(parser)
    parser.epilog = (
        "Shipped worlds: empty (and those in mapping/worlds). Spawn models from another "
        "terminal with 'workbench run gazebo_ros spawn_model -file F -urdf -model NAME'. "
        "Ctrl-C, SIGINT or SIGTERM stops it (writing the --html recording)."
    )


def run(args: argparse.Namespace) -> int:
    from workbench.sim.gzserver import options_from

    return sim(options_from(args))


def sim(options: object) -> int:
    """Run the server with :class:`workbench.sim.gzserver.ServerOptions` until stopped."""
    from workbench.sim.gzserver import ServerOptions, run_server

    assert isinstance(options, ServerOptions)
    return run_server(options)
