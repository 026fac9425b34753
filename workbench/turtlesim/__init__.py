"""Turtlesim: ROS Noetic's 2D turtle simulator, as a library and a bus node.

``TurtleSim`` is the pure simulation (no bus); :mod:`workbench.turtlesim.node`
puts it on the bus with turtlesim's topics, services and parameters.
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


def _register_nodes() -> None:
    """Make ``turtlesim/turtlesim_node`` and the teleops runnable from launch files."""
    from workbench.bus.registry import register_node

    register_node("turtlesim/turtlesim_node", "workbench.turtlesim.node:main")
    register_node("turtlesim/turtle_teleop_key", "workbench.teleop.run:turtle_teleop_main")
    register_node(
        "teleop_twist_keyboard/teleop_twist_keyboard", "workbench.teleop.run:twist_teleop_main"
    )


_register_nodes()

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
