"""notebooks/05_urdf.ipynb runs from start to end."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_urdf_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("05_urdf.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "05_urdf"
    assert f"files go to {out}" in text
    assert "robot name is: myfirst" in text
    assert "root Link: base_link has 4 child(ren)" in text
    assert f"snapshot: {out / 'physics.html'}" in text
    for name in ("myfirst", "multipleshapes", "origins", "materials", "visual", "flexible"):
        assert (out / f"{name}.html").is_file()
    assert (out / "broken.urdf").is_file()
