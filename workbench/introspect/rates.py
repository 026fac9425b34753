"""``rostopic hz`` and ``rostopic bw`` statistics and their printed lines."""

from __future__ import annotations

import math
from collections import deque


class HzMeter:
    """Receive times in, rate statistics out (``rostopic hz``).

    Args:
        window: Keep at most this many intervals (rostopic keeps 50000 by default).
    """

    def __init__(self, window: int = 50000) -> None:
        self.window = window
        self._last: float | None = None
        self._intervals: deque[float] = deque(maxlen=window)
        self.count = 0

    def add(self, t: float) -> None:
        """Record one message received at ``t`` seconds."""
        if self._last is not None:
            self._intervals.append(t - self._last)
        self._last = t
        self.count += 1

    @property
    def rate(self) -> float | None:
        """Average rate in Hz over the window (None before two messages)."""
        if not self._intervals:
            return None
        mean = sum(self._intervals) / len(self._intervals)
        return 1.0 / mean if mean > 0 else math.inf

    def report(self) -> str | None:
        """rostopic hz's two lines, or None before two messages."""
        if not self._intervals:
            return None
        n = len(self._intervals)
        mean = sum(self._intervals) / n
        std = math.sqrt(sum((x - mean) ** 2 for x in self._intervals) / n)
        rate = 1.0 / mean if mean > 0 else 0.0
        return (
            f"average rate: {rate:.3f}\n"
            f"\tmin: {min(self._intervals):.3f}s max: {max(self._intervals):.3f}s "
            f"std dev: {std:.5f}s window: {n + 1}"
        )


def _bytes(value: float) -> str:
    if value < 1000:
        return f"{value:.2f}B"
    if value < 1_000_000:
        return f"{value / 1000:.2f}KB"
    return f"{value / 1_000_000:.2f}MB"


class BwMeter:
    """Message sizes and receive times in, bandwidth out (``rostopic bw``).

    Args:
        window: The last N messages (rostopic's default is 100).
    """

    def __init__(self, window: int = 100) -> None:
        self._samples: deque[tuple[float, int]] = deque(maxlen=window)

    def add(self, t: float, size: int) -> None:
        """Record one message of ``size`` bytes received at ``t`` seconds."""
        self._samples.append((t, size))

    @property
    def bytes_per_second(self) -> float | None:
        if len(self._samples) < 2:
            return None
        span = self._samples[-1][0] - self._samples[0][0]
        total = sum(size for _, size in self._samples)
        return total / span if span > 0 else None

    def report(self) -> str | None:
        """rostopic bw's two lines, or None before two messages."""
        bps = self.bytes_per_second
        if bps is None:
            return None
        sizes = [size for _, size in self._samples]
        mean = sum(sizes) / len(sizes)
        return (
            f"average: {_bytes(bps)}/s\n"
            f"\tmean: {_bytes(mean)} min: {_bytes(min(sizes))} max: {_bytes(max(sizes))} "
            f"window: {len(sizes)}"
        )
