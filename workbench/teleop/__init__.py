"""Keyboard teleoperation: turtle_teleop_key and teleop_twist_keyboard.

:mod:`workbench.teleop.keys` turns key presses into velocity commands (no
terminal, no bus); :mod:`workbench.teleop.terminal` reads keys from a real
terminal in raw mode; the ``workbench teleop`` command joins them to the bus.
"""

from __future__ import annotations

from workbench.teleop.keys import TurtleKeys, TwistKeys, Velocity

__all__ = ["TurtleKeys", "TwistKeys", "Velocity"]
