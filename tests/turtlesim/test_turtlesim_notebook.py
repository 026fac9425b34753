"""notebooks/02_turtlesim.ipynb runs end to end (short mode) and replays the same path."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_turtlesim_notebook(run_notebook, tmp_path):
    notebook = run_notebook("02_turtlesim.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "02_turtlesim"
    assert f"files go to {out}" in text
    assert (out / "turtle.bag").is_file() and (out / "pose.png").is_file()
    assert 'name: "turtle2"' in text
    recorded = next(line for line in text.splitlines() if line.startswith("recorded end"))
    replayed = next(line for line in text.splitlines() if line.startswith("replayed end"))
    assert recorded.split("end")[1] == replayed.split("end")[1]
    images = [output for output in notebook.outputs if "image/png" in output.get("data", {})]
    assert len(images) >= 5
