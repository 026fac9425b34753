"""The scans amcl holds while it is busy: its tf message filter, and what happens under load.

``amcl_node.cpp`` reads ``scan`` through a ``message_filters::Subscriber`` (queue 100) into a
``tf2_ros::MessageFilter`` (target ``~odom_frame_id``, queue 100): a scan waits there until
``odom -> scan frame`` is known at its stamp; when the queue is full the oldest is dropped;
a scan whose stamp lies further behind the newest transform than the tf cache keeps can
never be transformed and is dropped at once (tf2's ``OutTheBack``). That is how ROS's amcl
catches up after falling behind: the stale part of a backlog costs nothing.

:class:`ScanQueue` does the same, and goes one step further: amcl takes the newest scan
whose transform is known and drops the older ones it had not started on, as a subscriber
with ``queue_size`` 1 would. The filter needs only the latest scan with the odometry at its
stamp (it updates after ``update_min_d`` / ``update_min_a`` of motion, whatever came in
between), so after a stall amcl is current again with the next scan instead of working
through seconds of old ones while ``map -> odom`` lags behind.
"""

from __future__ import annotations

import collections
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

#: The message filter's queue (``laser_scan_filter_`` in amcl_node.cpp).
QUEUE = 100

#: What the filter knows about a scan's transform.
READY = "ready"  # known at the scan's stamp
WAIT = "wait"  # not yet: the scan is newer than the latest transform
NEVER = "never"  # the stamp fell out of the tf cache (tf2's OutTheBack)
MISSING = "missing"  # the frames are not connected (yet), or another gap

#: Why a scan left the queue without being processed.
SUPERSEDED = "superseded"  # a newer scan was ready first
OVERFLOW = "overflow"  # more than QUEUE scans waited
NO_TRANSFORM = "no_transform"  # NEVER, or MISSING for longer than the wait


@dataclass
class HeldScan:
    """A scan in the queue.

    Attributes:
        msg: The ``sensor_msgs/LaserScan``.
        frame: Its frame, without a leading slash.
        arrived: When it arrived (wall seconds, ``time.monotonic``).
    """

    msg: Any
    frame: str
    arrived: float


@dataclass
class Dropped:
    """A scan that left the queue unprocessed: the reason, and for ``NO_TRANSFORM`` the
    filter's verdict (``NEVER`` or ``MISSING``) and tf's explanation."""

    scan: HeldScan
    reason: str
    state: str = ""
    why: str = ""


class ScanQueue:
    """The scans amcl holds, newest last (not thread safe: the node locks around it).

    Args:
        size: Scans held at most; the oldest goes first.
        missing_wait: Wall seconds a scan whose frames tf cannot connect may wait for them.
    """

    def __init__(self, size: int = QUEUE, missing_wait: float = 0.5) -> None:
        self.size = size
        self.missing_wait = missing_wait
        self._scans: collections.deque[HeldScan] = collections.deque()

    def __len__(self) -> int:
        return len(self._scans)

    def add(self, scan: HeldScan) -> Dropped | None:
        """Hold ``scan``; returns the oldest scan, dropped when the queue was full."""
        self._scans.append(scan)
        if len(self._scans) > self.size:
            return Dropped(self._scans.popleft(), OVERFLOW)
        return None

    def take(
        self, status: Callable[[HeldScan], tuple[str, str]], now: float
    ) -> tuple[HeldScan | None, list[Dropped]]:
        """The newest scan whose transform is known, and the scans dropped on the way.

        Looks from the newest scan back: the first ``READY`` one is taken and every older
        one is dropped as superseded; on the way, ``NEVER`` scans and ``MISSING`` ones
        that waited longer than ``missing_wait`` are dropped; scans still waiting for
        their transform stay.

        Args:
            status: ``(READY | WAIT | NEVER | MISSING, tf's explanation)`` of a scan.
            now: Wall seconds (``time.monotonic``).
        """
        taken: HeldScan | None = None
        kept: list[HeldScan] = []
        dropped: list[Dropped] = []
        scans = self._scans
        while scans:
            scan = scans.pop()
            if taken is not None:
                dropped.append(Dropped(scan, SUPERSEDED))
                continue
            state, why = status(scan)
            if state == READY:
                taken = scan
            elif state == NEVER or (state == MISSING and now - scan.arrived > self.missing_wait):
                dropped.append(Dropped(scan, NO_TRANSFORM, state, why))
            else:
                kept.append(scan)
        scans.extend(reversed(kept))
        dropped.reverse()  # oldest first
        return taken, dropped


__all__ = [
    "MISSING",
    "NEVER",
    "NO_TRANSFORM",
    "OVERFLOW",
    "QUEUE",
    "READY",
    "SUPERSEDED",
    "WAIT",
    "Dropped",
    "HeldScan",
    "ScanQueue",
]
