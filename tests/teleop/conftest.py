"""Fixtures for the teleop tests: a private core, and nodes run in a pseudo-terminal.

``teleop_process`` starts ``python -m workbench run PKG EXE`` in a pseudo-terminal
(pexpect) on a private core, with a subscriber in the test process collecting the
Twists it publishes on ``/cmd_vel``. Every process started here is stopped at
teardown (SIGINT, then SIGKILL).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator

import pytest
from process_helpers import private_core
from teleop_helpers import TeleopProcess


@pytest.fixture
def core_uri(tmp_path) -> Iterator[str]:
    """A private ``workbench core`` on a free loopback port; its URI."""
    with private_core(tmp_path) as uri:
        yield uri


@pytest.fixture
def teleop_process(core_uri) -> Iterator[Callable[..., TeleopProcess]]:
    """``start(package, executable, *args, env=...)`` -> a :class:`TeleopProcess`."""
    import pexpect

    from workbench.bus import Bus, Node
    from workbench.msgs.geometry_msgs import Twist

    bus = Bus.connect(core_uri)
    started: list[TeleopProcess] = []

    def start(package: str, executable: str, *args: str, env: dict[str, str] | None = None):
        process = TeleopProcess(child=None)
        node = Node(f"watch_{len(started)}", bus=bus)
        node.create_subscription("/cmd_vel", Twist, process.twists.append, queue_size=0)
        full_env = dict(os.environ, WORKBENCH_MASTER_URI=core_uri, PYTHONUNBUFFERED="1")
        full_env.pop("WORKBENCH_DEBUG", None)
        full_env.update(env or {})
        process.child = pexpect.spawn(
            sys.executable,
            ["-m", "workbench", "run", package, executable, *args],
            env=full_env,
            timeout=30,
            encoding="utf-8",
        )
        started.append(process)
        return process

    try:
        yield start
    finally:
        for process in started:
            if process.child.isalive():
                process.child.kill(2)
                process.child.expect([pexpect.EOF, pexpect.TIMEOUT], timeout=5)
            process.child.close(force=True)
        bus.shutdown()
