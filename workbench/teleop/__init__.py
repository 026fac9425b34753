"""Driving robots from the keyboard or the lidar: the lab's teleop and wander nodes.

* :mod:`workbench.teleop.keys`: :class:`Velocity` and turtlesim's turtle_teleop_key keys.
* :mod:`workbench.teleop.twist_keyboard`: teleop_twist_keyboard (``u i o`` / ``j k l`` ...).
* :mod:`workbench.teleop.turtlebot3`: turtlebot3_teleop_key (``w a s d x``).
* :mod:`workbench.teleop.turtlebot3_drive`: turtlebot3_drive, the lidar wanderer.
* :mod:`workbench.teleop.terminal`: single keys from a real terminal in raw mode.

Key handling and decisions are plain classes (no terminal, no bus); each module's
``main(argv)`` is the node ``workbench run`` and launch files start.
"""

from __future__ import annotations

from workbench.teleop.keys import TurtleKeys, Velocity
from workbench.teleop.turtlebot3 import Turtlebot3Keys
from workbench.teleop.turtlebot3_drive import Turtlebot3Drive
from workbench.teleop.twist_keyboard import TwistKeys

__all__ = ["Turtlebot3Drive", "Turtlebot3Keys", "TurtleKeys", "TwistKeys", "Velocity"]
