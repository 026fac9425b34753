"""Fixtures for multi-process bus tests: a private core on a free port, and child processes.

Every process started here is stopped at teardown (SIGINT, then SIGKILL).
"""

from __future__ import annotations

import pytest
from process_helpers import REPO, Processes, free_port, private_core, wait_port  # noqa: F401


@pytest.fixture
def core_uri(tmp_path):
    """A private ``workbench core`` on a free loopback port; its URI."""
    with private_core(tmp_path) as uri:
        yield uri


@pytest.fixture
def procs(core_uri, tmp_path):
    processes = Processes(core_uri, tmp_path)
    yield processes
    processes.stop_all()
