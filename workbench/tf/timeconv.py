"""Conversions between the time types a user may pass and integer nanoseconds.

The buffer stores stamps as integer nanoseconds (exact, like ``ros::Time``), so
two stamps 1 ns apart stay distinct even at Unix-epoch magnitudes where a float
of seconds would merge them.
"""

from __future__ import annotations

import math
from typing import Any

from workbench.tf.exceptions import InvalidArgumentException


def to_ns(value: Any, *, what: str = "time") -> int:
    """Nanoseconds of a time or duration.

    Accepts ``None`` (0, meaning "latest"), seconds as ``int``/``float``, and the
    time types of rospy (``secs``/``nsecs``), ROS 2 and rosbags (``sec``/``nanosec``),
    or anything with ``to_nsec()`` / ``nanoseconds``.

    Raises:
        InvalidArgumentException: ``value`` is not a time, or is NaN/infinite.
    """
    kind = type(value)
    if kind is float and value - value == 0.0:  # finite float: the common case
        return round(value * 1e9)
    if kind is int:
        return value * 1_000_000_000
    if value is None:
        return 0
    if isinstance(value, bool):
        raise InvalidArgumentException(f"{what} must be a time, not a bool ({value!r})")
    if isinstance(value, int):
        return value * 1_000_000_000
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InvalidArgumentException(f"{what} must be finite, got {value!r}")
        return round(value * 1e9)
    to_nsec = getattr(value, "to_nsec", None)
    if callable(to_nsec):
        return int(to_nsec())
    nanoseconds = getattr(value, "nanoseconds", None)
    if isinstance(nanoseconds, int):
        return nanoseconds
    if hasattr(value, "secs") and hasattr(value, "nsecs"):
        return int(value.secs) * 1_000_000_000 + int(value.nsecs)
    if hasattr(value, "sec") and hasattr(value, "nanosec"):
        return int(value.sec) * 1_000_000_000 + int(value.nanosec)
    to_sec = getattr(value, "to_sec", None)
    if callable(to_sec):
        return round(float(to_sec()) * 1e9)
    raise InvalidArgumentException(
        f"{what} must be a time (seconds or a Time), got {type(value).__name__} {value!r}"
    )


def ns_to_sec(ns: int) -> float:
    """Seconds (float) of integer nanoseconds."""
    return ns / 1e9
