"""notebooks/05_urdf.ipynb runs from start to end."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_urdf_notebook_runs(run_notebook):
    notebook = run_notebook("05_urdf.ipynb")
    text = "".join(
        output.get("text", "")
        for cell in notebook.cells
        if cell.cell_type == "code"
        for output in cell.get("outputs", [])
    )
    assert "robot name is: myfirst" in text
    assert "root Link: base_link has 4 child(ren)" in text
    assert "snapshot: physics.html" in text
