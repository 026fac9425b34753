"""Run a program as a child process and measure its own CPU time and peak memory.

Benchmarks run as ``python benchmarks/NAME.py``, so this module is importable
as ``child_process`` from each of them.
"""

from __future__ import annotations

import os
import subprocess
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path


@dataclass
class Measured:
    """A finished (or stopped) child process: exit code, CPU s, wall s, peak MB, timed out."""

    returncode: int
    cpu_s: float
    wall_s: float
    peak_mb: float
    timed_out: bool


def run_measured(argv: Sequence[str], cwd: Path, timeout: float) -> Measured:
    """Run ``argv`` in ``cwd`` for ``timeout`` s at most, its output to ``stdout.txt`` and
    ``stderr.txt`` there.

    The child's own rusage (``os.wait4``) gives its CPU time and peak memory.
    A child over time is killed; so is the child when this process is
    interrupted (the interrupt then propagates).
    """
    start = time.perf_counter()
    with open(cwd / "stdout.txt", "wb") as out, open(cwd / "stderr.txt", "wb") as err:
        proc = subprocess.Popen(
            list(argv), cwd=cwd, stdout=out, stderr=err, stdin=subprocess.DEVNULL
        )
    timed_out = False
    try:
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() - start > timeout:
                proc.kill()
                pid, status, usage = os.wait4(proc.pid, 0)
                timed_out = True
                break
            time.sleep(0.02)
    except BaseException:
        proc.kill()
        os.wait4(proc.pid, 0)
        proc.returncode = -9
        raise
    proc.returncode = os.waitstatus_to_exitcode(status)
    return Measured(
        returncode=proc.returncode,
        cpu_s=usage.ru_utime + usage.ru_stime,
        wall_s=time.perf_counter() - start,
        peak_mb=usage.ru_maxrss / 1024.0,
        timed_out=timed_out,
    )
