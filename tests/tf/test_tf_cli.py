"""``workbench tf echo | frames | static`` and the registered tf nodes."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time

import pytest

from workbench.tf import StampedTransform
from workbench.tf.frames import frames_dot, write_frames
from workbench.tf.nodes import parse_static_args

INPROC = {"WORKBENCH_MASTER_URI": "inproc"}


def test_echo_block_matches_tf_echo():
    """The manual's tf_echo world turtle1 block, digit for digit."""
    from workbench.cli.tf import format_echo
    from workbench.tf.transformations import quaternion_from_euler

    q = quaternion_from_euler(0, 0, math_radians(60.504))
    st = StampedTransform("world", "turtle1", 1639656810_475_000_000, (3.984, 2.351, 0.0), tuple(q))
    assert format_echo(st) == (
        "At time 1639656810.475\n"
        "- Translation: [3.984, 2.351, 0.000]\n"
        "- Rotation: in Quaternion [0.000, 0.000, 0.504, 0.864]\n"
        "            in RPY (radian) [0.000, -0.000, 1.056]\n"
        "            in RPY (degree) [0.000, -0.000, 60.504]"
    )


def math_radians(deg: float) -> float:
    import math

    return math.radians(deg)


def test_static_arguments():
    parent, child, xyz, q = parse_static_args(["1", "2", "3", "1.5707963", "0", "0", "a", "b"])
    assert (parent, child, xyz) == ("a", "b", (1.0, 2.0, 3.0))
    assert q[2] == pytest.approx(0.7071068, abs=1e-6)
    # tf's form with a trailing period in ms
    assert parse_static_args(["0", "0", "0", "0", "0", "0", "1", "a", "b", "100"])[3] == (
        0,
        0,
        0,
        1,
    )


def test_static_bad_arguments_is_one_line(run_cli):
    result = run_cli("tf", "static", "1", "2", "3", "0", "0", "0", "a", env=INPROC)
    assert result.returncode == 1
    assert (
        result.stderr.strip()
        .splitlines()[-1]
        .startswith("workbench tf: error: static_transform_publisher: bad arguments (7 arguments)")
    )


def test_echo_gives_up_with_a_hint(run_cli):
    result = run_cli("tf", "echo", "world", "turtle1", "--timeout", "0.3", env=INPROC)
    assert result.returncode == 1
    last = result.stderr.strip().splitlines()[-1]
    assert "no transform from 'world' to 'turtle1' within 0.3 s" in last
    assert '"world" passed to lookupTransform argument target_frame does not exist' in last


def test_frames_without_data_is_an_error(run_cli, tmp_path):
    result = run_cli("tf", "frames", "--duration", "0.1", "--gv", tmp_path / "f.gv", env=INPROC)
    assert result.returncode == 1
    assert "no tf data received in 0.1 s" in result.stderr


def test_frames_drawing(tmp_path, require_program):
    info = {
        "turtle1": {
            "parent": "world",
            "broadcaster": "/turtle1_tf_broadcaster",
            "rate": 62.5,
            "buffer_length": 4.9,
            "most_recent_transform": 10.0,
            "oldest_transform": 5.1,
            "static": False,
        },
        "carrot1": {"parent": "turtle1", "broadcaster": "/broadcaster_fixed", "static": True},
    }
    source = frames_dot(info, recorded_at=10.5)
    assert '"world" -> "turtle1"' in source and "Average rate: 62.500 Hz" in source
    assert '"turtle1" -> "carrot1"' in source and "Static transform" in source
    assert write_frames(source, tmp_path / "frames.gv").read_text() == source
    require_program("dot")
    svg = write_frames(source, tmp_path / "frames.svg").read_text()
    assert "<svg" in svg and "carrot1" in svg


def test_tf_nodes_are_registered():
    code = (
        "from workbench.bus.registry import registered_nodes as r;"
        "n = r(); print(n['tf2_ros/static_transform_publisher'], "
        "n['robot_state_publisher/robot_state_publisher'], "
        "n['joint_state_publisher_gui/joint_state_publisher_gui'])"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == [
        "workbench.tf.nodes:static_transform_publisher",
        "workbench.robot_state.nodes:robot_state_publisher",
        "workbench.robot_state.nodes:joint_state_publisher_gui",
    ]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


PUBLISHER = """
import time
from workbench.bus import Node
from workbench.tf import TransformBroadcaster
from workbench.tf.broadcaster import make_transform
node = Node("turtle1_tf_broadcaster")
br = TransformBroadcaster(node)
while True:
    br.send_transform(make_transform("world", "turtle1", (3.984, 2.351, 0.0),
                                     (0.0, 0.0, 0.504, 0.864), node.now()))
    time.sleep(0.02)
"""


@pytest.mark.multiprocess
def test_echo_and_frames_across_processes(run_cli, tmp_path):
    """A broadcaster process, a core, and the tools in a third process."""
    uri = f"tcp/127.0.0.1:{free_port()}"
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri)
    core = subprocess.Popen(
        [sys.executable, "-m", "workbench", "core"], env=env, stdout=subprocess.DEVNULL
    )
    publisher = None
    try:
        from workbench.bus.zconfig import port_open

        deadline = time.monotonic() + 30
        while not port_open("127.0.0.1", int(uri.rsplit(":", 1)[1])):
            assert time.monotonic() < deadline, "the core did not start"
            time.sleep(0.1)
        publisher = subprocess.Popen([sys.executable, "-c", PUBLISHER], env=env)
        result = run_cli(
            "tf", "echo", "world", "turtle1", "-n", "2", "--timeout", "20", env=env, timeout=60
        )
        assert result.returncode == 0, result.stderr
        assert result.stdout.count("- Translation: [3.984, 2.351, 0.000]") == 2
        assert "in RPY (degree) [0.000, -0.000, 60.5" in result.stdout
        gv = tmp_path / "frames.gv"
        result = run_cli(
            "tf", "frames", "--duration", "1.5", "--gv", gv, "--yaml", env=env, timeout=60
        )
        assert result.returncode == 0, result.stderr
        assert "turtle1: \n  parent: 'world'" in result.stdout
        assert '"world" -> "turtle1"' in gv.read_text()
    finally:
        for process in (publisher, core):
            if process is not None:
                process.send_signal(signal.SIGINT)
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()
