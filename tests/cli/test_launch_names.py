"""The lab table's launch commands work as printed, from any folder (issue 14, item 11)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize(
    "words",
    [
        ["learning_tf", "start_demo.launch"],
        ["start_demo.launch"],
        ["start_demo_carrot.launch"],
        ["gazebo_worlds", "table.launch"],
        ["turtlebot3_teleop", "turtlebot3_teleop_key.launch"],
    ],
)
def test_shipped_launch_files_by_package_or_name(tmp_path, run_cli, words):
    done = run_cli(
        "launch", "--dry-run", *words, cwd=tmp_path, env={"WORKBENCH_MASTER_URI": "inproc"}
    )
    assert done.returncode == 0, done.stderr
    assert "node /" in done.stdout
