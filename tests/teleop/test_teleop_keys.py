"""turtle_teleop_key through a real pseudo-terminal.

turtle_teleop_key (turtlesim, Noetic): arrow keys publish linear.x = +-2.0 or
angular.z = +-2.0 (scale_linear/scale_angular 2.0), one Twist per key, 'q' quits,
banner "Reading from keyboard / --- / Use arrow keys to move the turtle. 'q' to quit."
(teleop_twist_keyboard is tested in test_twist_keyboard.py.)
"""

from __future__ import annotations

import os
import sys
import termios
import threading
import time

import pytest

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist
from workbench.teleop.keys import TurtleKeys
from workbench.teleop.run import turtle_teleop
from workbench.teleop.terminal import NotATerminalError, RawTerminal

UP, DOWN, RIGHT, LEFT = "\x1b[A", "\x1b[B", "\x1b[C", "\x1b[D"


def test_turtle_keys():
    keys = TurtleKeys()
    commands = keys.feed(UP + LEFT + DOWN + RIGHT + "x")
    assert [(c.x, c.yaw) for c in commands] == [(2.0, 0.0), (0.0, 2.0), (-2.0, 0.0), (0.0, -2.0)]
    assert keys.feed(UP[:2]) == [] and [c.x for c in keys.feed(UP[2:])] == [2.0]  # split escape
    keys.feed("q")
    assert keys.quit


def _run_in_pty(loop, keys_to_type: str, topic: str, raw: bool = False):
    master, slave = os.openpty()
    stream = os.fdopen(slave, "r")
    bus = Bus(threaded=False)
    node = Node("teleop", bus=bus, disable_rosout=True)
    got: list[Twist] = []
    Node("turtle", bus=bus, disable_rosout=True).create_subscription(
        topic, Twist, got.append, queue_size=0
    )
    result = {}
    thread = threading.Thread(
        target=lambda: result.setdefault("rc", loop(node, RawTerminal(stream, raw=raw), topic)),
        daemon=True,
    )
    thread.start()
    # type only once the teleop has put the terminal in its mode (as a person would)
    wanted = termios.ICANON | (termios.ISIG if raw else 0)
    deadline = time.monotonic() + 10
    while termios.tcgetattr(slave)[3] & wanted and time.monotonic() < deadline:
        time.sleep(0.01)
    os.write(master, keys_to_type.encode())
    thread.join(timeout=10)
    assert not thread.is_alive()
    while bus.spin_once(0.0):
        pass
    bus.shutdown()
    stream.close()
    os.close(master)
    return result["rc"], got


def test_turtle_teleop_in_a_pty(capsys):
    rc, got = _run_in_pty(turtle_teleop, UP + UP + LEFT + "q", "/turtle1/cmd_vel")
    assert rc == 0
    assert [(t.linear.x, t.angular.z) for t in got] == [(2.0, 0.0), (2.0, 0.0), (0.0, 2.0)]
    assert "Use arrow keys to move the turtle. 'q' to quit." in capsys.readouterr().out


def test_without_a_terminal(tmp_path):
    with (
        open(tmp_path / "f", "w+") as f,
        pytest.raises(NotATerminalError, match="needs a terminal"),
    ):
        RawTerminal(f)


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_cli_teleop_in_a_pseudo_terminal():
    import pexpect

    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc")
    child = pexpect.spawn(
        sys.executable, ["-m", "workbench", "teleop", "turtle"], env=env, timeout=30
    )
    child.expect("Use arrow keys to move the turtle. 'q' to quit.")
    child.send(UP + LEFT)
    child.send("q")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
