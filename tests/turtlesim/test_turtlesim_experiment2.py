"""The manual's Experiment 2, typed as commands against a turtlesim in another process.

Each step is the manual's ``rosX`` command with ``workbench`` in front:
rosnode list/info, rostopic type/pub -1/echo, rosservice list/type/call /spawn,
rosparam set background_r + rosservice call /clear, rosbag record/info/play.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest
from PIL import Image
from process_helpers import free_port, wait_port

pytestmark = [pytest.mark.multiprocess, pytest.mark.slow]


def _start(args, env, cwd):
    return subprocess.Popen(
        [sys.executable, "-m", "workbench", *args],
        env=env,
        cwd=cwd,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )


def _stop(proc) -> str:
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return proc.stdout.read() if proc.stdout else ""


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    cwd = tmp_path_factory.mktemp("lab2")
    port = free_port()
    env = dict(os.environ, WORKBENCH_MASTER_URI=f"tcp/127.0.0.1:{port}")
    env.pop("WORKBENCH_DEBUG", None)
    core = _start(["core"], env, cwd)
    procs = [core]
    try:
        assert wait_port(port), "the core did not come up"  # else turtlesim runs in-process
        sim = _start(["turtlesim", "--png", str(cwd / "canvas.png")], env, cwd)
        procs.append(sim)

        def cli(*args, check=True):
            result = subprocess.run(
                [sys.executable, "-m", "workbench", *args],
                env=env,
                cwd=cwd,
                capture_output=True,
                text=True,
                timeout=60,
            )
            if check:
                assert result.returncode == 0, result.stderr
            return result

        deadline = time.monotonic() + 30
        while "/turtlesim" not in cli("node", "list").stdout:
            assert time.monotonic() < deadline, "turtlesim did not come up"
            time.sleep(0.5)
        yield cli, env, cwd
    finally:
        for proc in reversed(procs):
            _stop(proc)


def _pose(cli) -> dict[str, float]:
    text = cli("topic", "echo", "/turtle1/pose", "-n", "1").stdout
    return {
        k: float(v) for k, v in (line.split(": ") for line in text.splitlines() if ": " in line)
    }


def test_nodes_topics_and_types(lab):
    cli, _, _ = lab
    info = cli("node", "info", "/turtlesim").stdout
    assert "Node [/turtlesim]" in info
    assert " * /turtle1/pose [turtlesim/Pose]" in info
    assert " * /turtle1/cmd_vel [geometry_msgs/Twist]" in info
    assert cli("topic", "type", "/turtle1/cmd_vel").stdout.strip() == "geometry_msgs/Twist"
    assert "geometry_msgs/Vector3 linear" in cli("msg", "show", "geometry_msgs/Twist").stdout
    assert cli("service", "type", "/clear").stdout.strip() == "std_srvs/Empty"
    bad = cli("topic", "info", "/nope", check=False)
    assert bad.returncode == 1 and "unknown topic /nope" in bad.stderr


def test_pub_moves_the_turtle(lab):
    cli, _, _ = lab
    before = _pose(cli)
    args = ["topic", "pub", "-1", "/turtle1/cmd_vel", "geometry_msgs/Twist", "--"]
    cli(*args, "[2.0, 0.0, 0.0]", "[0.0, 0.0, 1.8]")
    time.sleep(1.5)  # the command holds for 1 s
    after = _pose(cli)
    assert after["theta"] != pytest.approx(before["theta"], abs=0.1)
    assert (after["x"], after["y"]) != pytest.approx((before["x"], before["y"]), abs=0.1)
    bad = cli(
        "topic",
        "pub",
        "-1",
        "/turtle1/cmd_vel",
        "geometry_msgs/Twist",
        "--",
        "[2.0, x, 0]",
        check=False,
    )
    assert bad.returncode == 1 and "field 'y' of geometry_msgs/Vector3" in bad.stderr


def test_spawn_kill_and_errors(lab):
    cli, _, _ = lab
    assert (
        cli("service", "call", "/spawn", "2", "2", "0.2", "turtle2").stdout.strip()
        == 'name: "turtle2"'
    )
    again = cli("service", "call", "/spawn", "2", "2", "0.2", "turtle2", check=False)
    assert again.returncode == 1 and "already exists" in again.stderr
    cli("service", "call", "/kill", "turtle2")
    gone = cli("service", "call", "/kill", "turtle2", check=False)
    assert gone.returncode == 1 and "no turtle named 'turtle2'" in gone.stderr
    wrong = cli("service", "call", "/spawn", "two", check=False)
    assert wrong.returncode == 1 and "float32" in wrong.stderr


def test_background_parameter_and_clear(lab):
    cli, _, cwd = lab
    cli("param", "set", "/turtlesim/background_r", "150")
    assert cli("param", "get", "/turtlesim/background_r").stdout.strip() == "150"
    cli("service", "call", "/clear")
    assert "success: True" in cli("service", "call", "/turtlesim/save_png").stdout
    with Image.open(cwd / "canvas.png") as image:
        assert image.convert("RGB").getpixel((2, 2)) == (150, 0x56, 0xFF)


def test_record_info_and_replay_the_same_poses(lab):
    cli, env, cwd = lab
    recorder = _start(["bag", "record", "-O", "run", "/turtle1/pose", "/turtle1/cmd_vel"], env, cwd)
    time.sleep(2.0)
    cli(
        "topic",
        "pub",
        "-1",
        "/turtle1/cmd_vel",
        "geometry_msgs/Twist",
        "--",
        "[1.0, 0, 0]",
        "[0, 0, 1.0]",
    )
    time.sleep(1.0)
    log = _stop(recorder)
    assert "Recording to 'run.bag'" in log and "Closing 'run.bag'" in log
    info = cli("bag", "info", "run.bag").stdout
    assert info.startswith("path:        run.bag\nversion:     2.0\n")
    assert "turtlesim/Pose      [863b248d5016ca62ea2e895ae5265cf9]" in info
    from workbench.bag import read_messages

    recorded = [
        (m.msg.x, m.msg.y, m.msg.theta) for m in read_messages(cwd / "run.bag", ["/turtle1/pose"])
    ]
    assert len(recorded) > 50
    # replay the poses while a second recorder listens on another topic name
    again = _start(["bag", "record", "-O", "replayed", "/replay/pose"], env, cwd)
    time.sleep(2.0)
    played = cli(
        "bag",
        "play",
        "run.bag",
        "/turtle1/pose:=/replay/pose",
        "--topics",
        "/turtle1/pose",
        "-r",
        "4",
    )
    time.sleep(1.0)
    _stop(again)
    assert "Opening run.bag" in played.stdout
    replayed = [(m.msg.x, m.msg.y, m.msg.theta) for m in read_messages(cwd / "replayed.bag")]
    assert replayed == recorded


def test_node_kill_last(lab):
    cli, _, _ = lab
    bad = cli("node", "kill", "/nobody", check=False)
    assert bad.returncode == 1 and "unknown node [/nobody]" in bad.stderr
    assert "killed" in cli("node", "kill", "/turtlesim").stdout
    deadline = time.monotonic() + 20
    while "/turtlesim" in cli("node", "list").stdout:
        assert time.monotonic() < deadline, "turtlesim is still registered"
        time.sleep(0.5)
