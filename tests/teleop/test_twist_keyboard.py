"""teleop_twist_keyboard against the ROS 1 node: its key tables, texts, parameters and exit.

The original (ros-teleop/teleop_twist_keyboard 1.0.0, Noetic): moveBindings map
u i o / j k l / m , . (and shifted U I O / J K L / M < >, t, b) to directions
(x, y, z, th); speedBindings q/z w/x e/c multiply (speed, turn) by 1.1/0.9;
any other key stops; Ctrl-C quits and a zero Twist is published on the way out;
"currently:\tspeed %s\tturn %s " after each speed key, the help again after
every 15th; ~speed 0.5, ~turn 1.0, ~repeat_rate 0, ~key_timeout 0 (wait forever).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import termios
import threading
import time

import pytest
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist
from workbench.teleop.keys import Velocity
from workbench.teleop.terminal import RawTerminal
from workbench.teleop.twist_keyboard import (
    TWIST_BANNER,
    TwistKeys,
    TwistRepeater,
    twist_teleop,
    wait_for_subscribers,
)

# The original's moveBindings, as published.
ORIGINAL_MOVES = {
    "i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
    "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
    "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
    "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
    "t": (0, 0, 1, 0), "b": (0, 0, -1, 0),
}  # fmt: skip
ORIGINAL_SPEEDS = {
    "q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1), "x": (0.9, 1), "e": (1, 1.1), "c": (1, 0.9),
}  # fmt: skip
STOP = Velocity()


def _as_tuple(v: Velocity | None) -> tuple[float, float, float, float] | None:
    return None if v is None else (v.x, v.y, v.z, v.yaw)


@pytest.mark.parametrize("key", sorted(ORIGINAL_MOVES))
def test_each_move_key_is_the_originals_direction_times_speed_and_turn(key):
    x, y, z, th = ORIGINAL_MOVES[key]
    command, lines = TwistKeys(speed=2.0, turn=3.0).press(key)
    assert _as_tuple(command) == (2.0 * x, 2.0 * y, 2.0 * z, 3.0 * th)
    assert lines == []


@pytest.mark.parametrize("key", sorted(ORIGINAL_SPEEDS))
def test_each_speed_key_scales_and_prints_the_currently_line(key):
    keys = TwistKeys()
    keys.press("u")  # moving forward and left
    command, lines = keys.press(key)
    speed, turn = 0.5 * ORIGINAL_SPEEDS[key][0], 1.0 * ORIGINAL_SPEEDS[key][1]
    assert lines == [f"currently:\tspeed {speed}\tturn {turn} "]
    assert _as_tuple(command) == (speed, 0.0, 0.0, turn)  # the new speeds apply at once


def test_the_currently_line_is_pythons_float_text():
    keys = TwistKeys()
    keys.press("q")
    assert keys.press("q")[1] == ["currently:\tspeed 0.6050000000000001\tturn 1.2100000000000002 "]


def test_every_fifteenth_speed_key_prints_the_help_again():
    keys = TwistKeys()
    printed = [keys.press("e" if n % 2 else "c")[1] for n in range(30)]
    with_help = [n for n, lines in enumerate(printed) if TWIST_BANNER in lines]
    assert with_help == [14, 29]
    assert printed[14][0].startswith("currently:") and printed[14][1] == TWIST_BANNER


def test_speed_limits_stop_the_speed_keys_and_say_so():
    keys = TwistKeys(speed=0.5, turn=1.0, speed_limit=0.6, turn_limit=5.0)
    assert keys.press("w")[1] == ["currently:\tspeed 0.55\tturn 1.0 "]
    assert keys.press("w")[1] == ["Linear speed limit reached!", "currently:\tspeed 0.6\tturn 1.0 "]


@pytest.mark.parametrize("key", ["k", "a", " ", "K", "1", "\x1b"])
def test_anything_else_stops(key):
    keys = TwistKeys()
    keys.press("i")
    assert keys.press(key) == (STOP, [])
    assert not keys.quit


def test_a_key_timeout_stops_a_moving_robot_once():
    keys = TwistKeys()
    keys.press("o")
    assert keys.press("") == (STOP, [])
    assert keys.press("") == (None, [])  # already stopped: nothing is sent


def test_ctrl_c_quits_without_a_command_of_its_own():
    keys = TwistKeys()
    keys.press("i")
    assert keys.press("\x03") == (None, [])
    assert keys.quit


def test_the_publisher_thread_sends_every_update_in_order_then_zero():
    sent: list[Velocity] = []
    repeater = TwistRepeater(sent.append)
    for x in (0.1, 0.2, 0.3):
        repeater.update(Velocity(x=x))
    repeater.stop()
    assert [v.x for v in sent] == [0.1, 0.2, 0.3, 0.0]


def test_with_a_repeat_rate_the_last_command_is_sent_again():
    sent: list[Velocity] = []
    repeater = TwistRepeater(sent.append, rate=100.0)
    repeater.update(Velocity(x=0.5))
    assert wait_for(lambda: len(sent) >= 5, timeout=10)
    repeater.stop()
    assert {v.x for v in sent[:-1]} == {0.5} and sent[-1] == Velocity()


def test_it_waits_for_a_subscriber_and_says_so_every_fifth_poll(capsys):
    class Publisher:
        topic = "/cmd_vel"
        polls = 0

        def get_num_connections(self) -> int:
            self.polls += 1
            return int(self.polls > 7)

    class NodeStub:
        is_shutdown = False

    wait_for_subscribers(Publisher(), NodeStub(), poll=0.001)
    assert capsys.readouterr().out == "Waiting for subscriber to connect to /cmd_vel\n"


# --- the loop in a pseudo-terminal, on an in-process bus -------------------------------


class _PtyRun:
    """``twist_teleop`` in a thread, reading a pseudo-terminal the test types into."""

    def __init__(self, params: dict[str, float]) -> None:
        self.master, slave = os.openpty()
        self.slave = slave
        self.stream = os.fdopen(slave, "r")
        self.bus = Bus()
        node = Node("teleop_twist_keyboard", bus=self.bus, disable_rosout=True)
        for name, value in params.items():
            node.set_param(f"~{name}", value)
        self.twists: list[Twist] = []
        watcher = Node("base", bus=self.bus, disable_rosout=True)
        watcher.create_subscription("/cmd_vel", Twist, self.twists.append, queue_size=0)
        self.result: dict[str, int] = {}
        terminal = RawTerminal(self.stream, raw=True)
        self.thread = threading.Thread(
            target=lambda: self.result.setdefault("rc", twist_teleop(node, terminal)),
            daemon=True,
        )
        self.thread.start()

    def type(self, keys: str) -> None:
        # type once the teleop reads in raw mode (no line editing, no signals), as a person would
        assert wait_for(
            lambda: not termios.tcgetattr(self.slave)[3] & (termios.ICANON | termios.ISIG)
        )
        os.write(self.master, keys.encode())

    def pairs(self) -> list[tuple[float, float, float]]:
        return [(t.linear.x, t.linear.y, t.angular.z) for t in list(self.twists)]

    def finish(self, twists: int) -> int:
        """Wait for the loop to end and for ``twists`` Twists to arrive; its exit status."""
        self.thread.join(timeout=20)
        assert not self.thread.is_alive()
        assert wait_for(lambda: len(self.twists) >= twists), self.pairs()
        self.bus.shutdown()
        self.stream.close()
        os.close(self.master)
        return self.result["rc"]


def test_keys_typed_in_a_terminal_become_twists_on_cmd_vel(capsys):
    run = _PtyRun({"speed": 0.2, "turn": 0.5})
    assert wait_for(lambda: run.pairs() == [(0.0, 0.0, 0.0)])  # the start-up update
    run.type("iJ")
    assert wait_for(lambda: len(run.twists) >= 3), run.pairs()
    run.type("k")
    assert wait_for(lambda: len(run.twists) >= 4), run.pairs()
    run.type("\x03")
    assert run.finish(twists=5) == 0
    assert run.pairs() == [
        (0.0, 0.0, 0.0),
        (0.2, 0.0, 0.0),
        (0.0, 0.2, 0.0),
        (0.0, 0.0, 0.0),  # k
        (0.0, 0.0, 0.0),  # on the way out
    ]
    out = capsys.readouterr().out
    assert out.startswith("\n" + TWIST_BANNER.lstrip("\n") + "\ncurrently:\tspeed 0.2\tturn 0.5 \n")


def test_key_timeout_stops_the_robot_when_no_key_comes():
    run = _PtyRun({"key_timeout": 0.2})
    run.type("l")
    assert wait_for(lambda: len(run.twists) >= 3), run.pairs()  # start, l, timeout stop
    run.type("\x03")
    assert run.finish(twists=4) == 0
    assert run.pairs()[:3] == [(0.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 0.0, 0.0)]


# --- the node as `workbench run` starts it ------------------------------------------------


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_workbench_run_teleop_twist_keyboard_py(teleop_process):
    import pexpect

    teleop = teleop_process("teleop_twist_keyboard", "teleop_twist_keyboard.py", "_speed:=0.4")
    child = teleop.child
    child.expect_exact("Reading from the keyboard  and Publishing to Twist!")
    child.expect_exact("CTRL-C to quit")
    child.expect_exact("currently:\tspeed 0.4\tturn 1.0 ")
    assert teleop.wait_twists(1) == [(0.0, 0.0)]
    teleop.type("i")
    assert teleop.wait_twists(2)[1] == (0.4, 0.0)
    teleop.type("q")
    child.expect_exact(f"currently:\tspeed {0.4 * 1.1}\tturn {1.0 * 1.1} ")
    assert teleop.wait_twists(3)[2] == (0.4 * 1.1, 0.0)
    teleop.type("\x03")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert teleop.wait_twists(4)[-1] == (0.0, 0.0)


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_sigterm_stops_it_cleanly_with_a_zero_twist(teleop_process):
    import pexpect

    teleop = teleop_process("teleop_twist_keyboard", "teleop_twist_keyboard")
    teleop.child.expect_exact("currently:\tspeed 0.5\tturn 1.0 ")
    teleop.type("u")
    assert teleop.wait_twists(2)[1] == (0.5, 1.0)
    time.sleep(0.2)
    teleop.child.kill(signal.SIGTERM)
    teleop.child.expect(pexpect.EOF)
    teleop.child.close()
    assert teleop.child.exitstatus == 128 + signal.SIGTERM
    assert "Traceback" not in teleop.child.before
    assert teleop.wait_twists(3)[-1] == (0.0, 0.0)


@pytest.mark.parametrize(
    "node",
    [
        ("teleop_twist_keyboard", "teleop_twist_keyboard.py"),
        ("turtlebot3_teleop", "turtlebot3_teleop_key"),
    ],
)
def test_without_a_terminal_it_is_one_clear_line(node):
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc")
    done = subprocess.run(
        [sys.executable, "-m", "workbench", "run", *node],
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )
    assert done.returncode == 1
    assert done.stdout == ""
    assert done.stderr.count("\n") == 1 and "needs a terminal" in done.stderr
