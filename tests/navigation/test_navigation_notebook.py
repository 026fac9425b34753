"""notebooks/10_navigation.ipynb: on the saved house map AMCL finds the TurtleBot3 from a rough
2D Pose Estimate and move_base takes it to goals sent with SimpleActionClient; the paths are
plotted on the map."""

from __future__ import annotations

import re

import pytest


@pytest.mark.notebook
def test_navigation_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("10_navigation.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "10_navigation"
    assert f"files go to {out}" in text
    assert "Traceback" not in text
    assert "SpawnModel: Successfully spawned entity" in text
    assert "nodes in the launch file: robot_state_publisher, map_server, amcl, move_base" in text
    # AMCL starts at the origin, about 3 m from the robot; after the estimate it is near
    start = float(re.search(r"AMCL at its initial pose: .* off by ([0-9.]+) m", text).group(1))
    guess = float(re.search(r"after the 2D Pose Estimate: .* off by ([0-9.]+) m", text).group(1))
    end = float(re.search(r"at the end: .* off by ([0-9.]+) m", text).group(1))
    assert start > 2.5 and 0.2 < guess < 0.6 and end < 0.1, (start, guess, end)
    reached = re.findall(r"goal \(.*\): state 3 \(SUCCEEDED\) after .* the robot ([0-9.]+) m", text)
    # DWA's xy_goal_tolerance (0.05 m) plus what AMCL may be off (its target: 0.1 m)
    assert len(reached) == 3 and all(float(d) < 0.2 for d in reached), text
    median = float(re.search(r"over the last three quarters median ([0-9.]+) m", text).group(1))
    assert median < 0.1
    assert (out / "navigation_paths.png").stat().st_size > 0
    assert re.search(r"Global costmap\s+\{'Topic': 'OK'\}", text), text
    assert (out / "navigation_rviz.html").stat().st_size > 0
    assert "stopped" in text
