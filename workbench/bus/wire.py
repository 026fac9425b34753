"""What goes on the wire between processes: size bounds, and what happens when Zenoh fails.

Messages and service calls between processes are bounded in size
(:data:`MAX_MESSAGE_BYTES`); a larger one is refused where it is sent, with
the topic or service and the bound, instead of reaching Zenoh.

Zenoh runs in Rust threads. When one of them panics (an internal error of
Zenoh), the session is poisoned: every later call raises
``pyo3_runtime.PanicException`` (a ``BaseException``) or silently does
nothing, and a node would linger, alive but deaf. Instead the process says
so in one line and exits with :data:`EXIT_TRANSPORT_FAILED`, so whoever
started it (a shell, ``workbench launch`` with ``respawn``) can start it
again on a fresh session.
"""

from __future__ import annotations

import functools
import os
import sys
import threading
import time
from collections.abc import Callable
from typing import Any, NoReturn, TypeVar

from workbench.errors import WorkbenchError
from workbench.limits import MiB, human_bytes

#: Largest serialized message or service request/response sent to another process, bytes.
MAX_MESSAGE_BYTES = 64 * MiB

#: Exit status of a process whose transport failed (``EX_TEMPFAIL``: try again).
EXIT_TRANSPORT_FAILED = 75

F = TypeVar("F", bound=Callable[..., Any])


def check_size(data: bytes, what: str, error: type[WorkbenchError]) -> bytes:
    """``data`` if it fits on the wire.

    Args:
        data: Serialized bytes.
        what: What they are ("a message on /scan", "a request to /spawn").
        error: The error class to raise (``MessageError``, ``ServiceError``).

    Raises:
        error: Larger than :data:`MAX_MESSAGE_BYTES`.
    """
    if len(data) > MAX_MESSAGE_BYTES:
        raise error(
            f"{what} is {human_bytes(len(data))}, more than the "
            f"{human_bytes(MAX_MESSAGE_BYTES)} a message between processes may be",
            hint="send less at once (split it), or keep large data in files",
        )
    return data


def is_transport_panic(error: BaseException) -> bool:
    """Whether ``error`` is a panic of Zenoh's Rust code (``pyo3_runtime.PanicException``)."""
    kind = type(error)
    return kind.__name__ == "PanicException" and kind.__module__.startswith("pyo3")


def transport_failed(where: str, error: BaseException) -> NoReturn:
    """Say that the transport failed in ``where``, then end the process at once.

    The session cannot be closed cleanly any more (that would panic again), so
    nothing else runs: the line, then :func:`os._exit`.
    """
    reason = " ".join(str(error).split())[:200] or type(error).__name__
    program = os.path.basename(sys.argv[0] or "python")
    print(
        f"[FATAL] [{time.time():.6f}]: {program} (pid {os.getpid()}): the Zenoh transport "
        f"failed in {where} ({reason}); exiting with status {EXIT_TRANSPORT_FAILED} so that "
        "this node can be started again on a fresh connection",
        file=sys.stderr,
        flush=True,
    )
    try:
        sys.stdout.flush()
    finally:
        os._exit(EXIT_TRANSPORT_FAILED)


def guarded(where: str) -> Callable[[F], F]:
    """Decorate a function that calls Zenoh: a panic inside ends the process cleanly."""

    def wrap(function: F) -> F:
        @functools.wraps(function)
        def run(*args: Any, **kwargs: Any) -> Any:
            try:
                return function(*args, **kwargs)
            except BaseException as error:
                if is_transport_panic(error):
                    transport_failed(where, error)
                raise

        return run  # type: ignore[return-value]

    return wrap


_hooks_installed = False
_hooks_lock = threading.Lock()


def install_panic_hooks() -> None:
    """Route a Zenoh panic that no one caught (in any thread) to :func:`transport_failed`."""
    global _hooks_installed
    with _hooks_lock:
        if _hooks_installed:
            return
        _hooks_installed = True
    previous_thread_hook = threading.excepthook
    previous_hook = sys.excepthook

    def thread_hook(args: Any) -> None:
        if args.exc_value is not None and is_transport_panic(args.exc_value):
            name = args.thread.name if args.thread is not None else "a thread"
            transport_failed(f"thread {name}", args.exc_value)
        previous_thread_hook(args)

    def main_hook(kind: Any, value: BaseException, traceback: Any) -> None:
        if is_transport_panic(value):
            transport_failed("the main thread", value)
        previous_hook(kind, value, traceback)

    threading.excepthook = thread_hook
    sys.excepthook = main_hook
