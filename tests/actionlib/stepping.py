"""A stepped bus on simulated time for the action tests (no wall clock involved)."""

from __future__ import annotations

from workbench.bus import Bus


class SteppedBus:
    """``Bus(threaded=False)`` on simulated time that tests advance by hand."""

    def __init__(self, start: float = 100.0) -> None:
        self.bus = Bus(threaded=False)
        self.bus.clock.use_sim_time(True)
        self.t = start
        self.bus.clock.set_time(int(start * 1e9))

    def drain(self) -> None:
        """Run every pending callback."""
        while self.bus.spin_once(0.0):
            pass

    def advance(self, seconds: float, step: float = 0.01) -> None:
        """Move time forward ``seconds`` in ``step``s, running callbacks and timers on the way."""
        end = self.t + seconds
        while self.t < end - 1e-9:
            self.t = min(self.t + step, end)
            self.bus.clock.set_time(round(self.t * 1e9))
            self.drain()
