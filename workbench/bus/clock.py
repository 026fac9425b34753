"""Wall and simulated time.

A :class:`Clock` gives ``now()`` as a ROS ``Time``. With simulated time
(``/use_sim_time`` true) it reads the last ``/clock`` message instead of the
wall clock; sleeps and timers then wait for ``/clock`` to advance.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

from workbench.errors import BusError


class ShutdownInterrupt(BusError):
    """A sleep was interrupted because the node or bus shut down."""


class Clock:
    """The time source of a bus (wall time, or simulated time from ``/clock``)."""

    def __init__(self) -> None:
        self._sim = False
        self._sim_ns = 0
        self._cond = threading.Condition()
        self._listeners: list[Callable[[], None]] = []

    @property
    def is_simulated(self) -> bool:
        return self._sim

    def use_sim_time(self, enabled: bool = True) -> None:
        """Switch to simulated time (time stands at 0 until the first ``/clock``)."""
        with self._cond:
            self._sim = enabled
            self._cond.notify_all()

    def now_ns(self) -> int:
        """Current time in nanoseconds since the epoch (or since simulation start)."""
        return self._sim_ns if self._sim else time.time_ns()

    def now(self) -> Any:
        """Current time as a ``workbench.msgs.Time``."""
        from workbench.msgs import Time

        return Time(0, self.now_ns())

    def set_time(self, stamp: Any) -> None:
        """Advance simulated time (called for each ``/clock`` message).

        Args:
            stamp: A ``Time`` or integer nanoseconds.
        """
        ns = stamp if isinstance(stamp, int) else stamp.to_nsec()
        with self._cond:
            self._sim_ns = ns
            self._cond.notify_all()
        for listener in list(self._listeners):
            listener()

    def add_listener(self, listener: Callable[[], None]) -> None:
        """Call ``listener()`` whenever simulated time changes."""
        self._listeners.append(listener)

    def sleep_until_ns(
        self, deadline_ns: int, stop: threading.Event | None = None, back: bool = False
    ) -> None:
        """Sleep until the clock reaches ``deadline_ns``.

        Args:
            deadline_ns: When to wake (integer nanoseconds of this clock).
            stop: Ends the sleep with :class:`ShutdownInterrupt` when set.
            back: Also wake when simulated time jumps backwards (a simulation reset).

        Raises:
            ShutdownInterrupt: ``stop`` was set while sleeping.
        """
        start_ns = self._sim_ns
        while True:
            if stop is not None and stop.is_set():
                raise ShutdownInterrupt("sleep interrupted by shutdown")
            if self._sim:
                with self._cond:
                    if back and self._sim_ns < start_ns:
                        return
                    if self._sim_ns >= deadline_ns or not self._sim:
                        if self._sim:
                            return
                        continue
                    self._cond.wait(0.05)
                continue
            remaining = (deadline_ns - time.time_ns()) / 1e9
            if remaining <= 0:
                return
            if stop is not None:
                if stop.wait(min(remaining, 0.5)):
                    raise ShutdownInterrupt("sleep interrupted by shutdown")
            else:
                time.sleep(min(remaining, 0.5))

    def sleep(self, seconds: float, stop: threading.Event | None = None) -> None:
        """Sleep ``seconds`` of this clock's time (negative or zero returns at once)."""
        if seconds <= 0:
            if stop is not None and stop.is_set():
                raise ShutdownInterrupt("sleep interrupted by shutdown")
            return
        self.sleep_until_ns(self.now_ns() + int(seconds * 1e9), stop)
