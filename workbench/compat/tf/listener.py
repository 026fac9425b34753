"""tf's ``Transformer``, ``TransformListener`` and ``TransformBroadcaster`` with camelCase names."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.tf import transformations as tft
from workbench.tf.buffer import Buffer, do_transform, stamp_msg, to_msg
from workbench.tf.core import StampedTransform
from workbench.tf.exceptions import InvalidArgumentException

#: One /tf publisher per node: the lab's broadcaster builds a TransformBroadcaster in
#: every callback, which in rospy reuses the node's publisher.
_BROADCASTERS: dict[int, Any] = {}


def _strip(frame: str) -> str:
    if not isinstance(frame, str):
        raise InvalidArgumentException(f"frame ids are strings, got {type(frame).__name__}")
    return frame.lstrip("/")


def _time_msg(ns: int) -> Any:
    return stamp_msg(ns)


def current_node() -> Any:
    """The node of ``rospy.init_node`` (of this thread or callback), else an anonymous one."""
    from workbench.compat import rospy

    node = rospy._node()
    if node is not None:
        return node
    from workbench.bus import Node

    return Node("tf", anonymous=True)


class Transformer:
    """tf's ``Transformer``: a buffer with tf's method names (no bus).

    Args:
        interpolating: Accepted for compatibility (tf always interpolates).
        cache_time: History kept per frame (seconds or a Duration), default 10 s.
    """

    def __init__(self, interpolating: bool = True, cache_time: Any = None) -> None:
        self._buffer = Buffer(cache_time=cache_time)

    # --- storing -------------------------------------------------------------------

    def setTransform(self, transform: Any, authority: str = "default_authority") -> bool:  # noqa: N802
        """Store a TransformStamped (leading '/' in frame ids is stripped)."""
        return self._buffer.set_transform(transform, authority)

    def clear(self) -> None:
        self._buffer.clear()

    # --- queries -------------------------------------------------------------------

    def _lookup(self, target: str, source: str, time: Any) -> StampedTransform:
        return self._buffer.lookup(_strip(target), _strip(source), time)

    def lookupTransform(  # noqa: N802
        self, target_frame: str, source_frame: str, time: Any
    ) -> tuple[list[float], list[float]]:
        """``([x, y, z], [qx, qy, qz, qw])``: the pose of ``source_frame`` in ``target_frame``.

        ``time`` 0 (``rospy.Time(0)``) means the latest common time.
        """
        st = self._lookup(target_frame, source_frame, time)
        return list(st.translation), list(st.rotation)

    def lookupTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[list[float], list[float]]:
        """Time travel: ``source_frame`` at ``source_time`` in ``target_frame`` at ``target_time``."""
        st = self._buffer.lookup_full(
            _strip(target_frame),
            target_time,
            _strip(source_frame),
            source_time,
            _strip(fixed_frame),
        )
        return list(st.translation), list(st.rotation)

    def canTransform(self, target_frame: str, source_frame: str, time: Any) -> bool:  # noqa: N802
        return self._buffer.can_lookup(_strip(target_frame), _strip(source_frame), time)[0]

    def canTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> bool:
        return bool(
            self._buffer.can_transform_full(
                _strip(target_frame),
                target_time,
                _strip(source_frame),
                source_time,
                _strip(fixed_frame),
            )
        )

    def waitForTransform(  # noqa: N802
        self,
        target_frame: str,
        source_frame: str,
        time: Any,
        timeout: Any,
        polling_sleep_duration: Any = None,
    ) -> None:
        """Block until the transform is available or ``timeout`` passes (then ``tf.Exception``)."""
        self._buffer._wait_or_raise(_strip(target_frame), _strip(source_frame), time, timeout)

    def waitForTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any,
        polling_sleep_duration: Any = None,
    ) -> None:
        target, source, fixed = _strip(target_frame), _strip(source_frame), _strip(fixed_frame)
        self._buffer._wait_or_raise(target, fixed, target_time, timeout)
        self._buffer._wait_or_raise(fixed, source, source_time, timeout)

    def getLatestCommonTime(self, source_frame: str, dest_frame: str) -> Any:  # noqa: N802
        """The newest time both frames have data for (a Time; 0 if every link is static)."""
        return _time_msg(
            self._buffer.get_latest_common_time(_strip(source_frame), _strip(dest_frame))
        )

    def frameExists(self, frame_id: str) -> bool:  # noqa: N802
        return self._buffer.frame_exists(_strip(frame_id))

    def getFrameStrings(self) -> list[str]:  # noqa: N802
        return self._buffer.get_frame_strings()

    def allFramesAsString(self) -> str:  # noqa: N802
        return self._buffer.all_frames_as_string()

    def allFramesAsYAML(self) -> str:  # noqa: N802
        return self._buffer.all_frames_as_yaml()

    def allFramesAsDot(self) -> str:  # noqa: N802
        from workbench.tf.frames import frames_dot

        return frames_dot(self._buffer.frames_info())

    def getTFPrefix(self) -> str:  # noqa: N802
        return ""


class TransformerROS(Transformer):
    """Adds tf's message and matrix helpers (``transformPoint``, ``asMatrix`` ...)."""

    def fromTranslationRotation(  # noqa: N802
        self, translation: Sequence[float], rotation: Sequence[float]
    ) -> np.ndarray:
        """The 4x4 matrix of a translation and a quaternion ``[x, y, z, w]``."""
        return np.dot(tft.translation_matrix(translation), tft.quaternion_matrix(rotation))

    def asMatrix(self, target_frame: str, hdr: Any) -> np.ndarray:  # noqa: N802
        """The 4x4 matrix taking data in ``hdr.frame_id`` at ``hdr.stamp`` into ``target_frame``."""
        translation, rotation = self.lookupTransform(target_frame, hdr.frame_id, hdr.stamp)
        return self.fromTranslationRotation(translation, rotation)

    def _transform_msg(self, target_frame: str, msg: Any) -> Any:
        header = msg.header
        st = self._lookup(target_frame, header.frame_id, header.stamp)
        out = do_transform(msg, to_msg(st))
        out.header.stamp = header.stamp
        return out

    def transformPoint(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        """A PointStamped expressed in ``target_frame`` (at the point's stamp; 0 = latest)."""
        return self._transform_msg(target_frame, ps)

    def transformPose(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        return self._transform_msg(target_frame, ps)

    def transformVector3(self, target_frame: str, v3s: Any) -> Any:  # noqa: N802
        return self._transform_msg(target_frame, v3s)

    def transformQuaternion(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        return self._transform_msg(target_frame, ps)


class TransformListener(TransformerROS):
    """tf's ``TransformListener``: a TransformerROS filled from ``/tf`` and ``/tf_static``.

    Args:
        interpolating: Accepted for compatibility.
        cache_time: History kept per frame (seconds or Duration), default 10 s.
        node: The node to subscribe with; default the ``rospy.init_node`` node.
    """

    def __init__(
        self, interpolating: bool = True, cache_time: Any = None, node: Any = None
    ) -> None:
        super().__init__(interpolating, cache_time)
        from workbench.tf.listener import TransformListener as _Listener

        self._listener = _Listener(self._buffer, node if node is not None else current_node())


class TransformBroadcaster:
    """tf's ``TransformBroadcaster``: ``sendTransform(translation, rotation, time, child, parent)``."""

    def __init__(self, queue_size: int = 100, node: Any = None) -> None:
        from workbench.tf.broadcaster import TransformBroadcaster as _Broadcaster

        node = node if node is not None else current_node()
        cached = _BROADCASTERS.get(id(node))
        if cached is None or cached.node is not node or cached.pub.closed:
            cached = _Broadcaster(node, queue_size)
            _BROADCASTERS[id(node)] = cached
        self._broadcaster = cached

    def sendTransform(  # noqa: N802
        self,
        translation: Sequence[float],
        rotation: Sequence[float],
        time: Any,
        child: str,
        parent: str,
    ) -> None:
        """Publish the pose of ``child`` in ``parent`` (metres; quaternion x, y, z, w) at ``time``."""
        from workbench.tf.broadcaster import make_transform

        self._broadcaster.send_transform(
            make_transform(_strip(parent), _strip(child), translation, rotation, time)
        )

    def sendTransformMessage(self, transform: Any) -> None:  # noqa: N802
        """Publish a TransformStamped (or a list of them)."""
        self._broadcaster.send_transform(transform)
