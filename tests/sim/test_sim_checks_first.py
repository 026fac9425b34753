"""A ``workbench sim`` that fails its own checks never disturbs the simulator already running.

A second server registering as ``/gazebo`` would shut the first one down (a new node of the
same name replaces the old, as with a ROS master); a typo in the world name must be refused
before the second one joins the graph.
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


def _env(uri: str) -> dict[str, str]:
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    return env


def _sim_time(bus: Bus) -> float:
    client = Node("probe", bus=bus, anonymous=True).create_client(
        "/gazebo/get_world_properties", gm.GetWorldProperties
    )
    reply = client.call(gm.GetWorldProperties.Request(), timeout=30)
    assert reply.success
    return float(reply.sim_time)


@pytest.mark.multiprocess
@pytest.mark.parametrize(
    "args, message",
    [
        (["emtpy"], "unknown world 'emtpy'"),
        (["empty", "--max-step-size", "0"], "--max-step-size must be in [0.0001, 0.1] s"),
        (["missing.world"], "missing.world"),
    ],
)
def test_a_second_sim_that_fails_its_checks_leaves_the_first_running(
    tmp_path: Path, free_uri, args, message
):
    log_path = tmp_path / "first.log"
    with open(log_path, "w") as log:
        first = subprocess.Popen(
            [sys.executable, "-m", "workbench", "sim", "--headless"],
            env=_env(free_uri),
            cwd=tmp_path,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
    try:
        deadline = time.monotonic() + 120
        while "services ready" not in log_path.read_text() and first.poll() is None:
            assert time.monotonic() < deadline, log_path.read_text()
            time.sleep(0.1)
        assert "services ready" in log_path.read_text(), log_path.read_text()
        second = subprocess.run(
            [sys.executable, "-m", "workbench", "sim", "--headless", *args],
            env=_env(free_uri),
            cwd=tmp_path,
            capture_output=True,
            text=True,
            timeout=120,
        )
        assert second.returncode == 1
        lines = second.stderr.strip().splitlines()
        assert len(lines) == 1 and message in lines[0], second.stderr
        bus = Bus.connect(free_uri)
        try:
            before = _sim_time(bus)
            deadline = time.monotonic() + 60
            while _sim_time(bus) < before + 0.1:
                assert time.monotonic() < deadline, "the first simulator stopped stepping"
                time.sleep(0.05)
        finally:
            bus.shutdown()
        assert first.poll() is None
        assert "new node registered with same name" not in log_path.read_text()
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(first.pid, signal.SIGINT)
        try:
            first.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(first.pid, signal.SIGKILL)
            first.wait()
