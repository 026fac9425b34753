"""Helpers for the navigation tests that run the labs' launch files as processes: read the
simulator's true pose of a model, wait for move_base's results, find a launched node's log
(``process_helpers.launched`` starts the launch files)."""

from __future__ import annotations

import math
import re
import time
from pathlib import Path

from process_helpers import wait_for

from workbench.msgs import gazebo_msgs as gm


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
