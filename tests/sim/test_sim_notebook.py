from __future__ import annotations

import re

import pytest


@pytest.mark.notebook
def test_gazebo_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("06_gazebo.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "06_gazebo"
    assert f"files go to {out}" in text
    assert "my_object -> SpawnModel: Successfully spawned entity" in text
    assert "my_object -> SpawnModel: Failure - model already exists." in text
    assert re.search(r"coffee_cup\s+z = 0\.55\d m", text), text
    rate = float(re.search(r"precession ([0-9.]+) rad/s", text).group(1))
    assert rate == pytest.approx(2.641, rel=0.05)
    drove = float(re.search(r"drove ([0-9.]+) m", text).group(1))
    assert drove > 0.3
    assert "the plugin pushed the box 0.5" in text
    assert "DeleteModel: successfully deleted model" in text
    assert f"saved {out / 'simple_bot.sdf'}" in text
    assert (out / "simple_bot.urdf").is_file()
    assert f"recording: {out / 'gazebo_lab.html'}" in text
    assert (out / "gazebo_lab.html").stat().st_size > 0
