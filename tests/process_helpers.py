"""Helpers for tests that start real processes: free ports, a private core, child processes.

Importable by name from any test folder (``from process_helpers import Processes``). Every
process started here is stopped at the end (SIGINT, then SIGKILL).
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def wait_port(port: int, timeout: float = 20.0) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.2):
                return True
        except OSError:
            time.sleep(0.05)
    return False


def wait_for(predicate, timeout: float = 15.0, poll: float = 0.05) -> bool:
    """Poll ``predicate`` every ``poll`` s until it holds or ``timeout`` seconds pass; its
    last value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(poll)
    return bool(predicate())


class Processes:
    """Starts child processes with the test's core URI and stops them all at the end."""

    def __init__(self, uri: str, tmp: Path) -> None:
        self.uri = uri
        self.tmp = tmp
        self.children: list[tuple[subprocess.Popen, Path]] = []

    def env(self) -> dict[str, str]:
        env = dict(os.environ, WORKBENCH_MASTER_URI=self.uri, PYTHONUNBUFFERED="1")
        env.pop("WORKBENCH_DEBUG", None)
        return env

    def start(self, *argv: str, name: str = "proc") -> subprocess.Popen:
        log = self.tmp / f"{name}-{len(self.children)}.log"
        with open(log, "wb") as stream:
            popen = subprocess.Popen(
                [sys.executable, *argv],
                env=self.env(),
                stdout=stream,
                stderr=subprocess.STDOUT,
                cwd=self.tmp,
            )
        self.children.append((popen, log))
        return popen

    def output(self, popen: subprocess.Popen) -> str:
        for child, log in self.children:
            if child is popen:
                return log.read_text(errors="replace")
        return ""

    def wait_output(self, popen: subprocess.Popen, text: str, timeout: float = 30.0) -> str:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            out = self.output(popen)
            if text in out:
                return out
            if popen.poll() is not None:
                break
            time.sleep(0.05)
        out = self.output(popen)
        raise AssertionError(f"'{text}' not seen; output was:\n{out[-2000:]}")

    def stop_all(self) -> None:
        for popen, _ in self.children:
            if popen.poll() is None:
                popen.send_signal(signal.SIGINT)
        for popen, _ in self.children:
            _wait_or_kill(popen)


def joined_bus(uri: str, attempts: int = 6):
    """A ``Bus`` joined to the core at ``uri`` once it answers (slow to, on a loaded machine).

    Each attempt waits up to 5 s for the core's parameter server, as ``Bus.connect`` does.
    """
    from workbench.bus import Bus
    from workbench.bus.errors import CoreError

    for _ in range(attempts - 1):
        try:
            return Bus.connect(uri)
        except CoreError:
            continue
    return Bus.connect(uri)


@contextlib.contextmanager
def private_core(tmp_path: Path) -> Iterator[str]:
    """A ``workbench core`` on a free loopback port for the block; yields its URI."""
    port = free_port()
    uri = f"tcp/127.0.0.1:{port}"
    with open(tmp_path / "core.log", "wb") as log:
        core = subprocess.Popen(
            [sys.executable, "-m", "workbench", "core"],
            env=dict(os.environ, WORKBENCH_MASTER_URI=uri),
            stdout=log,
            stderr=subprocess.STDOUT,
        )
    try:
        assert wait_port(port), (tmp_path / "core.log").read_text()
        yield uri
    finally:
        core.send_signal(signal.SIGINT)
        _wait_or_kill(core)


@contextlib.contextmanager
def core_processes(tmp_path: Path) -> Iterator[Processes]:
    """A private core and a :class:`Processes` on it for the block; stops every process after."""
    with private_core(tmp_path) as uri:
        processes = Processes(uri, tmp_path)
        try:
            yield processes
        finally:
            processes.stop_all()


def _wait_or_kill(popen: subprocess.Popen, timeout: float = 10.0) -> None:
    try:
        popen.wait(timeout)
    except subprocess.TimeoutExpired:
        popen.kill()
        popen.wait()


@contextlib.contextmanager
def launched(uri: str, log_path: Path, *argv: str) -> Iterator[subprocess.Popen]:
    """``workbench launch ARGV`` in its own session on the core at ``uri``; stopped with
    SIGINT (as Ctrl-C) at the end, then killed if it lingers."""
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    with open(log_path, "wb") as log:
        launch = subprocess.Popen(
            [sys.executable, "-m", "workbench", "launch", *argv],
            env=env,
            cwd=log_path.parent,
            stdout=log,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,  # keyboard teleops need a terminal: they say so and stop
            start_new_session=True,
        )
    try:
        yield launch
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        try:
            launch.wait(60)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            launch.wait()
