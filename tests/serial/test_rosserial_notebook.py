"""notebooks/11_rosserial.ipynb runs end to end (short mode): programs A and B on virtual boards."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
def test_rosserial_notebook(run_notebook, tmp_path):
    notebook = run_notebook("11_rosserial.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "11_rosserial"
    assert f"files go to {out}" in text
    for line in (
        "Requesting topics...",
        "Note: publish buffer size is 200 bytes",
        "Setup publisher on chatter [std_msgs/String]",
        "Note: publish buffer size is 280 bytes",
        "Setup publisher on pushed [std_msgs/Bool]",
        "Sending tx stop request",
    ):
        assert line in text
    assert text.count('data: "hello world!"') == 2
    assert "motor (pin 13): HIGH" in text and "motor (pin 13): LOW" in text
    pushed = [line.split("data: ")[1] for line in text.splitlines() if " s  data: " in line]
    assert pushed == ["True", "False", "True", "False"]
    assert (out / "button_motor.png").is_file()
    images = [output for output in notebook.outputs if "image/png" in output.get("data", {})]
    assert len(images) == 1
