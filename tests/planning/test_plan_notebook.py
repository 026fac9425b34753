from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_plan_execute_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("10_plan_execute.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "10_plan_execute"
    assert f"files go to {out}" in text
    assert f"snapshot: {out / 'arm3_plan.html'}" in text
    assert f"snapshot: {out / 'robot_arm_plan.html'}" in text
    assert (out / "arm3_point.png").is_file()
    assert "collision re-check" in text and "passed" in text
    assert "max tracking error" in text
    assert "GoalInCollisionError" in text and "IKError" in text and "UnknownPlannerError" in text
