"""Per-child-frame storage of stamped transforms (tf2's TimeCache and StaticCache).

An entry is a plain tuple ``(parent_id, tx, ty, tz, qx, qy, qz, qw)``: the pose of
the child frame in its parent frame at one stamp (metres, unit quaternion xyzw).
Stamps are integer nanoseconds, kept sorted in a list so a lookup is one
``bisect``; the hot path uses only floats and the ``math`` module.
"""

from __future__ import annotations

from bisect import bisect_left
from math import acos, sin

Entry = tuple  # (parent_id, tx, ty, tz, qx, qy, qz, qw)

#: Entries older than the newest by more than the cache time are dropped in
#: batches (an index moves forward; the list is compacted when half is dead).
_COMPACT_AT = 256


class NoData(Exception):  # noqa: N818 - internal signal, never escapes the buffer
    """Raised inside the buffer when a cache has no data at the requested time."""


def seconds_text(ns: int) -> str:
    """A time or a (non-negative) duration as tf2 prints it: ``%.9f`` of ``sec + 1e-9 * nsec``.

    tf2 converts ``ros::Time`` to seconds as ``sec + 1e-9 * nsec`` in doubles; at Unix-epoch
    magnitudes that differs in the last printed digits from ``ns / 1e9``, so the same
    arithmetic is used here to print the same digits.
    """
    sec, nsec = divmod(ns, 1_000_000_000)
    return f"{sec + 1e-9 * nsec:.9f}"


class TimeCache:
    """The history of one child frame, pruned to ``cache_ns`` behind its newest stamp."""

    __slots__ = ("stamps", "data", "start", "cache_ns", "static")

    def __init__(self, cache_ns: int) -> None:
        self.stamps: list[int] = []
        self.data: list[Entry] = []
        self.start = 0
        self.cache_ns = cache_ns
        self.static = False

    # --- insertion ------------------------------------------------------------

    def insert(self, stamp: int, entry: Entry) -> str | None:
        """Store ``entry`` at ``stamp``; returns ``None`` or the reason it was refused.

        The reasons are tf2's: ``"old"`` (older than the newest stamp minus the cache
        time) and ``"repeated"`` (an entry with exactly this stamp exists).
        """
        stamps = self.stamps
        if not stamps:
            stamps.append(stamp)
            self.data.append(entry)
            return None
        if stamp > stamps[-1]:
            stamps.append(stamp)
            self.data.append(entry)
            if stamps[self.start] < stamp - self.cache_ns:
                self._prune()
            return None
        else:
            if stamps[-1] > stamp + self.cache_ns:
                return "old"
            i = bisect_left(stamps, stamp, self.start)
            if i < len(stamps) and stamps[i] == stamp:
                return "repeated"
            stamps.insert(i, stamp)
            self.data.insert(i, entry)
        self._prune()
        return None

    def _prune(self) -> None:
        stamps = self.stamps
        oldest_kept = stamps[-1] - self.cache_ns
        start = self.start
        if stamps[start] < oldest_kept:
            start = bisect_left(stamps, oldest_kept, start)
            if start > _COMPACT_AT and start * 2 > len(stamps):
                del stamps[:start]
                del self.data[:start]
                start = 0
            self.start = start

    def clear(self) -> None:
        self.stamps.clear()
        self.data.clear()
        self.start = 0

    # --- queries --------------------------------------------------------------

    def __len__(self) -> int:
        return len(self.stamps) - self.start

    def latest(self) -> tuple[int, int]:
        """``(newest stamp, parent id at that stamp)``; ``(0, 0)`` when empty."""
        if len(self.stamps) == self.start:
            return 0, 0
        return self.stamps[-1], self.data[-1][0]

    def oldest_stamp(self) -> int:
        return self.stamps[self.start] if len(self.stamps) > self.start else 0

    def gather(self, t: int) -> Entry:
        """The entry at time ``t`` (0: the newest), interpolated between neighbours.

        Translation is interpolated linearly and rotation by slerp; when the two
        neighbours have different parents, the older one is returned unchanged
        (tf2's re-parenting protection).

        Raises:
            NoData: the cache is empty or ``t`` is outside the stored interval.
        """
        stamps = self.stamps
        if t:
            i = bisect_left(stamps, t, self.start)
            if i < len(stamps):
                s1 = stamps[i]
                if s1 == t:
                    return self.data[i]
                if i > self.start:
                    s0 = stamps[i - 1]
                    data = self.data
                    a = data[i - 1]
                    b = data[i]
                    if a[0] != b[0]:
                        return a
                    return _interpolate(a, b, (t - s0) / (s1 - s0))
        elif len(stamps) > self.start:
            return self.data[-1]
        raise NoData(self._explain(t))

    def _explain(self, t: int) -> str:
        """tf2's text for no data at ``t`` (TimeCache::findClosest); ``""`` when empty, as tf2."""
        stamps = self.stamps
        if len(stamps) == self.start:
            return ""
        first, last = stamps[self.start], stamps[-1]
        if first == last:
            return (
                f"Lookup would require extrapolation at time {seconds_text(t)}, "
                f"but only time {seconds_text(last)} is in the buffer"
            )
        if t > last:
            return (
                f"Lookup would require extrapolation {seconds_text(t - last)}s into the future.  "
                f"Requested time {seconds_text(t)} but the latest data is at time "
                f"{seconds_text(last)}"
            )
        return (
            f"Lookup would require extrapolation {seconds_text(first - t)}s into the past.  "
            f"Requested time {seconds_text(t)} but the earliest data is at time "
            f"{seconds_text(first)}"
        )


def _interpolate(a: Entry, b: Entry, r: float) -> Entry:
    """Linear interpolation of translation, slerp of rotation, at ratio ``r`` in (0, 1)."""
    p0, ax, ay, az, aqx, aqy, aqz, aqw = a
    _, bx, by, bz, bqx, bqy, bqz, bqw = b
    # slerp as tf2 (Bullet) does it: shortest arc; identical rotations return the first.
    dot = aqx * bqx + aqy * bqy + aqz * bqz + aqw * bqw
    adot = dot if dot >= 0.0 else -dot
    if adot < 0.9999999999999998:
        theta = acos(adot)
        d = sin(theta)
        w0 = sin((1.0 - r) * theta) / d
        w1 = sin(r * theta) / d
        if dot < 0.0:
            w1 = -w1
        return (
            p0,
            ax + (bx - ax) * r,
            ay + (by - ay) * r,
            az + (bz - az) * r,
            aqx * w0 + bqx * w1,
            aqy * w0 + bqy * w1,
            aqz * w0 + bqz * w1,
            aqw * w0 + bqw * w1,
        )
    return (p0, ax + (bx - ax) * r, ay + (by - ay) * r, az + (bz - az) * r, aqx, aqy, aqz, aqw)


class StaticCache:
    """A frame published on ``/tf_static``: one entry, valid at every time."""

    __slots__ = ("entry", "static")

    def __init__(self) -> None:
        self.entry: Entry | None = None
        self.static = True

    def insert(self, stamp: int, entry: Entry) -> str | None:
        self.entry = entry
        return None

    def clear(self) -> None:
        """Nothing: tf2 keeps static transforms when the buffer is cleared."""

    def __len__(self) -> int:
        return 0 if self.entry is None else 1

    def latest(self) -> tuple[int, int]:
        return (0, 0) if self.entry is None else (0, self.entry[0])

    def oldest_stamp(self) -> int:
        return 0

    def gather(self, t: int) -> Entry:
        if self.entry is None:
            raise NoData("")
        return self.entry
