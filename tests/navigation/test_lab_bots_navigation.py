"""Experiment 7.2's bot_model.launch runs in full (manual ~line 5530, paths changed only):
slam_gmapping gives map -> odom and /map, move_base reads the four YAML files, and custom_bot
reaches a goal pressed in the launched RViz's "2D Nav Goal" (through Meshcat's control panel,
as a browser sends it) and one a student types on /move_base_simple/goal with
``workbench topic pub``. Where it ends is read from the simulator (/gazebo/get_model_state),
not from the robot's own estimate."""

from __future__ import annotations

import math
import os
import subprocess
import sys
import time

import pytest
from meshcat_client import MeshcatPanel
from nav_processes import Results, node_log, true_pose, wait_text
from process_helpers import launched, private_core, wait_for

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import PoseStamped
from workbench.tf import Buffer, TransformListener

#: move_base's xy_goal_tolerance (0.1 m) plus what slam_gmapping's map may be off the world
#: and the robot rolls after its last command.
REACHED = 0.2


@pytest.mark.multiprocess
@pytest.mark.slow
def test_custom_bot_reaches_a_goal_from_rviz_and_one_from_the_command_line(tmp_path):
    log_path = tmp_path / "launch.log"
    with private_core(tmp_path) as uri, launched(uri, log_path, "lab_bots", "bot_model.launch"):
        log = lambda: log_path.read_text(errors="replace")[-3000:]  # noqa: E731
        rviz_url = wait_text(node_log(log_path, "rviz"), r"\[INFO\] rviz: (http://\S+)").group(1)
        with Bus.connect(uri) as bus:
            node = Node("student", bus=bus)
            buffer = Buffer()
            TransformListener(buffer, node)
            goals: list[PoseStamped] = []
            node.create_subscription("/move_base_simple/goal", PoseStamped, goals.append)
            results = Results(node)
            # slam_gmapping has a map and move_base its costmaps
            assert wait_for(lambda: buffer.can_transform("map", "base_link", 0), 180), log()
            wait_text(log_path, r"Sim period is set to 0\.10")

            # 1. RViz's "2D Nav Goal": sliders to (-1.5, 1.0) facing +y, then the button
            with MeshcatPanel(rviz_url) as panel:
                for name, value in (
                    ("Pose x (m)", -1.5),
                    ("Pose y (m)", 1.0),
                    ("Pose yaw (deg)", 90),
                ):
                    panel.set_slider(name, value)
                # RViz reads the sliders, then the clicks, once a frame: let a frame pass
                # so the press is not read with the sliders' old values
                time.sleep(1.0)
                panel.press("2D Nav Goal")
                assert wait_for(lambda: goals, 30), log()
            assert goals[0].header.frame_id == "map"  # RViz's fixed frame once gmapping runs
            p = goals[0].pose.position
            assert (p.x, p.y) == (-1.5, 1.0)
            first = results.next(0)
            assert first.status.status == 3, first.status.text  # SUCCEEDED
            x, y, _ = true_pose(node, "custom_bot")
            assert math.hypot(x + 1.5, y - 1.0) < REACHED, (x, y)

            # 2. the command line, as a student types it
            typed = subprocess.run(
                [
                    sys.executable, "-m", "workbench", "topic", "pub", "-1",
                    "/move_base_simple/goal", "geometry_msgs/PoseStamped",
                    "{header: {frame_id: map}, pose: {position: {x: 1.0, y: -1.0}, "
                    "orientation: {w: 1.0}}}",
                ],
                env={**os.environ, "WORKBENCH_MASTER_URI": uri},
                capture_output=True, text=True, timeout=120,
            )  # fmt: skip
            assert typed.returncode == 0, typed.stderr
            second = results.next(1)
            assert second.status.status == 3, second.status.text
            x, y, _ = true_pose(node, "custom_bot")
            assert math.hypot(x - 1.0, y + 1.0) < REACHED, (x, y)
    assert "Traceback" not in log_path.read_text(errors="replace")
