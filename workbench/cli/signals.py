"""Stopping long-running commands cleanly on SIGINT and SIGTERM.

A non-interactive shell starts a background job (``workbench core &``) with
SIGINT ignored, and Python keeps an ignored signal ignored, so Ctrl-C's
signal would never reach it. Like roscpp, the command line therefore installs
its handlers explicitly when it starts: SIGINT raises :class:`KeyboardInterrupt`
and SIGTERM raises :class:`Terminated` (a ``KeyboardInterrupt`` too), so every
``except KeyboardInterrupt`` / ``finally`` that finalises a command on Ctrl-C
(closing a bag, writing an ``--html`` snapshot, stopping a launcher's
children) runs on SIGTERM as well. Only the first signal interrupts; later ones
are ignored, so finalising is not cut short (SIGKILL still ends the process at
once), and reported when they come a second or more after the first; a node
started by ``workbench launch`` (``WORKBENCH_LAUNCHED=1``) gets Ctrl-C twice, from
the terminal and from its launcher, as under roslaunch, and reports neither.

A command stopped by a signal exits with ``128 + signal number``: 130 for
SIGINT and 143 for SIGTERM, as a shell reports a process killed by them.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time
from collections.abc import Iterator
from types import FrameType

#: A repeated stop signal this soon after the first is the same stop, and not reported.
REPEAT_QUIET_SECONDS = 1.0
#: The signals that stop a long-running command.
STOP_SIGNALS: tuple[signal.Signals, ...] = (signal.SIGINT, signal.SIGTERM)


class Terminated(KeyboardInterrupt):
    """Raised in the main thread when the process receives SIGTERM."""


class StopRequest:
    """The first stop signal a command received, if any."""

    def __init__(self) -> None:
        self.signum: int | None = None
        self.first_at = 0.0

    @property
    def exit_status(self) -> int | None:
        """``128 + signal number`` once a stop signal arrived, else None."""
        return None if self.signum is None else 128 + self.signum

    def note(self, signum: int) -> bool:
        """Record ``signum``; True when it is the first stop signal."""
        if self.signum is not None:
            launched = os.environ.get("WORKBENCH_LAUNCHED") == "1"
            if not launched and time.monotonic() - self.first_at >= REPEAT_QUIET_SECONDS:
                os.write(2, b"workbench: already stopping, please wait (SIGKILL forces it)\n")
            return False
        self.signum = signum
        self.first_at = time.monotonic()
        return True


#: The stop request of the running command (fresh for each :func:`stop_on_signals`).
_current = StopRequest()


def _raise_on_signal(signum: int, frame: FrameType | None) -> None:
    if _current.note(signum):
        raise Terminated() if signum == signal.SIGTERM else KeyboardInterrupt()


@contextlib.contextmanager
def _handlers(handler) -> Iterator[None]:
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread may install handlers; its caller's stay in force
        return
    previous = {signum: signal.getsignal(signum) for signum in STOP_SIGNALS}
    for signum in STOP_SIGNALS:
        signal.signal(signum, handler)
    try:
        yield
    finally:
        for signum, old in previous.items():
            signal.signal(signum, old)


@contextlib.contextmanager
def stop_on_signals() -> Iterator[StopRequest]:
    """While inside, SIGINT raises KeyboardInterrupt and SIGTERM raises :class:`Terminated`.

    The previous handlers come back on leaving, so an in-process caller (a test) keeps its own.

    Yields:
        The :class:`StopRequest` that records which signal arrived.
    """
    global _current
    _current = StopRequest()
    with _handlers(_raise_on_signal):
        yield _current


@contextlib.contextmanager
def stop_event_on_signals(event: threading.Event) -> Iterator[None]:
    """While inside, SIGINT and SIGTERM set ``event`` instead of raising.

    For loops that poll a flag, so a signal cannot interrupt a call half-way (a Drake
    call or the print that tells the user how to stop).
    """

    def handler(signum: int, frame: FrameType | None) -> None:
        _current.note(signum)
        event.set()

    with _handlers(handler):
        yield


def ignore_stop_signals() -> None:
    """Ignore SIGINT and SIGTERM from now on: the process is on its way out."""
    if threading.current_thread() is threading.main_thread():
        for signum in STOP_SIGNALS:
            signal.signal(signum, signal.SIG_IGN)


def silence_stdout() -> None:
    """Point stdout at /dev/null after its reader went away (``| head``).

    Later writes, and Python's flush at exit, then go nowhere instead of raising
    BrokenPipeError again; the command finishes quietly, as shell tools do.
    """
    import sys

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass
