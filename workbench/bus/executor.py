"""The executor: runs queued callbacks on worker threads, or when stepped by hand.

Threaded (the default), a few worker threads take ready entities (a
subscription with queued messages, a due timer) off one queue; one entity
never runs on two threads at once. Stepped (``threaded=False``), nothing
runs until :meth:`Executor.spin_once` or :meth:`Executor.spin_until` is
called, which makes tests and notebooks deterministic.
"""

from __future__ import annotations

import sys
import threading
import time
import traceback
from collections import deque
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from workbench.bus.clock import Clock


class Runnable(Protocol):
    """What the executor runs: a subscription or a timer.

    Attributes:
        scheduled: Set by the executor while the entity waits in (or runs from) its
            queue, so that it is queued once however often it is scheduled.
    """

    scheduled: bool

    def run_pending(self, budget: int) -> int:
        """Run up to ``budget`` pending callbacks; returns how many ran."""
        ...

    def has_pending(self) -> bool:
        """Whether callbacks are still waiting."""
        ...


class SteppedTimer(Protocol):
    """A timer as the stepped executor polls it."""

    next_ns: int

    def poll(self) -> bool:
        """Mark the timer due if its time has come; returns whether it is due."""
        ...


class Executor:
    """Runs the callbacks of one bus.

    Args:
        threaded: Run callbacks on worker threads; ``False``: only inside ``spin_*``.
        workers: Worker threads when threaded (started on first use).
        clock: The bus clock (stepped timers are polled against it).
        timers: Returns the bus's timers (polled when stepped).
        stop: Set when the bus shuts down.
    """

    def __init__(
        self,
        threaded: bool,
        workers: int,
        clock: Clock,
        timers: Callable[[], Sequence[SteppedTimer]],
        stop: threading.Event,
    ) -> None:
        self.threaded = threaded
        self._clock = clock
        self._timers = timers
        self._stop = stop
        self._workers_wanted = max(1, workers)
        self._workers: list[threading.Thread] = []
        self._start_lock = threading.Lock()
        self._ready: deque[Runnable] = deque()
        self._cond = threading.Condition(threading.Lock())

    @property
    def workers(self) -> list[threading.Thread]:
        """The worker threads started so far."""
        return list(self._workers)

    def schedule(self, entity: Runnable) -> None:
        """Queue ``entity`` to run (once, however often it is scheduled before it runs)."""
        cond = self._cond
        with cond:
            if entity.scheduled:
                return
            entity.scheduled = True
            self._ready.append(entity)
            cond.notify()
        if self.threaded and len(self._workers) < self._workers_wanted:
            self._start_workers()

    def _start_workers(self) -> None:
        with self._start_lock:
            while len(self._workers) < self._workers_wanted and not self._stop.is_set():
                worker = threading.Thread(
                    target=self._work, name=f"workbench-executor-{len(self._workers)}", daemon=True
                )
                self._workers.append(worker)
                worker.start()

    def _work(self) -> None:
        cond, ready, stop = self._cond, self._ready, self._stop
        while True:
            with cond:
                while not ready and not stop.is_set():
                    cond.wait()
                if stop.is_set():
                    return
                entity = ready.popleft()
            self._run(entity, 8)

    def _run(self, entity: Runnable, budget: int) -> None:
        try:
            entity.run_pending(budget)
        except Exception as error:  # entities catch their callbacks' errors; this is a bug
            print(
                f"[ERROR] executor: running {entity!r} failed: {type(error).__name__}: {error}; "
                f"the executor keeps running\n{traceback.format_exc().rstrip()}",
                file=sys.stderr,
                flush=True,
            )
        finally:
            with self._cond:
                if entity.has_pending():
                    self._ready.append(entity)
                    self._cond.notify()
                else:
                    entity.scheduled = False

    def poll_timers(self) -> float | None:
        """Stepped mode: schedule due timers; returns seconds until the next one."""
        if self.threaded:
            return None
        soonest = None
        now = self._clock.now_ns()
        for timer in self._timers():
            if timer.poll():
                self.schedule(timer)  # type: ignore[arg-type]
            else:
                wait = (timer.next_ns - now) / 1e9
                soonest = wait if soonest is None else min(soonest, wait)
        return soonest

    def spin_once(self, timeout: float = 0.0) -> bool:
        """Run at most one callback, waiting up to ``timeout`` seconds for one.

        Returns:
            Whether a callback ran.
        """
        deadline = time.monotonic() + max(0.0, timeout)
        while True:
            next_timer = self.poll_timers()
            with self._cond:
                if not self._ready:
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        return False
                    wait = remaining if next_timer is None else min(remaining, max(next_timer, 0))
                    if self._clock.is_simulated and next_timer is not None:
                        wait = min(wait, 0.01)
                    self._cond.wait(wait)
                    if not self._ready:
                        continue
                entity = self._ready.popleft()
            self._run(entity, 1)
            return True

    def spin_until(self, predicate: Callable[[], bool], timeout: float | None = None) -> bool:
        """Run callbacks until ``predicate()`` is true (or ``timeout`` wall seconds pass).

        Returns:
            Whether the predicate became true.
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        while not predicate():
            if self._stop.is_set():
                return False
            remaining = 0.05 if deadline is None else deadline - time.monotonic()
            if remaining <= 0:
                return bool(predicate())
            self.spin_once(min(remaining, 0.05))
        return True

    def stop(self) -> None:
        """Wake and join the workers (the stop event must be set already)."""
        with self._cond:
            self._cond.notify_all()
        with self._start_lock:  # a worker being started now is started before it is joined
            workers = list(self._workers)
        current = threading.current_thread()
        for worker in workers:
            if worker is not current:
                worker.join(timeout=2.0)
