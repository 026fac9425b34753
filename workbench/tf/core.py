"""The frame tree over time (tf2's BufferCore) on plain floats: no messages, no bus.

Frames form a tree that may change over time: each child frame has a
:class:`~workbench.tf.cache.TimeCache` (or a :class:`StaticCache` for
``/tf_static`` data) holding its pose in its parent at each stamp. A lookup
walks from the source frame and from the target frame towards the root at the
requested time until the walks meet, composing the transforms on the way.

Conventions (tf2's): ``lookup(target, source, t)`` returns ``T_target_source``,
the pose of ``source`` in ``target`` -- it maps a point expressed in ``source``
into ``target``. Time 0 means "the latest time at which every link between the
two frames has data". Translations are metres, rotations unit quaternions
``(x, y, z, w)``, stamps integer nanoseconds internally and seconds or Time objects
at the API.

Failures follow tf2 (geometry2 Noetic, 0.7.7): the same checks in the same order,
so a bad lookup raises the exception class tf2 raises, and the first line of its
message is tf2's text; a second line may add detail. Unlike tf2, a quaternion
accepted by ``set_transform`` (squared norm within 0.01 of 1) is stored normalised,
so results are proper rotations where tf2 would carry the error along.
"""

from __future__ import annotations

import logging
import math
import warnings
from bisect import bisect_left
from collections.abc import Sequence
from math import acos, sin
from typing import Any, NamedTuple

from workbench.tf.cache import NoData, StaticCache, TimeCache
from workbench.tf.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformDataWarning,
    TransformException,
)
from workbench.tf.timeconv import to_ns

#: tf2's limit on path length; a longer walk means the tree has a loop.
MAX_GRAPH_DEPTH = 1000
#: tf2 refuses quaternions whose squared norm differs from 1 by this much.
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3
DEFAULT_CACHE_TIME = 10.0
DEFAULT_AUTHORITY = "default_authority"

_IDENTITY = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
_LOG = logging.getLogger("workbench.tf")


class StampedTransform(NamedTuple):
    """The result of a core lookup: the pose of ``child_frame_id`` in ``frame_id``.

    Attributes:
        frame_id: The target (parent-side) frame.
        child_frame_id: The source frame.
        stamp_ns: The time the transform is valid at, integer nanoseconds.
        translation: ``(x, y, z)`` in metres, expressed in ``frame_id``.
        rotation: Unit quaternion ``(x, y, z, w)``.
    """

    frame_id: str
    child_frame_id: str
    stamp_ns: int
    translation: tuple[float, float, float]
    rotation: tuple[float, float, float, float]

    @property
    def stamp(self) -> float:
        """The stamp in seconds."""
        return self.stamp_ns / 1e9


def compose(a: Sequence[float], b: Sequence[float]) -> tuple[float, ...]:
    """``a * b`` for transforms given as ``(tx, ty, tz, qx, qy, qz, qw)``."""
    ax, ay, az, x1, y1, z1, w1 = a
    bx, by, bz, x2, y2, z2, w2 = b
    # rotate b's translation by a's rotation: v + w*t + q x t, t = 2 q x v
    tx = 2.0 * (y1 * bz - z1 * by)
    ty = 2.0 * (z1 * bx - x1 * bz)
    tz = 2.0 * (x1 * by - y1 * bx)
    return (
        ax + bx + w1 * tx + (y1 * tz - z1 * ty),
        ay + by + w1 * ty + (z1 * tx - x1 * tz),
        az + bz + w1 * tz + (x1 * ty - y1 * tx),
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
    )


def inverse(a: Sequence[float]) -> tuple[float, ...]:
    """The inverse of a transform ``(tx, ty, tz, qx, qy, qz, qw)``."""
    x, y, z, qx, qy, qz, qw = a
    return compose((0.0, 0.0, 0.0, -qx, -qy, -qz, qw), (-x, -y, -z, 0.0, 0.0, 0.0, 1.0))


def _matrix_sign(v: tuple[float, ...]) -> tuple[float, ...]:
    """``v`` with its quaternion's sign as tf2 gives it after a trip through a rotation matrix.

    tf2 composes the two halves of a fixed-frame lookup as ``tf2::Transform`` (a 3x3
    matrix) and reads the quaternion back from the matrix, which fixes its sign: ``w``
    is positive when the matrix trace is, else the component of the largest diagonal
    element is. ``q`` and ``-q`` are the same rotation; this only makes the numbers
    equal to tf2's.
    """
    x, y, z, w = v[3], v[4], v[5], v[6]
    d0 = 1.0 - 2.0 * (y * y + z * z)
    d1 = 1.0 - 2.0 * (x * x + z * z)
    d2 = 1.0 - 2.0 * (x * x + y * y)
    if d0 + d1 + d2 > 0.0:
        key = w
    elif d0 < d1:
        key = z if d1 < d2 else y
    else:
        key = z if d0 < d2 else x
    if key < 0.0:
        return (v[0], v[1], v[2], -x, -y, -z, -w)
    return v


def _strip_slash(name: str) -> str:
    return name[1:] if name.startswith("/") else name


class BufferCore:
    """tf2's BufferCore: stamped transforms per child frame, lookups through the tree.

    Args:
        cache_time: How much history each dynamic frame keeps, in seconds
            (tf2's default is 10 s). Data older than the newest stamp of its frame
            minus this is refused.
    """

    def __init__(self, cache_time: float = DEFAULT_CACHE_TIME) -> None:
        if not cache_time > 0:
            raise InvalidArgumentException(f"cache_time must be positive, got {cache_time!r}")
        self.cache_time = float(cache_time)
        self._cache_ns = round(self.cache_time * 1e9)
        self._ids: dict[str, int] = {}
        self._names: list[str] = ["NO_PARENT"]
        self._caches: list[TimeCache | StaticCache | None] = [None]
        self._authority: dict[int, str] = {}

    # --- frames ---------------------------------------------------------------

    def _frame_id(self, name: str) -> int:
        fid = self._ids.get(name)
        if fid is None:
            fid = len(self._names)
            self._ids[name] = fid
            self._names.append(name)
            self._caches.append(None)
        return fid

    def frame_exists(self, frame: str) -> bool:
        """Whether ``frame`` has been seen as a parent or a child."""
        return frame in self._ids

    def get_frame_strings(self) -> list[str]:
        """The names of every known frame, in the order they were first seen."""
        return list(self._names[1:])

    def clear(self) -> None:
        """Forget the stored dynamic transforms, as tf2's ``clear``.

        Frames stay known, and static transforms stay (tf2 keeps them: ``/tf_static``
        is latched and not sent again when a listener clears its buffer after time
        jumped back, as when a bag loops).
        """
        for cache in self._caches:
            if cache is not None:
                cache.clear()

    def _validate(self, function: str, frame: str) -> int:
        """The id of ``frame``, checked as tf2's validateFrameId checks it (with its texts)."""
        if not isinstance(frame, str):  # tf2_py refuses these with a TypeError
            raise InvalidArgumentException(
                f"Invalid argument passed to {function}: frame ids are strings, "
                f"got {type(frame).__name__} {frame!r}"
            )
        if frame == "":
            raise InvalidArgumentException(
                f"Invalid argument passed to {function} in tf2 frame_ids cannot be empty"
            )
        if frame.startswith("/"):
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {function} in tf2 frame_ids cannot '
                "start with a '/' like: ",
                f"(use '{frame.lstrip('/')}')",
            )
        fid = self._ids.get(frame)
        if fid is None:
            known = ", ".join(sorted(self._names[1:]))
            raise LookupException(
                f'"{frame}" passed to {function} does not exist. ',
                f"(known frames: {known})" if known else "(no frames are known yet)",
            )
        return fid

    # --- insertion ------------------------------------------------------------

    def set_transform_values(
        self,
        frame_id: str,
        child_frame_id: str,
        translation: Sequence[float],
        rotation: Sequence[float],
        stamp: Any,
        authority: str = DEFAULT_AUTHORITY,
        *,
        static: bool = False,
    ) -> bool:
        """Store the pose of ``child_frame_id`` in ``frame_id`` at ``stamp``.

        Args:
            frame_id: The parent frame.
            child_frame_id: The child frame.
            translation: ``(x, y, z)`` of the child origin in the parent, metres.
            rotation: Quaternion ``(x, y, z, w)`` of the child axes in the parent.
            stamp: Seconds or a Time; ignored for static transforms.
            authority: Who sent it (the broadcasting node), shown by ``view_frames``.
            static: Store as a ``/tf_static`` transform, valid at all times.

        Returns:
            ``True`` if stored. Data tf2 refuses -- a frame that is its own parent,
            empty frame ids, NaN values, a quaternion whose squared norm is off by
            0.01 or more, data older than the cache, a repeated stamp -- is not
            stored: a :class:`TransformDataWarning` names the reason and ``False``
            is returned.
        """
        stamp_ns = to_ns(stamp, what="stamp")
        parent = frame_id if type(frame_id) is str else str(frame_id)
        child = child_frame_id if type(child_frame_id) is str else str(child_frame_id)
        if parent[:1] == "/":
            parent = parent[1:]
        if child[:1] == "/":
            child = child[1:]
        try:
            tx, ty, tz = translation
            qx, qy, qz, qw = rotation
            tx, ty, tz = float(tx), float(ty), float(tz)
            qx, qy, qz, qw = float(qx), float(qy), float(qz), float(qw)
        except (TypeError, ValueError):
            raise InvalidArgumentException(
                f"transform {parent} -> {child}: translation must be 3 numbers and rotation "
                f"4 numbers (x, y, z, w); got {translation!r} and {rotation!r}"
            ) from None
        norm2 = qx * qx + qy * qy + qz * qz + qw * qw
        if (
            child
            and parent
            and child != parent
            and (tx - tx) + (ty - ty) + (tz - tz) == 0.0  # False for NaN and inf
            and -QUATERNION_NORMALIZATION_TOLERANCE
            < norm2 - 1.0
            < QUATERNION_NORMALIZATION_TOLERANCE
        ):
            if norm2 != 1.0:
                n = math.sqrt(norm2)
                qx, qy, qz, qw = qx / n, qy / n, qz / n, qw / n
            return self._insert(
                parent, child, stamp_ns, (tx, ty, tz, qx, qy, qz, qw), authority, static
            )
        problems = []
        if child == parent:
            problems.append(
                f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with '
                f'frame_id and child_frame_id "{child}" because they are the same'
            )
        if child == "":
            problems.append(
                f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" '
                "because child_frame_id not set"
            )
        if parent == "":
            problems.append(
                f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}" from '
                f'authority "{authority}" because frame_id not set'
            )
        values = (tx, ty, tz, qx, qy, qz, qw)
        if any(math.isnan(v) or math.isinf(v) for v in values):
            problems.append(
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority '
                f'"{authority}" because of a nan value in the transform '
                f"({tx:f} {ty:f} {tz:f}) ({qx:f} {qy:f} {qz:f} {qw:f})"
            )
        else:
            norm2 = qx * qx + qy * qy + qz * qz + qw * qw
            if abs(norm2 - 1.0) >= QUATERNION_NORMALIZATION_TOLERANCE:
                problems.append(
                    f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" '
                    f'from authority "{authority}" because of an invalid quaternion in the '
                    f"transform ({qx:f} {qy:f} {qz:f} {qw:f})"
                )
            else:
                n = math.sqrt(norm2)
                qx, qy, qz, qw = qx / n, qy / n, qz / n, qw / n
        if problems:
            for text in problems:
                warnings.warn(text, TransformDataWarning, stacklevel=2)
            return False
        return self._insert(
            parent, child, stamp_ns, (tx, ty, tz, qx, qy, qz, qw), authority, static
        )

    def _insert(
        self,
        parent: str,
        child: str,
        stamp_ns: int,
        values: tuple[float, ...],
        authority: str,
        static: bool,
    ) -> bool:
        ids = self._ids
        child_id = ids.get(child)
        if child_id is None:
            child_id = self._frame_id(child)
        parent_id = ids.get(parent)
        if parent_id is None:
            parent_id = self._frame_id(parent)
        cache = self._caches[child_id]
        if cache is None:
            cache = StaticCache() if static else TimeCache(self._cache_ns)
            self._caches[child_id] = cache
        refused = cache.insert(stamp_ns, (parent_id, *values))
        if refused is None:
            if self._authority.get(child_id) != authority:
                self._authority[child_id] = authority
            return True
        if refused == "old":
            text = (
                f"TF_OLD_DATA ignoring data from the past for frame {child} at time "
                f"{stamp_ns / 1e9:.9f} according to authority {authority} (the newest is "
                f"{cache.latest()[0] / 1e9:.9f} and the cache keeps {self.cache_time:g} s; "
                "a node publishing old stamps, or a bag or simulation restarted without "
                "clearing the buffer?)"
            )
        else:
            text = (
                f"TF_REPEATED_DATA ignoring data with redundant timestamp for frame {child} "
                f"at time {stamp_ns / 1e9:.9f} according to authority {authority}"
            )
        warnings.warn(text, TransformDataWarning, stacklevel=3)
        return False

    # --- lookups --------------------------------------------------------------
    #
    # The walks follow tf2's BufferCore (buffer_core.cpp) step for step, because which
    # exception a bad lookup raises depends on the order things are checked in:
    #
    # * time 0 first becomes the latest common time (getLatestCommonTime), which can
    #   itself fail (disconnected frames, a loop);
    # * then the source walks up to its root, stopping early at the target or at the
    #   first link without data at the time;
    # * then the target walks up until it reaches where the source walk stopped, or
    #   the source. A link without data on this walk fails at once; if the walk ends
    #   at another root, the source walk's missing data is reported if there was
    #   some, else the trees are not connected.

    def latest_common_time_ns(self, target_id: int, source_id: int) -> int:
        """The newest time every link between two frames has data (0: all static).

        tf2's getLatestCommonTime: the source's links are listed up to its root, then
        the target walks up until one of its links has a parent that a source link
        has; the answer is the oldest "newest stamp" of the links up to there
        (static links, stamped 0, do not count).

        Raises:
            ConnectivityException: the frames are in different trees.
            LookupException: the tree has a loop.
        """
        caches = self._caches
        if source_id == target_id:
            cache = caches[source_id]
            return cache.latest()[0] if cache is not None else 0
        never = 1 << 64
        source_links: list[tuple[int, int]] = []  # (newest stamp, parent) up from the source
        parents_seen: set[int] = set()
        common = never
        frame = source_id
        depth = 0
        while frame != 0:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest()
            if parent == 0:
                break
            if stamp and stamp < common:
                common = stamp
            source_links.append((stamp, parent))
            parents_seen.add(parent)
            frame = parent
            if frame == target_id:
                return 0 if common == never else common
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop()
        common = never
        common_parent = 0
        frame = target_id
        depth = 0
        while True:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest()
            if parent == 0:
                break
            if stamp and stamp < common:
                common = stamp
            if parent in parents_seen:
                common_parent = parent
                break
            frame = parent
            if frame == source_id:
                return 0 if common == never else common
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop()
        if common_parent == 0:
            raise self._connectivity(target_id, source_id)
        for stamp, parent in source_links:
            if stamp and stamp < common:
                common = stamp
            if parent == common_parent:
                break
        return 0 if common == never else common

    def _connectivity(self, target_id: int, source_id: int) -> ConnectivityException:
        target, source = self._names[target_id], self._names[source_id]
        return ConnectivityException(
            f"Could not find a connection between '{target}' and '{source}' because they "
            "are not part of the same tree.Tf has two or more unconnected trees."
        )

    def _loop(self) -> LookupException:
        return LookupException(
            f"The tf tree is invalid because it contains a loop.\n{self.all_frames_as_string()}\n"
        )

    def _extrapolation(
        self, why: str, target_id: int, source_id: int, where: int
    ) -> ExtrapolationException:
        names = self._names
        # tf2 formats this into a char[1000]: longer texts are cut to 999 characters
        text = (
            f"{why}, when looking up transform from frame [{names[source_id]}] "
            f"to frame [{names[target_id]}]"
        )[:999]
        cache = self._caches[where]
        if cache is not None and len(cache) == 0:
            detail = f"(frame '{names[where]}' has no data: its cache is empty since a clear())"
        else:
            parent = names[cache.latest()[1]] if cache is not None else "?"
            detail = f"(no data for frame '{names[where]}' in '{parent}' at that time)"
        return ExtrapolationException(text, detail)

    def _walk(self, target_id: int, source_id: int, t: int) -> tuple[float, ...]:
        """``T_target_source`` at ``t`` ns (0: each link's newest) as a 7-tuple.

        Raises:
            ExtrapolationException, ConnectivityException, LookupException (a loop).
        """
        if target_id == source_id:
            return _IDENTITY
        # T_frame_source for every frame the source walk reached (its last one included)
        below: dict[int, tuple[float, ...]] = {}
        top, from_source, why = self._climb(source_id, t, target_id, below)
        if top == target_id:
            return from_source
        # tf2's target walk goes on to ``top``; it stops here at the first frame of the
        # source walk instead: the links from there to ``top`` all had data (the source
        # walk used them), so the outcome is the same, with fewer products.
        end, from_target, why_target = self._climb(target_id, t, -1, below)
        if why_target is not None:
            raise self._extrapolation(why_target, target_id, source_id, end)
        if end in below:
            return compose(inverse(from_target), below[end])
        if why is not None:
            raise self._extrapolation(why, target_id, source_id, top)
        raise self._connectivity(target_id, source_id)

    def _climb(
        self, frame: int, t: int, goal: int, below: dict[int, tuple[float, ...]]
    ) -> tuple[int, tuple[float, ...], str | None]:
        """Walk up from ``frame`` composing ``T_current_start``, link by link at ``t``.

        With ``goal >= 0`` (the source walk) it stops on reaching ``goal`` and records
        ``T_current_start`` in ``below`` for every other frame it reaches; with
        ``goal < 0`` (the target walk) it stops on reaching a frame in ``below``
        (before using that frame's link). Either walk also stops at a frame without a
        parent (a root) or one whose link has no data at ``t``. Returns ``(frame
        reached, accumulated transform, why)``, ``why`` being tf2's text for the
        missing data or ``None``.

        Raises:
            LookupException: more than MAX_GRAPH_DEPTH links: the tree has a loop.
        """
        # Any: the loop tells TimeCache from StaticCache by ``cache.static``, not isinstance.
        caches: list[Any] = self._caches
        tx = ty = tz = qx = qy = qz = 0.0
        qw = 1.0
        depth = 0
        record = goal >= 0
        while True:
            if record:
                if frame == goal:
                    return frame, (tx, ty, tz, qx, qy, qz, qw), None
                below[frame] = (tx, ty, tz, qx, qy, qz, qw)
            elif frame in below:
                return frame, (tx, ty, tz, qx, qy, qz, qw), None
            cache = caches[frame]
            if cache is None:
                return frame, (tx, ty, tz, qx, qy, qz, qw), None
            # --- the link frame -> parent at t (inlined TimeCache.gather) ---
            if cache.static:
                entry = cache.entry
                if entry is None:
                    return frame, (tx, ty, tz, qx, qy, qz, qw), ""
                parent, ex, ey, ez, x1, y1, z1, w1 = entry
            else:
                stamps = cache.stamps
                n = len(stamps)
                lo = cache.start
                if t:
                    i = bisect_left(stamps, t, lo)
                    if i < n and stamps[i] == t:
                        parent, ex, ey, ez, x1, y1, z1, w1 = cache.data[i]
                    elif lo < i < n:
                        data = cache.data
                        a = data[i - 1]
                        b = data[i]
                        parent = a[0]
                        if parent != b[0]:  # re-parented between the stamps: no interpolation
                            _, ex, ey, ez, x1, y1, z1, w1 = a
                        else:
                            s0 = stamps[i - 1]
                            r = (t - s0) / (stamps[i] - s0)
                            _, ax, ay, az, ax1, ay1, az1, aw1 = a
                            _, bx, by, bz, bx1, by1, bz1, bw1 = b
                            ex = ax + (bx - ax) * r
                            ey = ay + (by - ay) * r
                            ez = az + (bz - az) * r
                            dot = ax1 * bx1 + ay1 * by1 + az1 * bz1 + aw1 * bw1
                            adot = dot if dot >= 0.0 else -dot
                            if adot < 0.9999999999999998:
                                theta = acos(adot)
                                d = sin(theta)
                                w0 = sin((1.0 - r) * theta) / d
                                wb = sin(r * theta) / d
                                if dot < 0.0:
                                    wb = -wb
                                x1 = ax1 * w0 + bx1 * wb
                                y1 = ay1 * w0 + by1 * wb
                                z1 = az1 * w0 + bz1 * wb
                                w1 = aw1 * w0 + bw1 * wb
                            else:
                                x1, y1, z1, w1 = ax1, ay1, az1, aw1
                    else:
                        return frame, (tx, ty, tz, qx, qy, qz, qw), cache._explain(t)
                elif n > lo:
                    parent, ex, ey, ez, x1, y1, z1, w1 = cache.data[-1]
                else:
                    return frame, (tx, ty, tz, qx, qy, qz, qw), ""
            # --- acc = link * acc ---
            cx = 2.0 * (y1 * tz - z1 * ty)
            cy = 2.0 * (z1 * tx - x1 * tz)
            cz = 2.0 * (x1 * ty - y1 * tx)
            tx, ty, tz = (
                ex + tx + w1 * cx + (y1 * cz - z1 * cy),
                ey + ty + w1 * cy + (z1 * cx - x1 * cz),
                ez + tz + w1 * cz + (x1 * cy - y1 * cx),
            )
            qx, qy, qz, qw = (
                w1 * qx + x1 * qw + y1 * qz - z1 * qy,
                w1 * qy - x1 * qz + y1 * qw + z1 * qx,
                w1 * qz + x1 * qy - y1 * qx + z1 * qw,
                w1 * qw - x1 * qx - y1 * qy - z1 * qz,
            )
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop()

    def lookup_ns(self, target: str, source: str, t: int) -> tuple[int, tuple[float, ...]]:
        """``(stamp_ns, (tx, ty, tz, qx, qy, qz, qw))`` of ``T_target_source`` at ``t`` ns."""
        if target == source:
            # tf2 answers the identity for any name, even unknown, empty or with a '/'
            if t == 0:
                fid = self._ids.get(target)
                cache = self._caches[fid] if fid is not None else None
                t = cache.latest()[0] if cache is not None else 0
            return t, _IDENTITY
        target_id = self._validate("lookupTransform argument target_frame", target)
        source_id = self._validate("lookupTransform argument source_frame", source)
        if t == 0:
            t = self.latest_common_time_ns(target_id, source_id)
        return t, self._walk(target_id, source_id, t)

    def lookup(self, target: str, source: str, time: Any = 0) -> StampedTransform:
        """The pose of ``source`` in ``target`` at ``time`` (0 or None: the latest common time).

        tf2's ``lookupTransform``: ``target == source`` is the identity (for any name);
        otherwise both frames are validated, target first.

        Raises:
            InvalidArgumentException: empty frame id or one starting with ``/``.
            LookupException: a frame is unknown (or the tree has a loop).
            ConnectivityException: the frames are in different trees.
            ExtrapolationException: some link on the path has no data at ``time``.
        """
        t = to_ns(time)
        ids = self._ids
        target_id = ids.get(target)
        source_id = ids.get(source)
        if t and target_id is not None and source_id is not None and target_id != source_id:
            # fast path: known, distinct frames at a given time
            tx, ty, tz, qx, qy, qz, qw = self._walk(target_id, source_id, t)
            return StampedTransform(target, source, t, (tx, ty, tz), (qx, qy, qz, qw))
        stamp, v = self.lookup_ns(target, source, t)
        return StampedTransform(target, source, stamp, (v[0], v[1], v[2]), (v[3], v[4], v[5], v[6]))

    def lookup_full(
        self,
        target: str,
        target_time: Any,
        source: str,
        source_time: Any,
        fixed_frame: str,
    ) -> StampedTransform:
        """Time travel: ``source`` at ``source_time`` seen from ``target`` at ``target_time``.

        Goes through ``fixed_frame``, a frame assumed not to move between the two
        times (``world``, ``map``, ``odom``): ``T_target(tt)_source(ts) =
        T_target_fixed(tt) * T_fixed_source(ts)``. The result is stamped as the
        target -> fixed lookup (``target_time``, or the latest common time for 0).

        As tf2: the three frames are validated first (target, source, fixed), then
        ``source`` is looked up in ``fixed`` at ``source_time``, then ``fixed`` in
        ``target`` at ``target_time``; the first failure is raised.
        """
        t_ns = to_ns(target_time, what="target_time")
        s_ns = to_ns(source_time, what="source_time")
        self._validate("lookupTransform argument target_frame", target)
        self._validate("lookupTransform argument source_frame", source)
        self._validate("lookupTransform argument fixed_frame", fixed_frame)
        _, b = self.lookup_ns(fixed_frame, source, s_ns)
        stamp, a = self.lookup_ns(target, fixed_frame, t_ns)
        v = _matrix_sign(compose(a, b))
        return StampedTransform(target, source, stamp, (v[0], v[1], v[2]), (v[3], v[4], v[5], v[6]))

    def _can_walk(self, target_id: int, source_id: int, t: int) -> tuple[bool, str]:
        if target_id == source_id:
            return True, ""
        try:
            self._walk(target_id, source_id, t or self.latest_common_time_ns(target_id, source_id))
        except (LookupException, ConnectivityException, ExtrapolationException) as exc:
            return False, exc.tf2_message
        return True, ""

    def _refused_by_can(self, function: str, frame: str) -> bool:
        """tf2's canTransform refuses empty and ``/``-prefixed ids with a logged warning only."""
        if frame != "" and not frame.startswith("/"):
            return False
        try:
            self._validate(function, frame)
        except InvalidArgumentException as exc:
            _LOG.warning("%s", exc.tf2_message)
        return True

    def can_lookup(self, target: str, source: str, time: Any = 0) -> tuple[bool, str]:
        """``(possible, why not)`` for :meth:`lookup`; never raises for frames or times.

        ``why not`` is the first line of the exception :meth:`lookup` would raise:
        tf2's text, as tf's ``tf_echo`` prints it. (:meth:`can_transform_core` gives
        tf2's ``canTransform`` string instead.)
        """
        if target == source:
            return True, ""
        try:
            self.lookup_ns(target, source, to_ns(time))
        except (
            LookupException,
            ConnectivityException,
            ExtrapolationException,
            InvalidArgumentException,
        ) as exc:
            return False, exc.tf2_message
        return True, ""

    def can_transform_core(self, target: str, source: str, time: Any = 0) -> tuple[bool, str]:
        """``(possible, why not)`` for a lookup, as tf2's ``canTransform`` (tf2_py's name).

        ``why not`` is tf2's error string: the text of the lookup's exception, except
        that unknown frames read ``canTransform: target_frame X does not exist.`` and
        that empty or ``/``-prefixed frames give ``""`` (their warning is logged).
        Never raises for frames.
        """
        if target == source:
            return True, ""
        try:
            t = to_ns(time)
        except InvalidArgumentException as exc:
            return False, str(exc)
        if self._refused_by_can("canTransform argument target_frame", target):
            return False, ""
        if self._refused_by_can("canTransform argument source_frame", source):
            return False, ""
        target_id = self._ids.get(target)
        source_id = self._ids.get(source)
        if target_id is None or source_id is None:
            missing = []
            if target_id is None:
                missing.append(f"canTransform: target_frame {target} does not exist.")
            if source_id is None:
                missing.append(f"canTransform: source_frame {source} does not exist.")
            return False, " ".join(missing)
        return self._can_walk(target_id, source_id, t)

    def can_transform_full_core(
        self,
        target: str,
        target_time: Any,
        source: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[bool, str]:
        """``(possible, why not)`` for :meth:`lookup_full`, as tf2's ``canTransform`` (fixed frame).

        Checks target -> fixed at ``target_time``, then fixed -> source at
        ``source_time``. Unknown frames are reported as tf2 (Noetic's last release)
        words it, ``fixed_frame: F`` + ``does not exist.`` included.
        """
        try:
            t_ns = to_ns(target_time, what="target_time")
            s_ns = to_ns(source_time, what="source_time")
        except InvalidArgumentException as exc:
            return False, str(exc)
        if (
            self._refused_by_can("canTransform argument target_frame", target)
            or self._refused_by_can("canTransform argument source_frame", source)
            or self._refused_by_can("canTransform argument fixed_frame", fixed_frame)
        ):
            return False, ""
        ids = self._ids
        target_id, source_id, fixed_id = ids.get(target), ids.get(source), ids.get(fixed_frame)
        if target_id is None or source_id is None or fixed_id is None:
            missing = []
            if target_id is None:
                missing.append(f"canTransform: target_frame {target} does not exist.")
            if source_id is None:
                missing.append(f"canTransform: source_frame {source} does not exist.")
            if fixed_id is None:
                missing.append(f"fixed_frame: {fixed_frame}does not exist.")
            return False, " ".join(missing)
        ok, why = self._can_walk(target_id, fixed_id, t_ns)
        if not ok:
            return ok, why
        return self._can_walk(fixed_id, source_id, s_ns)

    def get_latest_common_time(self, target: str, source: str) -> int:
        """The latest common time of two frames, integer nanoseconds (0: all static).

        As tf2_py's ``get_latest_common_time``: both frames must exist (a frame asked
        against itself too); its newest stamp when ``target == source``.

        Raises:
            InvalidArgumentException: an empty frame id or one starting with ``/``.
            LookupException: a frame is unknown.
            TransformException: the frames are in different trees, or the tree has a
                loop (tf2 raises this base class here, not ConnectivityException).
        """
        target_id = self._validate("get_latest_common_time", target)
        source_id = self._validate("get_latest_common_time", source)
        try:
            return self.latest_common_time_ns(target_id, source_id)
        except (ConnectivityException, LookupException) as exc:
            raise TransformException(exc.tf2_message, exc.detail) from None

    def get_parent(self, frame: str, time: Any = 0) -> str | None:
        """The parent of ``frame`` at ``time`` (0: latest), or ``None`` for a root."""
        fid = self._validate("getParent argument frame", frame)
        cache = self._caches[fid]
        if cache is None:
            return None
        try:
            return self._names[cache.gather(to_ns(time))[0]]
        except NoData:
            return None

    # --- introspection --------------------------------------------------------

    def frames_info(self, current_time: Any = None) -> dict[str, dict[str, Any]]:
        """Per child frame: parent, broadcaster, rate (Hz), newest/oldest stamps (s), buffer length.

        The same fields as tf2's ``allFramesAsYAML`` (what ``view_frames`` draws).
        """
        now = to_ns(current_time) / 1e9 if current_time is not None else 0.0
        info: dict[str, dict[str, Any]] = {}
        for fid in range(1, len(self._names)):
            cache = self._caches[fid]
            if cache is None or len(cache) == 0:
                continue
            latest, parent = cache.latest()
            oldest = cache.oldest_stamp()
            span = (latest - oldest) / 1e9
            entry: dict[str, Any] = {
                "parent": self._names[parent],
                "broadcaster": self._authority.get(fid, ""),
                "rate": len(cache) / max(span, 0.0001),
                "most_recent_transform": latest / 1e9,
                "oldest_transform": oldest / 1e9,
                "buffer_length": span,
                "static": cache.static,
            }
            if now > 0:
                entry["transform_delay"] = now - latest / 1e9
            info[self._names[fid]] = entry
        return info

    def all_frames_as_yaml(self, current_time: Any = None) -> str:
        """tf2's ``allFramesAsYAML``: one block per child frame (``[]`` when empty)."""
        info = self.frames_info(current_time)
        if not info:
            return "[]"
        lines = []
        for name, entry in info.items():
            lines.append(f"{name}: ")
            lines.append(f"  parent: '{entry['parent']}'")
            lines.append(f"  broadcaster: '{entry['broadcaster']}'")
            lines.append(f"  rate: {entry['rate']:.3f}")
            lines.append(f"  most_recent_transform: {entry['most_recent_transform']:.3f}")
            lines.append(f"  oldest_transform: {entry['oldest_transform']:.3f}")
            if "transform_delay" in entry:
                lines.append(f"  transform_delay: {entry['transform_delay']:.3f}")
            lines.append(f"  buffer_length: {entry['buffer_length']:.3f}")
        return "\n".join(lines) + "\n"

    def all_frames_as_string(self) -> str:
        """tf2's ``allFramesAsString``: ``Frame X exists with parent Y.`` per child frame.

        A frame whose data was cleared reads ``exists with parent NO_PARENT.``, as in tf2.
        """
        lines = []
        for fid in range(1, len(self._names)):
            cache = self._caches[fid]
            if cache is None:
                continue
            lines.append(
                f"Frame {self._names[fid]} exists with parent {self._names[cache.latest()[1]]}."
            )
        return "\n".join(lines) + ("\n" if lines else "")
