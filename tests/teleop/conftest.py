"""Fixtures for the teleop tests: a private core, and nodes run in a pseudo-terminal.

``teleop_process`` starts ``python -m workbench run PKG EXE`` in a pseudo-terminal
(pexpect) on a private core, with a subscriber in the test process collecting the
Twists it publishes on ``/cmd_vel``. Every process started here is stopped at
teardown (SIGINT, then SIGKILL).
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import pytest


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def _wait_port(port: int, timeout: float = 20.0) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.2):
                return True
        except OSError:
            time.sleep(0.05)
    return False


def wait_for(predicate: Callable[[], Any], timeout: float = 20.0) -> bool:
    """Poll ``predicate`` until it holds or ``timeout`` seconds pass; its last value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.02)
    return bool(predicate())


@pytest.fixture
def core_uri(tmp_path) -> Iterator[str]:
    """A private ``workbench core`` on a free loopback port; its URI."""
    port = _free_port()
    uri = f"tcp/127.0.0.1:{port}"
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri)
    with open(tmp_path / "core.log", "wb") as log:
        core = subprocess.Popen(
            [sys.executable, "-m", "workbench", "core"], env=env, stdout=log, stderr=log
        )
    try:
        assert _wait_port(port), (tmp_path / "core.log").read_text()
        yield uri
    finally:
        core.send_signal(2)
        try:
            core.wait(5)
        except subprocess.TimeoutExpired:
            core.kill()
            core.wait()


@dataclass
class TeleopProcess:
    """A node in a pseudo-terminal (``child``, pexpect) and the Twists seen on /cmd_vel."""

    child: Any
    twists: list[Any] = field(default_factory=list)

    def type(self, keys: str) -> None:
        """Type ``keys`` once the node reads in raw mode (Ctrl-C is then a key, not SIGINT).

        Between reads the node restores the terminal, as the originals do; a Ctrl-C typed
        then is a signal (a clean stop too, but with exit status 130).
        """
        import termios

        def raw() -> bool:
            return not termios.tcgetattr(self.child.child_fd)[3] & (termios.ICANON | termios.ISIG)

        assert wait_for(raw), "the node never read the keyboard in raw mode"
        self.child.send(keys)

    def pairs(self) -> list[tuple[float, float]]:
        """(linear.x, angular.z) of every Twist so far."""
        return [(t.linear.x, t.angular.z) for t in list(self.twists)]

    def wait_twists(self, count: int) -> list[tuple[float, float]]:
        assert wait_for(lambda: len(self.twists) >= count), self.pairs()
        return self.pairs()


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
