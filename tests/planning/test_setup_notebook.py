"""notebooks/09_setup_assistant.ipynb runs in short mode and shows the matrix."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_setup_assistant_notebook(run_notebook):
    notebook = run_notebook("09_setup_assistant.ipynb")
    html = [
        out["data"]["text/html"] for out in notebook.outputs if "text/html" in out.get("data", {})
    ]
    assert any("<td>Adjacent</td>" in table for table in html)
    text = notebook.text
    assert "[12/12] Wrote" in text
    assert "max tracking error" in text
