"""notebooks/09_setup_assistant.ipynb runs in short mode and shows the matrix."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_setup_assistant_notebook(run_notebook, tmp_path):
    notebook = run_notebook("09_setup_assistant.ipynb")
    out = tmp_path / "output" / "09_setup_assistant"
    html = [
        out["data"]["text/html"] for out in notebook.outputs if "text/html" in out.get("data", {})
    ]
    assert any("<td>Adjacent</td>" in table for table in html)
    text = notebook.text
    assert "[12/12] Wrote" in text
    assert "max tracking error" in text
    assert f"files go to {out}" in text
    for config, srdf in (("robot_arm_config", "robot_arm.srdf"), ("arm3_config", "arm3.srdf")):
        assert (out / config / srdf).is_file() and (out / config / "planning.yaml").is_file()
