"""notebooks/01_pubsub_services.ipynb runs (short mode) and shows the lab's results."""

from __future__ import annotations

import pytest


@pytest.mark.notebook
@pytest.mark.multiprocess
def test_pubsub_notebook(run_notebook):
    notebook = run_notebook("01_pubsub_services.ipynb")
    text = notebook.text
    assert "1 + 3 = 4" in text
    assert "heard from the talker process: ['hello world'" in text
    assert "after spinning (queue_size=3 keeps the newest): [2, 3, 4]" in text
    assert "exit codes: [0, 0]" in text
