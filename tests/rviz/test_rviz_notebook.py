from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_rviz_markers_notebook_runs(run_notebook, tmp_path):
    text = run_notebook("03_rviz_markers.ipynb").text
    out = tmp_path / "output" / "03_rviz_markers"
    assert f"files go to {out}" in text
    assert "showing [3]" in text  # the last of the cycling shapes: a cylinder
    assert "('points_and_lines', 0), ('points_and_lines', 1), ('points_and_lines', 2)]" in text
    assert (
        "my_marker MOUSE_DOWN (move_x)" in text
        and "my_marker POSE_UPDATE (move_x): now at 1.50" in text
    )
    assert "the server now has the marker at x = 1.50" in text
    assert f"snapshot: {out / 'rviz_markers.html'}" in text
    assert (out / "rviz_markers.html").stat().st_size > 0
