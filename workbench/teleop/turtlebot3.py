"""turtlebot3_teleop_key: w/x and a/d step a TurtleBot3's velocity, as the Noetic node does.

* ``w``/``x`` raise/lower the target linear velocity by 0.01 m/s, ``a``/``d`` the
  target angular velocity by 0.1 rad/s, clamped to the model's limits: burger
  0.22 m/s and 2.84 rad/s, waffle and waffle_pi 0.26 m/s and 1.82 rad/s (any
  other name: burger's). Each prints ``currently:\\tlinear vel V\\t angular vel W ``
  and every 20th reprints the help.
* ``s`` or space stops at once (target and output zero); Ctrl-C quits.
* Every 0.1 s (the key timeout), or after each key, it publishes the output
  velocity, which moves towards the target by at most half a step per message.
* The model is the ``model`` parameter (the launch file sets it from
  ``TURTLEBOT3_MODEL``), else the ``TURTLEBOT3_MODEL`` environment variable,
  else burger. On exit it publishes a zero Twist.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

from workbench.teleop.keys import Velocity
from workbench.teleop.terminal import RawTerminal, run_keyboard_node

#: The help text, printed as ``print(TB3_BANNER)`` (so with a blank line before and after).
TB3_BANNER = """
Control Your TurtleBot3!
---------------------------
Moving around:
        w
   a    s    d
        x

w/x : increase/decrease linear velocity (Burger : ~ 0.22, Waffle and Waffle Pi : ~ 0.26)
a/d : increase/decrease angular velocity (Burger : ~ 2.84, Waffle and Waffle Pi : ~ 1.82)

space key, s : force stop

CTRL-C to quit
"""

#: model -> (largest linear m/s, largest angular rad/s).
VELOCITY_LIMITS: dict[str, tuple[float, float]] = {
    "burger": (0.22, 2.84),
    "waffle": (0.26, 1.82),
    "waffle_pi": (0.26, 1.82),
}
LINEAR_STEP = 0.01
ANGULAR_STEP = 0.1
KEY_TIMEOUT = 0.1
HELP_EVERY = 20
CTRL_C = "\x03"


def velocity_limits(model: str) -> tuple[float, float]:
    """The (linear, angular) limits of a TurtleBot3 model; burger's for an unknown name."""
    return VELOCITY_LIMITS.get(model, VELOCITY_LIMITS["burger"])


def status_line(linear: float, angular: float) -> str:
    """``currently:\\tlinear vel 0.01\\t angular vel 0.0 `` (as the original prints it)."""
    return f"currently:\tlinear vel {linear}\t angular vel {angular} "


def clamp(value: float, low: float, high: float) -> float:
    """``value`` limited to ``[low, high]``."""
    return low if value < low else high if value > high else value


def ramp(output: float, target: float, slop: float) -> float:
    """``output`` moved towards ``target`` by at most ``slop`` (the simple profile)."""
    if target > output:
        return min(target, output + slop)
    if target < output:
        return max(target, output - slop)
    return target


def model_name(param: Any = None) -> str:
    """The model: the ``model`` parameter, else ``TURTLEBOT3_MODEL``, else burger."""
    if param:
        return str(param)
    return os.environ.get("TURTLEBOT3_MODEL", "").strip() or "burger"


class Turtlebot3Keys:
    """The key handling and velocity profile of turtlebot3_teleop_key, without terminal or bus.

    Args:
        model: ``burger``, ``waffle`` or ``waffle_pi`` (the limits).
    """

    def __init__(self, model: str = "burger") -> None:
        self.model = model
        self.max_linear, self.max_angular = velocity_limits(model)
        self.target_linear = 0.0
        self.target_angular = 0.0
        self.linear = 0.0
        self.angular = 0.0
        self.quit = False
        self._presses = 0

    def press(self, key: str) -> list[str]:
        """Handle one key (``""``: none came within the key timeout); the lines to print."""
        lines: list[str] = []
        if key in ("w", "x"):
            step = LINEAR_STEP if key == "w" else -LINEAR_STEP
            self.target_linear = clamp(self.target_linear + step, -self.max_linear, self.max_linear)
        elif key in ("a", "d"):
            step = ANGULAR_STEP if key == "a" else -ANGULAR_STEP
            self.target_angular = clamp(
                self.target_angular + step, -self.max_angular, self.max_angular
            )
        elif key in (" ", "s"):
            self.target_linear = self.linear = 0.0
            self.target_angular = self.angular = 0.0
            lines.append(status_line(self.target_linear, self.target_angular))
        elif key == CTRL_C:
            self.quit = True
        if key in ("w", "x", "a", "d"):
            self._presses += 1
            lines.append(status_line(self.target_linear, self.target_angular))
        if self._presses == HELP_EVERY:
            lines.append(TB3_BANNER)
            self._presses = 0
        return lines

    def command(self) -> Velocity:
        """Step the output towards the target (half a key step at most) and return it."""
        self.linear = ramp(self.linear, self.target_linear, LINEAR_STEP / 2.0)
        self.angular = ramp(self.angular, self.target_angular, ANGULAR_STEP / 2.0)
        return Velocity(x=self.linear, yaw=self.angular)


def turtlebot3_teleop(node: Any, terminal: RawTerminal, topic: str = "cmd_vel") -> int:
    """Run turtlebot3_teleop_key on ``node`` until Ctrl-C; publishes on ``topic``.

    Returns:
        0.
    """
    from workbench.msgs.geometry_msgs import Twist

    publisher = node.create_publisher(topic, Twist, queue_size=10)
    keys = Turtlebot3Keys(model_name(node.get_param("model", None)))
    try:
        print(TB3_BANNER, flush=True)
        with terminal:
            while not keys.quit and not node.is_shutdown:
                try:
                    chars = terminal.read(KEY_TIMEOUT)
                except EOFError:
                    break
                for key in chars or [""]:
                    for line in keys.press(key):
                        print(line, flush=True)
                    if keys.quit:
                        break
                    publisher.publish(keys.command().to_twist())
    finally:
        if not publisher.closed:
            publisher.publish(Twist())
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """``turtlebot3_teleop/turtlebot3_teleop_key`` for ``workbench run`` and launch files."""
    return run_keyboard_node("turtlebot3_teleop", argv, turtlebot3_teleop)
