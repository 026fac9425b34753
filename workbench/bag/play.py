"""Replaying a bag with its original timing, like ``rosbag play``.

The player is independent of the bus: it calls ``publish(topic, typename,
msg)`` at the right moments, so the CLI wires it to a bus node and tests
can drive it with a fake clock.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from workbench.bag.errors import BagError
from workbench.bag.reader import read_messages, summarize

PublishFunction = Callable[[str, str, Any], None]
#: ``clock(bag_time_ns)`` publishes ``/clock``.
ClockFunction = Callable[[int], None]

CLOCK_PERIOD = 0.01  # s: rosbag play --clock publishes at 100 Hz by default


@dataclass
class PlayReport:
    """What a :func:`play` run did."""

    published: int
    loops: int
    bag_duration: float  # s
    wall_duration: float  # s


def play(
    path: str | os.PathLike[str],
    publish: PublishFunction,
    *,
    rate: float = 1.0,
    delay: float = 0.2,
    loop: bool = False,
    clock: ClockFunction | None = None,
    start: float = 0.0,
    topics: Iterable[str] | None = None,
    max_loops: int | None = None,
    should_stop: Callable[[], bool] = lambda: False,
    sleep: Callable[[float], None] = time.sleep,
    now: Callable[[], float] = time.monotonic,
    progress: Callable[[float, float], None] | None = None,
) -> PlayReport:
    """Publish a bag's messages with their recorded spacing divided by ``rate``.

    Args:
        path: The bag.
        publish: Called as ``publish(topic, typename, msg)`` for each message.
        rate: Speed factor (``-r``); 2.0 plays twice as fast.
        delay: Seconds to wait after advertising before the first message (``-d``,
            rosbag's default is 0.2 s).
        loop: Start again at the end (``-l``) until ``should_stop`` or ``max_loops``.
        clock: Publishes bag time on ``/clock`` (``--clock``) every 10 ms of wall time.
        start: Skip the first ``start`` seconds of the bag (``-s``).
        topics: Only these topics.
        max_loops: Stop after this many passes when looping (None: until stopped).
        should_stop: Polled between messages; True ends the playback.
        sleep, now: Wall-clock functions (replaceable in tests).
        progress: Called as ``progress(bag_time_s, elapsed_bag_s)`` after each message.

    Raises:
        BagError: bad rate, or an unreadable bag.
    """
    if not rate > 0:
        raise BagError(f"rate must be positive, got {rate}", hint="use -r 0.5 for half speed")
    if not (0 <= start <= 2**32 and 0 <= delay < math.inf):  # NaN fails every comparison
        raise BagError(f"start and delay must be finite seconds >= 0, got {start:g} and {delay:g}")
    summary = summarize(path)
    first_ns = summary.start_ns
    last_ns = summary.end_ns
    wanted = list(topics) if topics else None
    wall_start = now()
    published = 0
    loops = 0
    if first_ns is None or last_ns is None:
        return PlayReport(0, 0, 0.0, 0.0)
    if delay > 0:
        sleep(delay)
    while True:
        loops += 1
        t0_wall = now()
        # The bag's time starts at its first message as read, not at what the index says:
        # a damaged index (a chunk "starting" in 2106, or at 0) must not make it wait forever.
        begin_ns: int | None = None
        for message in read_messages(path, wanted):
            stamp = message.stamp_ns
            if begin_ns is None:
                begin_ns = stamp + round(start * 1e9)
            if stamp < begin_ns:
                continue
            target = t0_wall + (stamp - begin_ns) / 1e9 / rate
            while True:
                if should_stop():
                    return PlayReport(
                        published, loops, (last_ns - first_ns) / 1e9, now() - wall_start
                    )
                remaining = target - now()
                if clock is not None:
                    clock(begin_ns + round(max(0.0, now() - t0_wall) * rate * 1e9))
                if remaining <= 0:
                    break
                sleep(min(remaining, CLOCK_PERIOD) if clock is not None else remaining)
            publish(message.topic, message.typename, message.msg)
            published += 1
            if progress is not None:
                progress(stamp / 1e9, (stamp - begin_ns) / 1e9)
        if not loop or (max_loops is not None and loops >= max_loops) or should_stop():
            break
    return PlayReport(published, loops, (last_ns - first_ns) / 1e9, now() - wall_start)


def check_rate(rate: float) -> float:
    """Validate a ``-r`` value for the CLI."""
    if not rate > 0:
        raise BagError(f"rate must be positive, got {rate}")
    return rate
