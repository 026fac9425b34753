from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_plan_execute_notebook_runs(run_notebook):
    notebook = run_notebook("10_plan_execute.ipynb")
    text = notebook.text
    assert "collision re-check" in text and "passed" in text
    assert "max tracking error" in text
    assert "GoalInCollisionError" in text and "IKError" in text and "UnknownPlannerError" in text
