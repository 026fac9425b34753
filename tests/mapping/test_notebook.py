"""The offline SLAM notebook runs end to end in short mode."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_slam_offline_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("10_slam_offline.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "10_slam_offline"
    assert f"files go to {out}" in text
    assert f"saved mymap.pgm and mymap.yaml in {out}" in text
    assert (out / "mymap.pgm").is_file() and (out / "mymap.yaml").is_file()
    assert "loop closures" in text
    assert "reloaded equals the saved grid's trinary form: True" in text
    assert "dead reckoning" in text
