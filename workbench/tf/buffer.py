"""``workbench.tf.Buffer``: tf2_ros's Python Buffer on top of :class:`BufferCore`.

It adds the message-facing API (``geometry_msgs/TransformStamped`` in and out,
``transform()`` for stamped points, poses, vectors and quaternions), thread
safety, and waiting lookups: with ``timeout > 0`` a call waits for the data to
arrive -- spinning the bus when a :class:`~workbench.tf.TransformListener` feeds
the buffer, else sleeping until another thread inserts data. As in tf2_ros, a
lookup still impossible when the timeout passes raises the error it raises without
waiting (``LookupException``, ``ExtrapolationException``, ...), with a second line
saying how long it waited. The timeout is measured on the buffer's clock (the bus
clock, wall or simulated); a simulated clock that stops advancing ends the wait
after the same span of wall time, so a paused simulation cannot hang the caller
(tf2_ros would wait for ever).
"""

from __future__ import annotations

import threading
import time as _time
from collections.abc import Callable
from typing import Any

import numpy as np

from workbench.spatial import matrix_from_quaternion
from workbench.tf.core import DEFAULT_AUTHORITY, DEFAULT_CACHE_TIME, BufferCore, StampedTransform
from workbench.tf.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from workbench.tf.timeconv import to_ns

_CORE_ERRORS = (
    LookupException,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
)


_CLOCK_STOPPED = "(the clock stopped while waiting)"


def _wall_ns() -> int:
    return _time.time_ns()


def _let_the_listener_in() -> None:
    """Let other threads run after a failed lookup, once the buffer's lock is released.

    tf's and tf2's tutorials retry a failed lookup at once, in a loop without a sleep. In
    ROS the buffer is filled by the listener's own spinner thread in C++; here that thread
    shares the interpreter, and such a loop kept it from the buffer for seconds (turtle2
    stood still for 7 s in the manual's Experiment 4).
    """
    _time.sleep(0)


class Buffer(BufferCore):
    """Stores transforms and answers lookups (``tf2_ros.Buffer``).

    Args:
        cache_time: History kept per frame: seconds or a Duration (default 10 s).
        debug: Accepted for tf2_ros compatibility; has no effect.
    """

    def __init__(self, cache_time: Any = None, debug: bool = True) -> None:
        seconds = DEFAULT_CACHE_TIME if cache_time is None else to_ns(cache_time) / 1e9
        super().__init__(seconds)
        self._lock = threading.RLock()
        self._arrived = threading.Condition(self._lock)
        self._clock: Callable[[], int] = _wall_ns
        self._spinner: Callable[[float], Any] | None = None

    # --- wiring (used by TransformListener) -------------------------------------

    def use_clock(self, now_ns: Callable[[], int]) -> None:
        """Measure waiting timeouts on ``now_ns()`` (integer nanoseconds) instead of wall time."""
        self._clock = now_ns

    def use_spinner(self, spin: Callable[[float], Any] | None) -> None:
        """While waiting, call ``spin(seconds)`` to deliver messages (a bus's ``spin_once``)."""
        self._spinner = spin

    # --- the core API, made thread safe (listeners insert from bus threads) ----------

    def set_transform_values(self, *args: Any, **kwargs: Any) -> bool:
        with self._lock:
            ok = super().set_transform_values(*args, **kwargs)
            if ok:
                self._arrived.notify_all()
            return ok

    def lookup(self, target: str, source: str, time: Any = 0) -> StampedTransform:
        try:
            with self._lock:
                return super().lookup(target, source, time)
        except _CORE_ERRORS:
            _let_the_listener_in()
            raise

    def lookup_full(self, *args: Any) -> StampedTransform:
        try:
            with self._lock:
                return super().lookup_full(*args)
        except _CORE_ERRORS:
            _let_the_listener_in()
            raise

    def can_lookup(self, target: str, source: str, time: Any = 0) -> tuple[bool, str]:
        with self._lock:
            return super().can_lookup(target, source, time)

    def can_transform_core(self, target: str, source: str, time: Any = 0) -> tuple[bool, str]:
        with self._lock:
            return super().can_transform_core(target, source, time)

    def can_transform_full_core(
        self, target: str, target_time: Any, source: str, source_time: Any, fixed_frame: str
    ) -> tuple[bool, str]:
        with self._lock:
            return super().can_transform_full_core(
                target, target_time, source, source_time, fixed_frame
            )

    def get_latest_common_time(self, target: str, source: str) -> int:
        with self._lock:
            return super().get_latest_common_time(target, source)

    def get_parent(self, frame: str, time: Any = 0) -> str | None:
        with self._lock:
            return super().get_parent(frame, time)

    def frames_info(self, current_time: Any = None) -> dict[str, dict[str, Any]]:
        with self._lock:
            return super().frames_info(current_time)

    def all_frames_as_string(self) -> str:
        with self._lock:
            return super().all_frames_as_string()

    def get_frame_strings(self) -> list[str]:
        with self._lock:
            return super().get_frame_strings()

    def clear(self) -> None:
        with self._lock:
            super().clear()

    # --- insertion ----------------------------------------------------------------

    def set_transform(self, transform: Any, authority: str = DEFAULT_AUTHORITY) -> bool:
        """Store a ``geometry_msgs/TransformStamped`` (tf2_ros ``set_transform``).

        Returns:
            ``True`` if stored; ``False`` with a :class:`TransformDataWarning` for data
            tf2 refuses (see :meth:`BufferCore.set_transform_values`).
        """
        return self._set(transform, authority, static=False)

    def set_transform_static(self, transform: Any, authority: str = DEFAULT_AUTHORITY) -> bool:
        """Store a transform valid at all times (what ``/tf_static`` carries)."""
        return self._set(transform, authority, static=True)

    def _set(self, msg: Any, authority: str, static: bool) -> bool:
        try:
            tr = msg.transform.translation
            rot = msg.transform.rotation
            header = msg.header
            child = msg.child_frame_id
        except AttributeError:
            raise InvalidArgumentException(
                f"set_transform needs a geometry_msgs/TransformStamped, got {type(msg).__name__}"
            ) from None
        return self.set_transform_values(
            header.frame_id,
            child,
            (tr.x, tr.y, tr.z),
            (rot.x, rot.y, rot.z, rot.w),
            header.stamp,
            authority,
            static=static,
        )

    # --- waiting ------------------------------------------------------------------

    def _wait(self, check: Callable[[], tuple[bool, str]], timeout: Any) -> tuple[bool, str]:
        timeout_ns = to_ns(timeout, what="timeout")
        with self._lock:
            ok, why = check()
        if ok or timeout_ns <= 0:
            return ok, why
        start = self._clock()
        deadline = start + timeout_ns
        last_clock, last_move = start, _time.monotonic()
        step = min(0.01, timeout_ns / 1e9)
        while True:
            if self._spinner is not None:
                self._spinner(step)
            else:
                with self._lock:
                    self._arrived.wait(step)
            with self._lock:
                ok, why = check()
            if ok:
                return ok, why
            now = self._clock()
            if now >= deadline or now < start - 3_000_000_000:  # tf2: a jump back ends the wait
                return False, why
            if now != last_clock:
                last_clock, last_move = now, _time.monotonic()
            elif _time.monotonic() - last_move > timeout_ns / 1e9:
                return False, why + "\n" + _CLOCK_STOPPED

    def _timed_out(self, what: str, timeout: Any, why: str) -> TimeoutException:
        return TimeoutException(
            f"Timed out after {to_ns(timeout) / 1e9:g} s waiting for {what}: {why}"
        )

    # --- lookups ------------------------------------------------------------------

    def _after_waiting(self, exc: TransformException, timeout: Any, why: str) -> TransformException:
        """``exc`` again, its second line saying the lookup failed after waiting."""
        note = f"(still failing after waiting {to_ns(timeout) / 1e9:g} s"
        note += "; the clock stopped while waiting)" if why.endswith(_CLOCK_STOPPED) else ")"
        detail = f"{exc.detail}\n{note}" if exc.detail else note
        return type(exc)(exc.tf2_message, detail)

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any = 0, timeout: Any = 0.0
    ) -> Any:
        """The pose of ``source_frame`` in ``target_frame`` as a TransformStamped.

        Args:
            target_frame: The frame to express the result in (the header's frame_id).
            source_frame: The frame whose pose is wanted (the child_frame_id).
            time: Seconds or a Time; 0 means the latest time every link has data for.
            timeout: Seconds or a Duration to wait for the transform to become available.

        Raises:
            LookupException, ConnectivityException, ExtrapolationException,
            InvalidArgumentException: as tf2 raises them; with a timeout, when the
            lookup is still impossible after waiting (as tf2_ros: it waits with
            ``can_transform``, then looks up).
        """
        why = ""
        if timeout:
            _, why = self._wait(lambda: self.can_lookup(target_frame, source_frame, time), timeout)
        try:  # not under the lock: a failed lookup lets the listener in (see lookup)
            result = self.lookup(target_frame, source_frame, time)
        except _CORE_ERRORS as exc:
            if not timeout:
                raise
            raise self._after_waiting(exc, timeout, why) from None
        return to_msg(result)

    def _wait_or_raise(self, target: str, source: str, time: Any, timeout: Any) -> None:
        """Wait for a lookup to become possible; :class:`TimeoutException` if it does not."""
        ok, why = self._wait(lambda: self.can_lookup(target, source, time), timeout)
        if not ok:
            raise self._timed_out(f"'{source}' in '{target}' at {_fmt(time)}", timeout, why)

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = 0.0,
    ) -> Any:
        """Time travel (see :meth:`BufferCore.lookup_full`), as a TransformStamped.

        With a timeout, waits as :meth:`can_transform_full` does, then looks up.
        """
        why = ""
        if timeout:
            _, why = self._wait(
                lambda: self.can_transform_full_core(
                    target_frame, target_time, source_frame, source_time, fixed_frame
                ),
                timeout,
            )
        try:  # not under the lock: a failed lookup lets the listener in (see lookup)
            result = self.lookup_full(
                target_frame, target_time, source_frame, source_time, fixed_frame
            )
        except _CORE_ERRORS as exc:
            if not timeout:
                raise
            raise self._after_waiting(exc, timeout, why) from None
        return to_msg(result)

    def can_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: Any = 0,
        timeout: Any = 0.0,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """Whether the lookup would succeed (waiting up to ``timeout``); never raises for frames.

        The debug tuple's text is tf2's ``canTransform`` error string (``""`` for an
        empty or ``/``-prefixed frame, whose warning is logged).
        """
        ok, why = self._wait(
            lambda: self.can_transform_core(target_frame, source_frame, time), timeout
        )
        return (ok, why) if return_debug_tuple else ok

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = 0.0,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """Whether :meth:`lookup_transform_full` would succeed (waiting up to ``timeout``)."""
        ok, why = self._wait(
            lambda: self.can_transform_full_core(
                target_frame, target_time, source_frame, source_time, fixed_frame
            ),
            timeout,
        )
        return (ok, why) if return_debug_tuple else ok

    # --- transforming data ------------------------------------------------------------

    def transform(
        self, object_stamped: Any, target_frame: str, timeout: Any = 0.0, new_type: Any = None
    ) -> Any:
        """``object_stamped`` expressed in ``target_frame`` (tf2_ros ``Buffer.transform``).

        Supports ``geometry_msgs`` PointStamped, PoseStamped, Vector3Stamped and
        QuaternionStamped. The transform is looked up at the object's header stamp
        (0: the latest); the result carries the transform's frame and stamp, as
        tf2_geometry_msgs does.
        """
        if new_type is not None and new_type is not type(object_stamped):
            raise InvalidArgumentException(
                f"transform(new_type={getattr(new_type, '__name__', new_type)}) is not "
                "supported; convert the result yourself"
            )
        header = _header_of(object_stamped)
        t = self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout)
        return do_transform(object_stamped, t)

    def transform_full(
        self,
        object_stamped: Any,
        target_frame: str,
        target_time: Any,
        fixed_frame: str,
        timeout: Any = 0.0,
        new_type: Any = None,
    ) -> Any:
        """Like :meth:`transform`, but through ``fixed_frame`` into ``target_frame`` at ``target_time``."""
        header = _header_of(object_stamped)
        t = self.lookup_transform_full(
            target_frame, target_time, header.frame_id, header.stamp, fixed_frame, timeout
        )
        return do_transform(object_stamped, t)

    def transform_points(
        self, points: Any, target_frame: str, source_frame: str, time: Any = 0
    ) -> np.ndarray:
        """An ``(N, 3)`` array of points in ``source_frame`` expressed in ``target_frame`` (metres)."""
        with self._lock:
            st = self.lookup(target_frame, source_frame, time)
        return apply_to_points(st.translation, st.rotation, np.asarray(points, dtype=float))


# --- conversions ----------------------------------------------------------------------


def _fmt(time: Any) -> str:
    try:
        ns = to_ns(time)
    except TransformException:
        return repr(time)
    return "the latest time" if ns == 0 else f"time {ns / 1e9:.9f}"


def _header_of(obj: Any) -> Any:
    header = getattr(obj, "header", None)
    if header is None:
        raise InvalidArgumentException(
            f"transform() needs a stamped message with a header, got {type(obj).__name__}"
        )
    return header


_CLASSES: tuple[Any, ...] | None = None


def _classes() -> tuple[Any, ...]:
    """(Time, Header, TransformStamped, Transform, Vector3, Quaternion), looked up once."""
    global _CLASSES
    if _CLASSES is None:
        from workbench.msgs import Time
        from workbench.msgs.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
        from workbench.msgs.std_msgs import Header

        _CLASSES = (Time, Header, TransformStamped, Transform, Vector3, Quaternion)
    return _CLASSES


def stamp_msg(ns: int) -> Any:
    """A ``time`` message of integer nanoseconds."""
    secs, nsecs = divmod(int(ns), 1_000_000_000)
    return _classes()[0]._from_wire(secs, nsecs)


def to_msg(st: StampedTransform) -> Any:
    """A ``geometry_msgs/TransformStamped`` of a core result (built without re-checking)."""
    Time, Header, TransformStamped, Transform, Vector3, Quaternion = _classes()  # noqa: N806
    x, y, z = st.translation
    qx, qy, qz, qw = st.rotation
    secs, nsecs = divmod(st.stamp_ns, 1_000_000_000)
    return TransformStamped._from_wire(
        Header._from_wire(0, Time._from_wire(secs, nsecs), st.frame_id),
        st.child_frame_id,
        Transform._from_wire(Vector3._from_wire(x, y, z), Quaternion._from_wire(qx, qy, qz, qw)),
    )


def from_msg(msg: Any) -> tuple[tuple[float, float, float], tuple[float, float, float, float]]:
    """``(translation, rotation)`` tuples of a TransformStamped or Transform message."""
    tr = getattr(msg, "transform", msg)
    t, r = tr.translation, tr.rotation
    return (t.x, t.y, t.z), (r.x, r.y, r.z, r.w)


def apply_to_points(translation: Any, rotation: Any, points: np.ndarray) -> np.ndarray:
    """Apply a transform to an ``(N, 3)`` (or ``(3,)``) array of points."""
    rotated = np.asarray(points, dtype=float) @ matrix_from_quaternion(rotation).T
    return rotated + np.asarray(translation, dtype=float)


def _rotate(q: tuple[float, ...], v: tuple[float, float, float]) -> tuple[float, float, float]:
    from workbench.tf.core import compose

    r = compose((0.0, 0.0, 0.0, *q), (*v, 0.0, 0.0, 0.0, 1.0))
    return r[0], r[1], r[2]


def do_transform(obj: Any, transform: Any) -> Any:
    """Apply a TransformStamped to a stamped geometry message (tf2_geometry_msgs).

    Returns a new message of the same type, in the transform's ``frame_id`` and stamp.
    """
    from workbench.msgs.std_msgs import Header
    from workbench.tf.core import compose

    (t, q) = from_msg(transform)
    kind = getattr(obj, "_type", type(obj).__name__)
    header = Header(frame_id=transform.header.frame_id, stamp=transform.header.stamp)
    cls = type(obj)
    if kind == "geometry_msgs/PointStamped":
        p = obj.point
        x, y, z = _rotate(q, (p.x, p.y, p.z))
        out = cls()
        out.header = header
        out.point.x, out.point.y, out.point.z = x + t[0], y + t[1], z + t[2]
        return out
    if kind == "geometry_msgs/Vector3Stamped":
        v = obj.vector
        out = cls()
        out.header = header
        out.vector.x, out.vector.y, out.vector.z = _rotate(q, (v.x, v.y, v.z))
        return out
    if kind == "geometry_msgs/PoseStamped":
        p, o = obj.pose.position, obj.pose.orientation
        r = compose((*t, *q), (p.x, p.y, p.z, o.x, o.y, o.z, o.w))
        out = cls()
        out.header = header
        out.pose.position.x, out.pose.position.y, out.pose.position.z = r[0], r[1], r[2]
        o2 = out.pose.orientation
        o2.x, o2.y, o2.z, o2.w = r[3], r[4], r[5], r[6]
        return out
    if kind == "geometry_msgs/QuaternionStamped":
        o = obj.quaternion
        r = compose((0.0, 0.0, 0.0, *q), (0.0, 0.0, 0.0, o.x, o.y, o.z, o.w))
        out = cls()
        out.header = header
        out.quaternion.x, out.quaternion.y, out.quaternion.z, out.quaternion.w = r[3:]
        return out
    raise InvalidArgumentException(
        f"transform() does not know how to transform a {kind}; it supports PointStamped, "
        "PoseStamped, Vector3Stamped and QuaternionStamped"
    )
