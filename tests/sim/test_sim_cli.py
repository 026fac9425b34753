"""`workbench sim`, spawn_model and the Gazebo launch files, as the lab uses them.

Additional Experiment 1 with only paths and package names changed::

    workbench launch gazebo_worlds empty_world.launch
    workbench run gazebo spawn_model -file $PWD/object.urdf -urdf -z 1 -model my_object
    workbench launch gazebo_worlds table.launch
    workbench launch gazebo_worlds coffee_cup.launch
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from workbench.bus import Bus, Node
from workbench.msgs import gazebo_msgs as gm
from workbench.paths import urdf_dir
from workbench.viz.snapshot import snapshot_paths


def _env(uri: str) -> dict[str, str]:
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    return env


def _workbench(args: list[str], uri: str, cwd: Path, timeout: float = 120):
    return subprocess.run(
        [sys.executable, "-m", "workbench", *args],
        env=_env(uri),
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


@contextlib.contextmanager
def _background(args: list[str], uri: str, cwd: Path, ready: str):
    log_path = cwd / "server.log"
    with open(log_path, "w") as log:
        process = subprocess.Popen(
            [sys.executable, "-m", "workbench", *args],
            env=_env(uri),
            cwd=cwd,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
    try:
        deadline = time.monotonic() + 120
        while ready not in log_path.read_text() and process.poll() is None:
            assert time.monotonic() < deadline, log_path.read_text()
            time.sleep(0.1)
        assert ready in log_path.read_text(), log_path.read_text()
        yield process, log_path
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()


def _model_state(bus: Bus, name: str):
    client = Node("probe", bus=bus, anonymous=True).create_client(
        "/gazebo/get_model_state", gm.GetModelState
    )
    return client.call(gm.GetModelState.Request(model_name=name), timeout=30)


def _wait_sim_time(bus: Bus, seconds: float) -> None:
    client = Node("clock_probe", bus=bus, anonymous=True).create_client(
        "/gazebo/get_world_properties", gm.GetWorldProperties
    )
    start = client.call(gm.GetWorldProperties.Request(), timeout=30).sim_time
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if client.call(gm.GetWorldProperties.Request(), timeout=30).sim_time >= start + seconds:
            return
        time.sleep(0.1)
    raise AssertionError("the simulation did not advance")


@pytest.mark.multiprocess
@pytest.mark.slow
def test_additional_experiment_1_command_lines(tmp_path, free_uri):
    uri = free_uri
    (tmp_path / "object.urdf").write_text((urdf_dir() / "simple_box.urdf").read_text())
    with _background(
        ["launch", "gazebo_worlds", "empty_world.launch", "gui:=false"],
        uri,
        tmp_path,
        "services ready",
    ) as (_, log):
        spawned = _workbench(
            [
                "run",
                "gazebo",
                "spawn_model",
                "-file",
                f"{tmp_path}/object.urdf",
                "-urdf",
                "-z",
                "1",
                "-model",
                "my_object",
            ],
            uri,
            tmp_path,
        )
        assert spawned.returncode == 0, spawned.stdout + spawned.stderr
        assert "Spawn status: SpawnModel: Successfully spawned entity" in spawned.stdout
        again = _workbench(
            [
                "run",
                "gazebo",
                "spawn_model",
                "-file",
                "object.urdf",
                "-urdf",
                "-model",
                "my_object",
            ],
            uri,
            tmp_path,
        )
        assert again.returncode == 1
        assert "Spawn status: SpawnModel: Failure - model already exists." in again.stdout
        table = _workbench(["launch", "gazebo_worlds", "table.launch"], uri, tmp_path)
        assert "Successfully spawned entity" in table.stdout, table.stdout + table.stderr
        cup = _workbench(["launch", "gazebo_worlds", "coffee_cup.launch"], uri, tmp_path)
        assert "Successfully spawned entity" in cup.stdout, cup.stdout + cup.stderr
        bus = Bus.connect(uri)
        try:
            _wait_sim_time(bus, 2.0)
            box = _model_state(bus, "my_object")
            table_state = _model_state(bus, "table_model")
            cup_state = _model_state(bus, "coffee_cup")
        finally:
            bus.shutdown()
        # simple_box's link frame is the bottom of its box: it fell 1 m and rests at z = 0
        assert box.success and abs(box.pose.position.z) < 5e-3, box
        assert abs(box.twist.linear.z) < 0.05
        assert table_state.success and abs(table_state.pose.position.z) < 5e-3
        # the cup rests on the 0.55 m table top
        assert cup_state.pose.position.z == pytest.approx(0.55, abs=0.01)
        assert "simple_box" not in log.read_text() or "triangle inequality" in log.read_text()


@pytest.mark.multiprocess
@pytest.mark.parametrize("source", ["world", "urdf"])
def test_the_ros_talking_plugin_follows_topic_pub(tmp_path, source, free_uri):
    uri = free_uri
    server = ["sim", "velodyne", "--headless"] if source == "world" else ["sim", "--headless"]
    with _background(server, uri, tmp_path, "services ready") as (_, log):
        if source == "urdf":
            spawned = _workbench(
                [
                    "run",
                    "gazebo_ros",
                    "spawn_model",
                    "-database",
                    "velodyne",
                    "-urdf",
                    "-model",
                    "my_velodyne",
                ],
                uri,
                tmp_path,
            )
            assert spawned.returncode == 0, spawned.stdout + spawned.stderr
        bus = Bus.connect(uri)
        try:
            speeds: list[float] = []
            node = Node("watch", bus=bus)

            def joint_speed(message) -> None:
                # the top's spin relative to the base, which turns the other way a little
                if "my_velodyne::top" in message.name:
                    top = message.twist[message.name.index("my_velodyne::top")].angular.z
                    base = message.twist[message.name.index("my_velodyne::base")].angular.z
                    speeds.append(top - base)

            node.create_subscription("/gazebo/link_states", gm.LinkStates, joint_speed)
            published = _workbench(
                ["topic", "pub", "-1", "/my_velodyne/vel_cmd", "std_msgs/Float32", "data: 3.0"],
                uri,
                tmp_path,
            )
            assert published.returncode == 0, published.stderr
            deadline = time.monotonic() + 60
            while not (speeds and abs(speeds[-1] - 3.0) < 0.1) and time.monotonic() < deadline:
                time.sleep(0.1)
        finally:
            bus.shutdown()
        assert speeds and speeds[-1] == pytest.approx(3.0, abs=0.1), log.read_text()
        if source == "world":
            assert "plugin loaded: velodyne_control (velocity_controller.py" in log.read_text()


def test_sim_runs_a_world_until_a_time_and_writes_its_recording(tmp_path, run_cli):
    done = run_cli(
        "sim",
        "model_push",
        "--fast",
        "--until",
        "2",
        "--html",
        str(tmp_path / "push.html"),
        env={"WORKBENCH_MASTER_URI": "inproc"},
    )
    assert done.returncode == 0, done.stderr
    assert "stopped at t = 2.000 s" in done.stdout
    paths = snapshot_paths(tmp_path / "push.html")
    assert any("box" in path for path in paths), paths[:20]


@pytest.mark.parametrize(
    "args, message",
    [
        (["sim", "nowhere"], "unknown world 'nowhere'"),
        (["sim", "bad.world"], "not an XML world file"),
        (["sim", "--real-time-factor", "0"], "--real-time-factor must be above 0"),
    ],
)
def test_bad_worlds_and_options_are_one_line_errors(tmp_path, run_cli, args, message):
    (tmp_path / "bad.world").write_text("this is no XML")
    done = run_cli(*args, "--headless", cwd=tmp_path, env={"WORKBENCH_MASTER_URI": "inproc"})
    assert done.returncode != 0
    lines = [line for line in done.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and message in lines[0], done.stderr
    assert "Traceback" not in done.stderr


def test_a_missing_plugin_is_reported_and_the_sim_runs_on(tmp_path, run_cli):
    done = run_cli(
        "sim",
        "--headless",
        "--fast",
        "--until",
        "0.5",
        "--plugin",
        "box=missing_plugin.py",
        "--plugin",
        "not_here.py",
        cwd=tmp_path,
        env={"WORKBENCH_MASTER_URI": "inproc"},
    )
    assert done.returncode == 0, done.stderr
    assert "file 'missing_plugin.py' not found" in done.stderr + done.stdout
    assert "stopped at t = 0.500 s" in done.stdout
