"""Helpers for the navigation tests that run the labs' launch files as processes: start a
launch file as a student does (no terminal on stdin), read the simulator's true pose of a
model, wait for move_base's results, and find a launched node's log."""

from __future__ import annotations

import contextlib
import math
import os
import re
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

from process_helpers import wait_for

from workbench.msgs import gazebo_msgs as gm


@contextlib.contextmanager
def launched(uri: str, log_path: Path, *argv: str) -> Iterator[subprocess.Popen]:
    """``workbench launch ARGV`` in its own session on the core at ``uri``; stopped with
    SIGINT (as Ctrl-C) at the end, then killed if it lingers."""
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    with open(log_path, "wb") as log:
        launch = subprocess.Popen(
            [sys.executable, "-m", "workbench", "launch", *argv],
            env=env,
            cwd=log_path.parent,
            stdout=log,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,  # keyboard teleops need a terminal: they say so and stop
            start_new_session=True,
        )
    try:
        yield launch
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        try:
            launch.wait(60)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            launch.wait()


def node_log(launch_log: Path, node: str, timeout: float = 60.0) -> Path:
    """The log file the launcher gave ``node`` (``process[node-N]: ... (log: PATH)``)."""
    pattern = re.compile(
        rf"process\[{re.escape(node)}-\d+\]: started with pid \[\d+\] \(log: (.+)\)"
    )
    found: list[str] = []

    def seen() -> bool:
        found[:] = pattern.findall(launch_log.read_text(errors="replace"))
        return bool(found)

    assert wait_for(seen, timeout), launch_log.read_text(errors="replace")
    return Path(found[0])


def wait_text(path: Path, pattern: str, timeout: float = 120.0) -> re.Match:
    """The first match of ``pattern`` in the file at ``path`` once it shows."""
    match: list[re.Match] = []

    def seen() -> bool:
        text = path.read_text(errors="replace") if path.exists() else ""
        hit = re.search(pattern, text)
        match[:] = [hit] if hit else []
        return bool(hit)

    assert wait_for(seen, timeout), f"{pattern!r} not in {path}"
    return match[0]


def true_pose(node, model: str) -> tuple[float, float, float]:
    """The simulator's pose of ``model`` (``/gazebo/get_model_state``): x, y in m, yaw in rad."""
    client = node.create_client("/gazebo/get_model_state", gm.GetModelState)
    state = client.call(gm.GetModelState.Request(model_name=model), timeout=30)
    assert state.success, state.status_message
    p, q = state.pose.position, state.pose.orientation
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    return p.x, p.y, yaw


class Results:
    """move_base's results (``/move_base/result``) as they come."""

    def __init__(self, node) -> None:
        self.results: list = []
        node.create_subscription(
            "/move_base/result", "move_base_msgs/MoveBaseActionResult", self.results.append, 0
        )

    def next(self, count: int, timeout: float = 300.0):
        """The result after the first ``count``; waits up to ``timeout`` s of wall time."""
        begin = time.monotonic()
        assert wait_for(lambda: len(self.results) > count, timeout), (
            f"no move_base result in {time.monotonic() - begin:.0f} s"
        )
        return self.results[count]
