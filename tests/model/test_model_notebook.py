"""notebooks/05_urdf.ipynb runs from start to end."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_urdf_notebook_runs(run_notebook):
    notebook = run_notebook("05_urdf.ipynb")
    text = notebook.text
    assert "robot name is: myfirst" in text
    assert "root Link: base_link has 4 child(ren)" in text
    assert "snapshot: physics.html" in text
