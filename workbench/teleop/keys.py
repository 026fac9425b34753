"""Velocity commands, and turtle_teleop_key's arrow keys.

* :class:`Velocity`: the command every teleop here produces (a Twist's x, y, z, yaw).
* ``turtle_teleop_key`` (turtlesim, Noetic): arrow keys only; up/down give
  ``linear.x = +-scale_linear`` (2.0), left/right ``angular.z = +-scale_angular``
  (2.0); one command per key press; ``q`` quits.

teleop_twist_keyboard's keys are in :mod:`workbench.teleop.twist_keyboard`,
turtlebot3_teleop_key's in :mod:`workbench.teleop.turtlebot3`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

ESC = "\x1b"
ARROWS = {"A": "up", "B": "down", "C": "right", "D": "left"}


@dataclass(frozen=True)
class Velocity:
    """A velocity command (body frame): linear m/s, angular rad/s."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    yaw: float = 0.0

    def to_twist(self) -> Any:
        """As a ``geometry_msgs/Twist``."""
        from workbench.msgs.geometry_msgs import Twist, Vector3

        return Twist(linear=Vector3(x=self.x, y=self.y, z=self.z), angular=Vector3(z=self.yaw))


TURTLE_BANNER = (
    "Reading from keyboard\n"
    "---------------------------\n"
    "Use arrow keys to move the turtle. 'q' to quit."
)


class TurtleKeys:
    """turtle_teleop_key: feed it characters, get a command per arrow key.

    Args:
        scale_linear: m/s for up/down (the ``~scale_linear`` parameter).
        scale_angular: rad/s for left/right (``~scale_angular``).
    """

    def __init__(self, scale_linear: float = 2.0, scale_angular: float = 2.0) -> None:
        self.scale_linear = scale_linear
        self.scale_angular = scale_angular
        self._pending = ""
        self.quit = False

    def feed(self, chars: str) -> list[Velocity]:
        """Characters typed (arrow keys arrive as ``ESC [ A`` ...) -> commands to publish."""
        out: list[Velocity] = []
        for ch in chars:
            if self.quit:
                break
            if self._pending:
                self._pending += ch
                if len(self._pending) == 2 and ch != "[":
                    self._pending = ""
                elif len(self._pending) == 3:
                    key = ARROWS.get(ch)
                    self._pending = ""
                    if key is not None:
                        out.append(self._command(key))
                continue
            if ch == ESC:
                self._pending = ch
            elif ch == "q":
                self.quit = True
        return out

    def _command(self, key: str) -> Velocity:
        linear = {"up": 1.0, "down": -1.0}.get(key, 0.0)
        angular = {"left": 1.0, "right": -1.0}.get(key, 0.0)
        return Velocity(x=self.scale_linear * linear, yaw=self.scale_angular * angular)
