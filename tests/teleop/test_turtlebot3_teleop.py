"""turtlebot3_teleop_key against the Noetic node: steps, limits, smoothing, texts, exit.

The original (ROBOTIS turtlebot3_teleop/nodes/turtlebot3_teleop_key, noetic):
w/x step the target linear velocity by 0.01, a/d the angular by 0.1, clamped
to burger 0.22/2.84 or waffle(_pi) 0.26/1.82; space or s stops at once; each
loop (key timeout 0.1 s) publishes the output velocity moved towards the
target by at most half a step; "currently:\tlinear vel %s\t angular vel %s "
after w/x/a/d/s, the help again after every 20th w/x/a/d; a zero Twist on exit.
"""

from __future__ import annotations

import signal
import sys

import pytest
from teleop_helpers import TeleopProcess

from workbench.teleop.turtlebot3 import (
    TB3_BANNER,
    Turtlebot3Keys,
    model_name,
    ramp,
    velocity_limits,
)

MANUAL_SCREEN = [  # Experiment 10's screenshot of the node, line by line
    "Control Your TurtleBot3!",
    "Moving around:",
    "        w",
    "   a    s    d",
    "        x",
    "w/x : increase/decrease linear velocity (Burger : ~ 0.22, Waffle and Waffle Pi : ~ 0.26)",
    "a/d : increase/decrease angular velocity (Burger : ~ 2.84, Waffle and Waffle Pi : ~ 1.82)",
    "space key, s : force stop",
    "CTRL-C to quit",
]


def test_the_help_is_the_screen_of_the_manual():
    lines = TB3_BANNER.splitlines()
    assert [line for line in lines if line in MANUAL_SCREEN] == MANUAL_SCREEN
    assert lines[0] == "" and lines[2] == "---------------------------"


@pytest.mark.parametrize(
    ("model", "limits"),
    [
        ("burger", (0.22, 2.84)),
        ("waffle", (0.26, 1.82)),
        ("waffle_pi", (0.26, 1.82)),
        ("tank", (0.22, 2.84)),
    ],
)
def test_velocity_limits_per_model(model, limits):
    assert velocity_limits(model) == limits
    keys = Turtlebot3Keys(model)
    for _ in range(40):
        keys.press("w")
    for _ in range(40):
        keys.press("d")
    assert (keys.target_linear, keys.target_angular) == (limits[0], -limits[1])
    for _ in range(80):
        keys.press("x")
    assert keys.target_linear == -limits[0]


def test_steps_print_the_currently_line_as_python_prints_floats():
    keys = Turtlebot3Keys()
    printed = [keys.press("w") for _ in range(6)]
    assert printed[0] == ["currently:\tlinear vel 0.01\t angular vel 0.0 "]
    assert printed[5] == ["currently:\tlinear vel 0.060000000000000005\t angular vel 0.0 "]
    assert keys.press("a") == ["currently:\tlinear vel 0.060000000000000005\t angular vel 0.1 "]


def test_stop_keys_zero_target_and_output_at_once():
    for stop in ("s", " "):
        keys = Turtlebot3Keys()
        for _ in range(5):
            keys.press("w")
            keys.press("a")
            keys.command()
        assert keys.linear > 0 and keys.angular > 0
        assert keys.press(stop) == ["currently:\tlinear vel 0.0\t angular vel 0.0 "]
        command = keys.command()
        assert (command.x, command.yaw) == (0.0, 0.0)


def test_other_keys_change_nothing_and_ctrl_c_quits():
    keys = Turtlebot3Keys()
    keys.press("w")
    assert keys.press("q") == [] and keys.press("") == [] and keys.target_linear == 0.01
    assert not keys.quit
    keys.press("\x03")
    assert keys.quit


def test_the_output_ramps_half_a_step_per_message():
    keys = Turtlebot3Keys()
    for _ in range(3):
        keys.press("w")  # target 0.03 m/s
    keys.press("d")  # target -0.1 rad/s
    outputs = [(round(c.x, 6), round(c.yaw, 6)) for c in (keys.command() for _ in range(8))]
    assert outputs == [
        (0.005, -0.05),
        (0.01, -0.1),
        (0.015, -0.1),
        (0.02, -0.1),
        (0.025, -0.1),
        (0.03, -0.1),
        (0.03, -0.1),
        (0.03, -0.1),
    ]
    assert ramp(0.0, 1.0, 0.3) == 0.3 and ramp(1.0, 0.0, 0.3) == 0.7 and ramp(0.5, 0.5, 0.1) == 0.5


def test_every_twentieth_step_reprints_the_help():
    keys = Turtlebot3Keys()
    printed = [keys.press("wxad"[n % 4]) for n in range(41)]
    assert [n for n, lines in enumerate(printed) if TB3_BANNER in lines] == [19, 39]
    assert printed[19][0].startswith("currently:") and printed[19][1] == TB3_BANNER
    assert TB3_BANNER not in keys.press("s")  # stops do not count


def test_the_model_comes_from_the_parameter_then_the_environment(monkeypatch):
    monkeypatch.delenv("TURTLEBOT3_MODEL", raising=False)
    assert model_name(None) == "burger"
    monkeypatch.setenv("TURTLEBOT3_MODEL", "waffle_pi")
    assert model_name(None) == "waffle_pi"
    assert model_name("waffle") == "waffle"


# --- the node as `workbench run` starts it ------------------------------------------------


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_workbench_run_turtlebot3_teleop_key_with_waffle_limits(teleop_process):
    import pexpect

    teleop = teleop_process(
        "turtlebot3_teleop", "turtlebot3_teleop_key", env={"TURTLEBOT3_MODEL": "waffle"}
    )
    child = teleop.child
    for line in MANUAL_SCREEN:
        child.expect_exact(line)
    teleop.wait_twists(2)  # it publishes every 0.1 s while no key comes
    assert set(teleop.pairs()) == {(0.0, 0.0)}
    teleop.type("w" * 30)  # 0.30 m/s asked, waffle's 0.26 m/s granted
    child.expect_exact("currently:\tlinear vel 0.26\t angular vel 0.0 ")
    teleop.type("a")
    child.expect_exact("currently:\tlinear vel 0.26\t angular vel 0.1 ")
    teleop.wait_twists(len(teleop.twists) + 60)  # the ramp reaches the target
    linear, angular = teleop.pairs()[-1]
    assert linear == pytest.approx(0.26) and angular == pytest.approx(0.1)
    steps = [b[0] - a[0] for a, b in zip(teleop.pairs(), teleop.pairs()[1:], strict=False)]
    assert max(steps) == pytest.approx(0.005)  # never more than half a step per message
    teleop.type(" ")
    child.expect_exact("currently:\tlinear vel 0.0\t angular vel 0.0 ")
    teleop.type("\x03")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert teleop.pairs()[-1] == (0.0, 0.0)


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_sigterm_stops_it_cleanly_with_a_zero_twist(teleop_process):
    import pexpect

    teleop = teleop_process("turtlebot3_teleop", "turtlebot3_teleop_key")
    teleop.child.expect_exact("CTRL-C to quit")
    teleop.type("ww")
    teleop.child.expect_exact("currently:\tlinear vel 0.02\t angular vel 0.0 ")
    teleop.wait_twists(len(teleop.twists) + 5)
    assert teleop.pairs()[-1][0] == pytest.approx(0.02)
    count = len(teleop.twists)
    teleop.child.kill(signal.SIGTERM)
    teleop.child.expect(pexpect.EOF)
    teleop.child.close()
    assert teleop.child.exitstatus == 128 + signal.SIGTERM
    assert "Traceback" not in teleop.child.before
    teleop.wait_twists(count + 1)
    assert teleop.pairs()[-1] == (0.0, 0.0)


@pytest.mark.skipif(sys.platform == "win32", reason="pseudo-terminals are POSIX")
def test_the_labs_roslaunch_line_works_with_model_from_the_command_line(core_uri):
    """``roslaunch turtlebot3_teleop turtlebot3_teleop_key.launch``, here with model:=waffle_pi."""
    import os

    import pexpect

    env = dict(os.environ, WORKBENCH_MASTER_URI=core_uri, TURTLEBOT3_MODEL="burger")
    child = pexpect.spawn(
        sys.executable,
        ["-m", "workbench", "launch", "turtlebot3_teleop", "turtlebot3_teleop_key.launch"]
        + ["model:=waffle_pi"],
        env=env,
        timeout=30,
        encoding="utf-8",
    )
    teleop = TeleopProcess(child=child)
    try:
        for line in MANUAL_SCREEN:
            child.expect_exact(line)
        teleop.type("w" * 27)
        child.expect_exact("currently:\tlinear vel 0.26\t angular vel 0.0 ")  # not burger's 0.22
        teleop.type("\x03")
        child.expect_exact("process has finished cleanly")
        child.sendintr()
        child.expect(pexpect.EOF)
    finally:
        child.close(force=True)
