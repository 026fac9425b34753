"""Running one command of benchmarks/corpus.py and sorting its outcome into a class.

Every command runs as a child process with a timeout, so a hang, an abort or a
traceback is recorded as such instead of stopping the run. The runner is a
plain function (:data:`Runner`): tests pass their own.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

#: The classes a file's command can end in, in the order the tables list them.
WORKS = "works"
WARNINGS = "works with warnings"
REFUSAL = "correct refusal"
#: workbench refuses on purpose what ROS accepts (a ``<machine>`` on another computer).
DESIGN = "refusal by design"
UNVERIFIED = "refusal, no oracle"
WRONG = "wrong"
TRACEBACK = "traceback"
HANG = "hang"
CRASH = "crash"
CLASSES = (WORKS, WARNINGS, REFUSAL, DESIGN, UNVERIFIED, WRONG, TRACEBACK, HANG, CRASH)
#: Classes that count as running.
RUNS = (WORKS, WARNINGS)

#: Exit status of workbench's top-level guard after an unexpected exception (a bug).
INTERNAL_ERROR_STATUS = 70
#: Exit statuses of a workbench command stopped by SIGINT or SIGTERM (128 + the signal).
#: This benchmark stops its children with SIGKILL only, so these come from outside.
STOPPED_STATUSES = {128 + signal.SIGINT: "SIGINT", 128 + signal.SIGTERM: "SIGTERM"}
#: Longest stdout/stderr kept per command, characters.
KEEP_CHARS = 200_000


@dataclass
class Outcome:
    """How a child process ended.

    Attributes:
        returncode: Exit status; negative for a signal (``-6`` abort); None after a timeout.
        stdout: Its standard output (the first :data:`KEEP_CHARS`).
        stderr: Its standard error (the first :data:`KEEP_CHARS`).
        timed_out: Killed at the timeout.
        seconds: Wall time, s.
    """

    returncode: int | None
    stdout: str
    stderr: str
    timed_out: bool = False
    seconds: float = 0.0

    @property
    def text(self) -> str:
        return self.stdout + "\n" + self.stderr


#: ``runner(argv, env, cwd, timeout) -> Outcome``.
Runner = Callable[[Sequence[str], Mapping[str, str], Path, float], Outcome]


def run_process(argv: Sequence[str], env: Mapping[str, str], cwd: Path, timeout: float) -> Outcome:
    """Run ``argv`` in ``cwd`` with ``env`` for at most ``timeout`` s.

    The child leads its own process group; at the timeout the whole group is
    killed, so a program that started helpers leaves none behind.
    """
    start = time.perf_counter()
    proc = subprocess.Popen(
        list(argv),
        cwd=cwd,
        env=dict(env),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        _kill_group(proc.pid)
        out, err = proc.communicate()
    except BaseException:
        _kill_group(proc.pid)
        proc.wait()
        raise
    _kill_group(proc.pid)  # helpers the child left running
    return Outcome(
        returncode=None if timed_out else proc.returncode,
        stdout=out.decode(errors="replace")[:KEEP_CHARS],
        stderr=err.decode(errors="replace")[:KEEP_CHARS],
        timed_out=timed_out,
        seconds=time.perf_counter() - start,
    )


def _kill_group(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pid, signal.SIGKILL)


@dataclass
class Verdict:
    """What ROS's own tool (the oracle) says about a file.

    Attributes:
        accepts: True or False; None when there is no oracle for it here.
        message: The tool's one-line reason when it refuses, or what it is.
    """

    accepts: bool | None
    message: str = ""


NO_ORACLE = Verdict(None, "no oracle")

_TRACEBACK = "Traceback (most recent call last)"
_WARNING = re.compile(r"\bwarn(ing)?\b|\[WARN\]", re.IGNORECASE)


def failure(outcome: Outcome) -> tuple[str, str] | None:
    """(class, message) when ``outcome`` is a hang, a crash or a traceback, else None."""
    if outcome.timed_out:
        return HANG, f"no answer within {outcome.seconds:.0f} s"
    if outcome.returncode is not None and outcome.returncode < 0:
        try:
            name = signal.Signals(-outcome.returncode).name
        except ValueError:
            name = f"signal {-outcome.returncode}"
        return CRASH, f"killed by {name}: {last_line(outcome.stderr) or last_line(outcome.stdout)}"
    if outcome.returncode in STOPPED_STATUSES:
        name = STOPPED_STATUSES[outcome.returncode]
        return CRASH, f"stopped by {name} from outside (exit {outcome.returncode})"
    if _TRACEBACK in outcome.text:
        return TRACEBACK, traceback_line(outcome.text)
    if outcome.returncode == INTERNAL_ERROR_STATUS and "internal error" in outcome.stderr:
        return TRACEBACK, error_line(outcome)
    return None


def traceback_line(text: str) -> str:
    """The exception line that ends the last traceback in ``text``."""
    tail = text[text.rindex(_TRACEBACK) :].splitlines()
    for line in tail[1:]:
        if line and not line.startswith((" ", "\t")):
            return shorten(line)
    return shorten(tail[-1])


def last_line(text: str) -> str:
    lines = [line for line in text.splitlines() if line.strip()]
    return shorten(lines[-1]) if lines else ""


_COMMAND_PREFIX = re.compile(r"^workbench [\w -]+: error: ")


def error_line(outcome: Outcome) -> str:
    """The line that says why a command failed: the first with 'error', else the last
    (without workbench's ``workbench CMD: error:`` prefix)."""
    for stream in (outcome.stderr, outcome.stdout):
        for line in stream.splitlines():
            if "error" in line.lower():
                return shorten(_COMMAND_PREFIX.sub("", line))
    return last_line(outcome.stderr) or last_line(outcome.stdout) or f"exit {outcome.returncode}"


def warning_lines(text: str, ignore: Sequence[str] = ()) -> list[str]:
    """Lines of ``text`` that warn, except those containing one of ``ignore``."""
    return [
        shorten(line)
        for line in text.splitlines()
        if _WARNING.search(line) and not any(part in line for part in ignore)
    ]


def shorten(text: str, length: int = 300) -> str:
    text = " ".join(text.split())
    return text if len(text) <= length else text[: length - 3] + "..."


def classify(
    ours_ok: bool,
    ours_message: str,
    verdict: Verdict,
    *,
    warnings: Sequence[str] = (),
    mismatch: str | None = None,
    tool: str = "ROS",
    by_design: bool = False,
) -> tuple[str, str]:
    """The class of a command that neither hung, crashed nor printed a traceback.

    Args:
        ours_ok: workbench accepted the file (exit status 0 and whatever else the kind needs).
        ours_message: workbench's one line when it refused.
        verdict: The oracle's answer.
        warnings: workbench's warnings when it accepted.
        mismatch: How workbench's result differs from the oracle's, when both accept.
        tool: The oracle's name for the messages.
        by_design: workbench's refusal is one it makes on purpose (documented), so it is
            not wrong where the oracle accepts the file.

    Returns:
        (class, one-line message).
    """
    if ours_ok:
        if verdict.accepts is False:
            return WRONG, shorten(f"accepted, {tool} refuses: {verdict.message}")
        if mismatch:
            return WRONG, shorten(f"differs from {tool}: {mismatch}")
        if warnings:
            return WARNINGS, warnings[0]
        return WORKS, ""
    if verdict.accepts is False:
        return REFUSAL, ours_message
    if by_design:
        return DESIGN, ours_message
    if verdict.accepts is None:
        return UNVERIFIED, ours_message
    return WRONG, shorten(f"refused, {tool} accepts: {ours_message}")
