"""Key presses to velocity commands, as the two ROS keyboard teleops map them.

* ``turtle_teleop_key`` (turtlesim, Noetic): arrow keys only; up/down give
  ``linear.x = +-scale_linear`` (2.0), left/right ``angular.z = +-scale_angular``
  (2.0); one command per key press; ``q`` quits.
* ``teleop_twist_keyboard`` (ROS 1): the ``u i o / j k l / m , .`` block,
  shifted for holonomic moves, ``t``/``b`` for z; ``q/z``, ``w/x``, ``e/c`` scale
  both/linear/angular speed by 10%; any other key stops; speed 0.5, turn 1.0.
"""

from __future__ import annotations

from dataclasses import dataclass

ESC = "\x1b"
ARROWS = {"A": "up", "B": "down", "C": "right", "D": "left"}


@dataclass(frozen=True)
class Velocity:
    """A velocity command (body frame): linear m/s, angular rad/s."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    yaw: float = 0.0

    def to_twist(self):
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


TWIST_BANNER = """
Reading from the keyboard  and Publishing to Twist!
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

For Holonomic mode (strafing), hold down the shift key:
---------------------------
   U    I    O
   J    K    L
   M    <    >

t : up (+z)
b : down (-z)

anything else : stop

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%

CTRL-C to quit
"""

MOVE_BINDINGS: dict[str, tuple[int, int, int, int]] = {
    "i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
    "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
    "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
    "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
    "t": (0, 0, 1, 0), "b": (0, 0, -1, 0),
}  # fmt: skip
SPEED_BINDINGS: dict[str, tuple[float, float]] = {
    "q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1.0), "x": (0.9, 1.0), "e": (1.0, 1.1), "c": (1.0, 0.9),
}  # fmt: skip


class TwistKeys:
    """teleop_twist_keyboard: one key (or a timeout, ``""``) at a time.

    Args:
        speed: Linear speed, m/s.
        turn: Angular speed, rad/s.
    """

    def __init__(self, speed: float = 0.5, turn: float = 1.0) -> None:
        self.speed = speed
        self.turn = turn
        self.direction = (0, 0, 0, 0)
        self.quit = False
        self.status_lines = 0

    def status(self) -> str:
        return f"currently:\tspeed {self.speed}\tturn {self.turn} "

    def press(self, key: str) -> tuple[Velocity | None, str | None]:
        """Handle one key (``""`` when the key timeout passed with no key).

        Returns:
            ``(command to publish or None, line to print or None)``.
        """
        if key in MOVE_BINDINGS:
            self.direction = MOVE_BINDINGS[key]
        elif key in SPEED_BINDINGS:
            lin, ang = SPEED_BINDINGS[key]
            self.speed *= lin
            self.turn *= ang
            line = self.status()
            if self.status_lines == 14:
                line = TWIST_BANNER + "\n" + line
            self.status_lines = (self.status_lines + 1) % 15
            return self._velocity(), line
        else:
            if key == "" and self.direction == (0, 0, 0, 0):
                return None, None
            self.direction = (0, 0, 0, 0)
            if key == "\x03":
                self.quit = True
        return self._velocity(), None

    def _velocity(self) -> Velocity:
        x, y, z, th = self.direction
        return Velocity(x * self.speed, y * self.speed, z * self.speed, th * self.turn)
