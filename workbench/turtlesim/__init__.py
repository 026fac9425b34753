"""Turtlesim: ROS Noetic's 2D turtle simulator, as a library and a bus node.

``TurtleSim`` is the pure simulation (no bus); :mod:`workbench.turtlesim.node`
puts it on the bus with turtlesim's topics, services and parameters;
:mod:`workbench.turtlesim.tf_demo` is Experiment 4's turtle tf demo in one process.
"""

from __future__ import annotations

from workbench.turtlesim.sim import (
    CANVAS_PX,
    COMMAND_TIMEOUT,
    DEFAULT_BACKGROUND,
    DEFAULT_PEN,
    METER_PX,
    UPDATE_PERIOD,
    UPDATE_RATE,
    WORLD_SIZE,
    Turtle,
    TurtleError,
    TurtlePose,
    TurtleSim,
)

__all__ = [
    "CANVAS_PX",
    "COMMAND_TIMEOUT",
    "DEFAULT_BACKGROUND",
    "DEFAULT_PEN",
    "METER_PX",
    "UPDATE_PERIOD",
    "UPDATE_RATE",
    "WORLD_SIZE",
    "Turtle",
    "TurtleError",
    "TurtlePose",
    "TurtleSim",
]
