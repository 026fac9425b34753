"""``workbench rviz``: RViz in the browser (markers, tf, robot model, laser, map ...)."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    from workbench.rviz.node import add_arguments

    add_arguments(parser)
    parser.epilog = (
        "Displays without -d: Grid, TF, RobotModel (robot_description), Marker "
        "(visualization_marker), MarkerArray, LaserScan (scan), Map (map). Ctrl-C, SIGINT "
        "or SIGTERM stops it (writing --html/--png)."
    )


def run(args: argparse.Namespace) -> int:
    from workbench.rviz.node import run as run_rviz

    return run_rviz(args)
