"""notebooks/04_tf.ipynb runs from start to end."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_tf_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("04_tf.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "04_tf"
    assert f"files go to {out}" in text
    assert "- Translation: [" in text and "in RPY (degree)" in text
    assert "turtle1: \n  parent: 'world'" in text
    assert "radius 2.00" in text
    assert "base_laser: (1.00, 0.20, 0.00) -----> base_link: (1.10, 0.20, 0.20)" in text
    assert "Frame wrist_roll_link exists with parent elbow_pitch_link." in text
    assert "links not placed: {}" in text and "frames not placed: {}" in text
    assert f"plot: {out / 'turtles.png'}" in text and (out / "turtles.png").is_file()
    assert f"snapshot: {out / 'robot_tf.html'}" in text and (out / "robot_tf.html").is_file()
