"""teleop_twist_keyboard: keys to ``geometry_msgs/Twist`` on ``cmd_vel``, as ROS 1's node does.

Behaviour of the Noetic package (1.0.0), with the later ``~speed_limit`` and
``~turn_limit`` parameters:

* ``u i o / j k l / m , .`` set a direction (forward/back times turn left/right),
  their shifted keys ``U I O / J K L / M < >`` the holonomic (strafing) ones,
  ``t``/``b`` up/down; the Twist is the direction times ``speed`` (linear) and
  ``turn`` (angular).
* ``q/z`` scale both speeds by 1.1/0.9, ``w/x`` only linear, ``e/c`` only angular;
  each prints ``currently:\\tspeed S\\tturn T `` and every 15th reprints the help.
* Any other key stops (``k`` is simply not a move key); Ctrl-C quits.
* Parameters ``~speed`` (0.5), ``~turn`` (1.0), ``~repeat_rate`` (0: publish once
  per key; > 0: also repeat the last Twist at that rate, Hz), ``~key_timeout``
  (0: wait for keys forever; > 0: stop when no key came for that long, s),
  ``~speed_limit``/``~turn_limit`` (1000).
* Before the help is printed it waits for a subscriber on ``cmd_vel``; on exit it
  publishes a zero Twist.
"""

from __future__ import annotations

import collections
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

from workbench.teleop.keys import Velocity
from workbench.teleop.terminal import RawTerminal, run_keyboard_node

#: The help text, printed as ``print(TWIST_BANNER)`` (so with a blank line before and after).
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

#: key -> (x, y, z, yaw) direction.
MOVE_BINDINGS: dict[str, tuple[int, int, int, int]] = {
    "i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
    "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
    "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
    "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
    "t": (0, 0, 1, 0), "b": (0, 0, -1, 0),
}  # fmt: skip
#: key -> (linear factor, angular factor).
SPEED_BINDINGS: dict[str, tuple[float, float]] = {
    "q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1.0), "x": (0.9, 1.0), "e": (1.0, 1.1), "c": (1.0, 0.9),
}  # fmt: skip
CTRL_C = "\x03"
STOPPED = (0, 0, 0, 0)


def status_line(speed: float, turn: float) -> str:
    """``currently:\\tspeed 0.5\\tturn 1.0 `` (Python's float text, trailing space included)."""
    return f"currently:\tspeed {speed}\tturn {turn} "


class TwistKeys:
    """The key handling of teleop_twist_keyboard, without terminal or bus.

    Args:
        speed: Linear speed, m/s.
        turn: Angular speed, rad/s.
        speed_limit: Largest ``speed`` the speed keys reach.
        turn_limit: Largest ``turn`` the speed keys reach.
    """

    def __init__(
        self,
        speed: float = 0.5,
        turn: float = 1.0,
        speed_limit: float = 1000.0,
        turn_limit: float = 1000.0,
    ) -> None:
        self.speed = speed
        self.turn = turn
        self.speed_limit = speed_limit
        self.turn_limit = turn_limit
        self.direction = STOPPED
        self.quit = False
        self._speed_changes = 0

    def press(self, key: str) -> tuple[Velocity | None, list[str]]:
        """Handle one key (``""``: the key timeout passed without one).

        Returns:
            The command to publish (None: publish nothing) and the lines to print.
        """
        lines: list[str] = []
        if key in MOVE_BINDINGS:
            self.direction = MOVE_BINDINGS[key]
        elif key in SPEED_BINDINGS:
            linear, angular = SPEED_BINDINGS[key]
            self.speed = min(self.speed_limit, self.speed * linear)
            self.turn = min(self.turn_limit, self.turn * angular)
            if self.speed == self.speed_limit:
                lines.append("Linear speed limit reached!")
            if self.turn == self.turn_limit:
                lines.append("Angular speed limit reached!")
            lines.append(status_line(self.speed, self.turn))
            if self._speed_changes == 14:
                lines.append(TWIST_BANNER)
            self._speed_changes = (self._speed_changes + 1) % 15
        elif key == "" and self.direction == STOPPED:
            return None, lines  # a timeout while stopped sends nothing
        else:
            self.direction = STOPPED
            if key == CTRL_C:
                self.quit = True
                return None, lines  # the stop Twist is sent on the way out
        return self.velocity(), lines

    def velocity(self) -> Velocity:
        """The current command: direction times speed and turn."""
        x, y, z, yaw = self.direction
        return Velocity(x * self.speed, y * self.speed, z * self.speed, yaw * self.turn)


class TwistRepeater:
    """Publishes from a thread: each update once, in order; with a rate, the last one again.

    Args:
        publish: Called with each command to send.
        rate: Repeat the last command this often, Hz (0: only on updates).
    """

    def __init__(self, publish: Callable[[Velocity], None], rate: float = 0.0) -> None:
        self._publish = publish
        self._period = 1.0 / rate if rate > 0 else None
        self._pending: collections.deque[Velocity] = collections.deque()
        self._last = Velocity()
        self._done = False
        self._condition = threading.Condition()
        self._thread = threading.Thread(target=self._run, name="teleop-publisher", daemon=True)
        self._thread.start()

    def update(self, command: Velocity) -> None:
        """Publish ``command`` (and repeat it, with a rate, until the next update)."""
        with self._condition:
            self._pending.append(command)
            self._condition.notify()

    def stop(self) -> None:
        """Send what is pending, then a zero Twist, and end the thread."""
        with self._condition:
            self._done = True
            self._condition.notify()
        self._thread.join()

    def _run(self) -> None:
        while True:
            with self._condition:
                if not self._pending and not self._done:
                    self._condition.wait(self._period)
                if self._pending:
                    self._last = self._pending.popleft()
                elif self._done:
                    break
            if not self._send(self._last):
                return
        self._send(Velocity())

    def _send(self, command: Velocity) -> bool:
        from workbench.bus import ShutdownError

        try:
            self._publish(command)
        except ShutdownError:
            return False
        return True


def wait_for_subscribers(publisher: Any, node: Any, poll: float = 0.5) -> None:
    """Wait until ``publisher`` has a subscriber, saying so every 2.5 s as the original does."""
    polls = 0
    while publisher.get_num_connections() == 0 and not node.is_shutdown:
        if polls == 4:
            print(f"Waiting for subscriber to connect to {publisher.topic}", flush=True)
        time.sleep(poll)
        polls = (polls + 1) % 5


def twist_teleop(node: Any, terminal: RawTerminal, topic: str = "cmd_vel") -> int:
    """Run teleop_twist_keyboard on ``node`` until Ctrl-C; publishes on ``topic``.

    Returns:
        0.
    """
    from workbench.msgs.geometry_msgs import Twist

    keys = TwistKeys(
        float(node.get_param("~speed", 0.5)),
        float(node.get_param("~turn", 1.0)),
        float(node.get_param("~speed_limit", 1000.0)),
        float(node.get_param("~turn_limit", 1000.0)),
    )
    repeat_rate = float(node.get_param("~repeat_rate", 0.0))
    key_timeout = float(node.get_param("~key_timeout", 0.0))
    publisher = node.create_publisher(topic, Twist, queue_size=1)
    repeater = TwistRepeater(lambda command: publisher.publish(command.to_twist()), repeat_rate)
    try:
        wait_for_subscribers(publisher, node)
        repeater.update(keys.velocity())
        print(TWIST_BANNER)
        print(status_line(keys.speed, keys.turn), flush=True)
        with terminal:
            while not keys.quit:
                try:
                    chars = terminal.read(key_timeout if key_timeout > 0 else None)
                except EOFError:
                    break
                for key in chars or [""]:
                    command, lines = keys.press(key)
                    for line in lines:
                        print(line, flush=True)
                    if command is not None:
                        repeater.update(command)
                    if keys.quit:
                        break
    finally:
        repeater.stop()
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """``teleop_twist_keyboard/teleop_twist_keyboard.py`` for ``workbench run`` and launch files."""
    return run_keyboard_node("teleop_twist_keyboard", argv, twist_teleop)
