"""ROS 1 ``time`` and ``duration`` behaviour for the two builtin message classes.

``Time(secs, nsecs)`` and ``Duration(secs, nsecs)`` behave like rospy's: a
float ``secs`` alone is split into seconds and nanoseconds, values are kept
canonical (``0 <= nsecs < 1e9``), ``to_sec()``/``to_nsec()``, arithmetic
(time - time = duration, time + duration = time) and ordering. On the wire
they are the typestore's ``builtin_interfaces`` ``sec``/``nanosec`` pair.
"""

from __future__ import annotations

import math
from typing import Any

from workbench.errors import MessageError

_NS = 1_000_000_000


def _split(secs: Any, nsecs: Any, kind: str) -> tuple[int, int]:
    if isinstance(secs, bool) or isinstance(nsecs, bool):
        raise MessageError(f"{kind} needs numbers, not bool")
    if not isinstance(secs, int):
        try:
            value = float(secs)
        except (TypeError, ValueError):
            raise MessageError(f"{kind} seconds must be a number; got {secs!r}") from None
        if not math.isfinite(value):
            raise MessageError(f"{kind} seconds must be finite; got {secs!r}")
        if nsecs:
            raise MessageError(f"{kind}: give float seconds alone, or integer secs and nsecs")
        if abs(value) > 2.0**63 / _NS:  # no ROS time has it, and value * 1e9 may overflow
            raise MessageError(f"{kind} of {secs!r} s is out of range")
        total = round(value * _NS)
    else:
        try:
            total = secs * _NS + int(nsecs)
        except (TypeError, ValueError, OverflowError):
            raise MessageError(f"{kind} nanoseconds must be an integer; got {nsecs!r}") from None
    return divmod(total, _NS)


class _TimeBase:
    """Shared by Time and Duration (a mixin placed before ``Message``)."""

    __slots__ = ()
    _kind = "time"
    _duration_class: type
    _time_class: type

    def __init__(self, secs: Any = 0, nsecs: Any = 0, *, sec: Any = None, nanosec: Any = None):
        if sec is not None or nanosec is not None:
            secs, nsecs = sec or 0, nanosec or 0
        s, ns = _split(secs, nsecs, self._kind)
        self._check_range(s)
        object.__setattr__(self, "sec", s)
        object.__setattr__(self, "nanosec", ns)

    def _check_range(self, s: int) -> None:
        if not -(2**31) <= s < 2**31:
            raise MessageError(f"{self._kind} of {s} s is out of the 32-bit range")

    def __setattr__(self, name: str, value: Any) -> None:
        name = {"secs": "sec", "nsecs": "nanosec"}.get(name, name)
        super().__setattr__(name, value)

    @property
    def secs(self) -> int:
        """Whole seconds (rospy's name for ``sec``)."""
        return self.sec  # type: ignore[attr-defined]

    @property
    def nsecs(self) -> int:
        """Nanoseconds within the second (rospy's name for ``nanosec``)."""
        return self.nanosec  # type: ignore[attr-defined]

    def to_nsec(self) -> int:
        """Total nanoseconds."""
        return self.sec * _NS + self.nanosec  # type: ignore[attr-defined]

    def to_sec(self) -> float:
        """Total seconds as a float."""
        return self.to_nsec() / 1e9

    def is_zero(self) -> bool:
        return self.to_nsec() == 0

    def __bool__(self) -> bool:
        return not self.is_zero()

    @classmethod
    def from_sec(cls, seconds: float) -> Any:
        return cls(float(seconds))

    @classmethod
    def from_nsec(cls, nanoseconds: int) -> Any:
        return cls(0, int(nanoseconds))

    def _other_ns(self, other: Any) -> int | None:
        return other.to_nsec() if isinstance(other, _TimeBase) else None

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, _TimeBase) or other._kind != self._kind:
            return NotImplemented
        return self.to_nsec() == other.to_nsec()

    def __lt__(self, other: Any) -> bool:
        if not isinstance(other, _TimeBase) or other._kind != self._kind:
            return NotImplemented
        return self.to_nsec() < other.to_nsec()

    def __le__(self, other: Any) -> bool:
        return self == other or self < other

    def __gt__(self, other: Any) -> bool:
        if not isinstance(other, _TimeBase) or other._kind != self._kind:
            return NotImplemented
        return self.to_nsec() > other.to_nsec()

    def __ge__(self, other: Any) -> bool:
        return self == other or self > other

    def __hash__(self) -> int:
        return hash((self._kind, self.to_nsec()))

    def __repr__(self) -> str:
        return f"{type(self).__name__}[{self.to_nsec()}]"

    def __str__(self) -> str:
        return str(self.to_nsec())


class TimeMixin(_TimeBase):
    """A point in time (ROS 1 ``time``): seconds and nanoseconds since the epoch."""

    __slots__ = ()
    _kind = "time"

    def __add__(self, other: Any) -> Any:
        if isinstance(other, DurationMixin):
            return type(self)(0, self.to_nsec() + other.to_nsec())
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, TimeMixin):
            return self._duration_class(0, self.to_nsec() - other.to_nsec())
        if isinstance(other, DurationMixin):
            return type(self)(0, self.to_nsec() - other.to_nsec())
        return NotImplemented


class DurationMixin(_TimeBase):
    """A signed span of time (ROS 1 ``duration``)."""

    __slots__ = ()
    _kind = "duration"

    def __add__(self, other: Any) -> Any:
        if isinstance(other, DurationMixin):
            return type(self)(0, self.to_nsec() + other.to_nsec())
        if isinstance(other, TimeMixin):
            return other + self
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, DurationMixin):
            return type(self)(0, self.to_nsec() - other.to_nsec())
        return NotImplemented

    def __neg__(self) -> Any:
        return type(self)(0, -self.to_nsec())

    def __abs__(self) -> Any:
        return type(self)(0, abs(self.to_nsec()))

    def __mul__(self, factor: float) -> Any:
        if isinstance(factor, (int, float)) and not isinstance(factor, bool):
            return type(self)(0, round(self.to_nsec() * factor))
        return NotImplemented

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Any:
        if isinstance(other, DurationMixin):
            return self.to_nsec() / other.to_nsec()
        if isinstance(other, (int, float)) and not isinstance(other, bool):
            return type(self)(0, round(self.to_nsec() / other))
        return NotImplemented
