"""notebooks/10_slam_live.ipynb: the TurtleBot3 wanders through the house while slam_gmapping
maps it; the saved map's walls are the house's walls."""

from __future__ import annotations

import re

import pytest


@pytest.mark.notebook
def test_slam_live_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("10_slam_live.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "10_slam_live"
    assert f"files go to {out}" in text
    assert "SpawnModel: Successfully spawned entity" in text
    assert "Traceback" not in text
    grown = [
        int(n) for n in re.findall(r"map at t = +[0-9.]+ s: \d+ x \d+ cells, (\d+) occupied", text)
    ]
    assert len(grown) >= 2 and grown[-1] > grown[0] > 0, text
    assert "saved: True" in text
    assert (out / "map.pgm").stat().st_size > 0 and (out / "map.yaml").is_file()
    assert "the same cells as the live map, thresholded: True" in text
    precision, recall = map(
        float, re.search(r"precision ([0-9.]+)  recall ([0-9.]+)", text).groups()
    )
    assert precision >= 0.9 and recall >= 0.5
    rms = float(re.search(r"trajectory error: RMS ([0-9.]+) m", text).group(1))
    assert rms < 0.1
    assert re.search(r"Map\s+\{'Topic': 'OK'\}", text), text
    assert (out / "slam_rviz.html").stat().st_size > 0
    assert "stopped" in text
