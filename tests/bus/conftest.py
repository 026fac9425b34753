"""Fixtures for multi-process bus tests: a private core on a free port, and child processes.

Every process started here is stopped at teardown (SIGINT, then SIGKILL).
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest
from bus_process_helpers import REPO, free_port, wait_port  # noqa: F401


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
        stream = open(log, "wb")  # noqa: SIM115 - closed with the process
        popen = subprocess.Popen(
            [sys.executable, *argv],
            env=self.env(),
            stdout=stream,
            stderr=subprocess.STDOUT,
            cwd=self.tmp,
        )
        stream.close()
        self.children.append((popen, log))
        return popen

    def output(self, popen: subprocess.Popen) -> str:
        for child, log in self.children:
            if child is popen:
                return log.read_text(errors="replace")
        return ""

    def wait_output(self, popen: subprocess.Popen, text: str, timeout: float = 20.0) -> str:
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
                popen.send_signal(2)
        for popen, _ in self.children:
            try:
                popen.wait(5)
            except subprocess.TimeoutExpired:
                popen.kill()
                popen.wait()


@pytest.fixture
def core_uri(tmp_path):
    """A private ``workbench core`` on a free loopback port; its URI."""
    port = free_port()
    uri = f"tcp/127.0.0.1:{port}"
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri)
    log = open(tmp_path / "core.log", "wb")  # noqa: SIM115
    core = subprocess.Popen(
        [sys.executable, "-m", "workbench", "core"], env=env, stdout=log, stderr=subprocess.STDOUT
    )
    log.close()
    try:
        assert wait_port(port), (tmp_path / "core.log").read_text()
        yield uri
    finally:
        core.send_signal(2)
        try:
            core.wait(5)
        except subprocess.TimeoutExpired:
            core.kill()
            core.wait()


@pytest.fixture
def procs(core_uri, tmp_path):
    processes = Processes(core_uri, tmp_path)
    yield processes
    processes.stop_all()
