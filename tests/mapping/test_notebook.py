"""The offline SLAM notebook runs end to end in short mode."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_slam_offline_notebook_runs(run_notebook):
    notebook = run_notebook("10_slam_offline.ipynb")
    text = notebook.text
    assert "loop closures" in text
    assert "reloaded equals the saved grid's trinary form: True" in text
    assert "dead reckoning" in text
