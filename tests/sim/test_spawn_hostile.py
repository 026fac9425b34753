"""Hostile spawn requests to a running ``workbench sim``: refused, and the server runs on.

A 100,000-character ``model_name`` crashed Drake (exit 139), a 1e308 m box did too
once stepped, a 1,500-link chain stalled the server for minutes. Each is sent over
the bus to a real server process: the reply is ``success: false`` with a status line,
and the process is alive, its clock advances and it still spawns a sound model.
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

BOX = """<robot name="box"><link name="body">
  <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="{size}"/></geometry></collision></link></robot>"""

SDF_BOX = """<sdf version="1.6"><model name="crate"><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
  </link><plugin name="p3d" filename="libgazebo_ros_p3d.so"><bodyName>body</bodyName></plugin>
  </model></sdf>"""


def _chain(links: int) -> str:
    inertial = (
        '<inertial><mass value="0.1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" '
        'ixz="0" iyz="0"/></inertial>'
    )
    body = "".join(f'<link name="l{i}">{inertial}</link>' for i in range(links))
    joints = "".join(
        f'<joint name="j{i}" type="continuous"><parent link="l{i - 1}"/><child link="l{i}"/>'
        '<origin xyz="0 0 0.1"/><axis xyz="0 1 0"/></joint>'
        for i in range(1, links)
    )
    return f'<robot name="chain">{body}{joints}</robot>'


LONG = "n" * 100_000
SHOWN = "n" * 37 + "..."
#: (what, service, request fields, status message)
HOSTILE = [
    (
        "100,000-character model_name",
        "spawn_urdf_model",
        {"model_name": LONG, "model_xml": BOX.format(size="0.2 0.2 0.2")},
        f"SpawnModel: Failure - model name '{SHOWN}' has 100,000 characters; at most 256",
    ),
    (
        "100,000-character model_name, SDF",
        "spawn_sdf_model",
        {"model_name": LONG, "model_xml": SDF_BOX},
        f"SpawnModel: Failure - model name '{SHOWN}' has 100,000 characters; at most 256",
    ),
    (
        "100,000-character robot_namespace",
        "spawn_sdf_model",
        {"model_name": "crate", "model_xml": SDF_BOX, "robot_namespace": LONG},
        f"SpawnModel: Failure - robot_namespace '{SHOWN}' has 100,000 characters; at most 256",
    ),
    (
        "1e308 m collision box",
        "spawn_urdf_model",
        {"model_name": "huge", "model_xml": BOX.format(size="1e308 1 1")},
        "SpawnModel: Failure - spawn request 'huge': link 'body' <collision> <geometry> <box>: "
        "size 1e+308 is more than 1e+06 m, the largest shape workbench takes (give the shape's "
        "real size in metres)",
    ),
    (
        "1,500-link chain",
        "spawn_urdf_model",
        {"model_name": "chain", "model_xml": _chain(1_500)},
        "SpawnModel: Failure - the model has 1,500 links; a spawned model has at most 500",
    ),
]


@contextlib.contextmanager
def _server(uri: str, cwd: Path):
    """``workbench sim empty --headless`` on ``uri`` until the block ends."""
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    log_path = cwd / "server.log"
    with open(log_path, "w") as log:
        process = subprocess.Popen(
            [sys.executable, "-m", "workbench", "sim", "empty", "--headless"],
            env=env,
            cwd=cwd,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
    try:
        deadline = time.monotonic() + 120
        while "services ready" not in log_path.read_text():
            assert process.poll() is None and time.monotonic() < deadline, log_path.read_text()
            time.sleep(0.1)
        yield process, log_path
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()


def _sim_time(node) -> float:
    client = node.create_client("/gazebo/get_world_properties", gm.GetWorldProperties)
    reply = client.call(gm.GetWorldProperties.Request(), timeout=30)
    assert reply.success
    return reply.sim_time


def _steps_on(node, process, log: Path) -> None:
    """The server is alive, answers, and its clock moves on."""
    start = _sim_time(node)
    deadline = time.monotonic() + 60
    while _sim_time(node) < start + 0.05:
        assert process.poll() is None, log.read_text()[-3000:]
        assert time.monotonic() < deadline, "the simulation stopped advancing"
        time.sleep(0.05)


def _spawn(node, service: str, fields: dict) -> gm.SpawnModel.Response:
    request = gm.SpawnModel.Request(**fields)
    request.initial_pose.position.z = 0.5
    request.initial_pose.orientation.w = 1.0
    client = node.create_client(f"/gazebo/{service}", gm.SpawnModel)
    return client.call(request, timeout=60)


@pytest.mark.multiprocess
@pytest.mark.slow
def test_hostile_spawn_requests_are_refused_and_the_server_runs_on(tmp_path, free_uri):
    with _server(free_uri, tmp_path) as (process, log):
        bus = Bus.connect(free_uri)
        try:
            node = Node("hostile_spawner", bus=bus, anonymous=True)
            for what, service, fields, status in HOSTILE:
                reply = _spawn(node, service, fields)
                assert (reply.success, reply.status_message) == (False, status), what
                _steps_on(node, process, log)
            names = node.create_client("/gazebo/get_world_properties", gm.GetWorldProperties)
            assert names.call(gm.GetWorldProperties.Request(), timeout=30).model_names == [
                "ground_plane"
            ]
            sound = _spawn(
                node,
                "spawn_urdf_model",
                {"model_name": "box", "model_xml": BOX.format(size="0.2 0.2 0.2")},
            )
            assert sound.success, sound.status_message
            _steps_on(node, process, log)
            # near the bound: accepted, built while the server runs, and it steps on
            near = _spawn(
                node, "spawn_urdf_model", {"model_name": "chain", "model_xml": _chain(300)}
            )
            assert near.success, near.status_message
            _steps_on(node, process, log)
        finally:
            bus.shutdown()
    assert "Segmentation fault" not in log.read_text() and "Traceback" not in log.read_text()
