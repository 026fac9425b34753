"""Broadcasters: ``tf2_msgs/TFMessage`` on ``/tf`` and, latched, on ``/tf_static``."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from workbench.tf.exceptions import InvalidArgumentException


def _node_or_default(node: Any, name: str) -> Any:
    if node is not None:
        return node
    from workbench.bus import Node

    return Node(name, anonymous=True)


def _as_list(transform: Any) -> list[Any]:
    items = list(transform) if isinstance(transform, (list, tuple)) else [transform]
    for item in items:
        if getattr(item, "_type", None) != "geometry_msgs/TransformStamped":
            raise InvalidArgumentException(
                "sendTransform needs geometry_msgs/TransformStamped messages, got "
                f"{type(item).__name__}",
                hint="build one with workbench.msgs.geometry_msgs.TransformStamped",
            )
    return items


class TransformBroadcaster:
    """Publishes transforms on ``/tf`` (``tf2_ros.TransformBroadcaster``).

    Args:
        node: The node that publishes (its name is the broadcaster ``view_frames``
            shows); ``None`` creates an anonymous node on the default bus.
        queue_size: Publisher queue size.
    """

    def __init__(self, node: Any = None, queue_size: int = 100) -> None:
        from workbench.msgs.tf2_msgs import TFMessage

        self.node = _node_or_default(node, "tf_broadcaster")
        self._message = TFMessage
        self.pub = self.node.create_publisher("/tf", TFMessage, queue_size=queue_size)

    def send_transform(self, transform: Any) -> None:
        """Publish one TransformStamped or a list of them in one TFMessage."""
        msg = self._message()
        msg.transforms = _as_list(transform)
        self.pub.publish(msg)

    sendTransform = send_transform  # noqa: N815 - tf2_ros's ROS 1 name


class StaticTransformBroadcaster:
    """Publishes transforms that never change on latched ``/tf_static``.

    Like tf2_ros, it remembers every transform it was given (a new one for the
    same child frame replaces the old) and republishes the whole set, so a
    listener that connects later receives all of them.
    """

    def __init__(self, node: Any = None) -> None:
        from workbench.msgs.tf2_msgs import TFMessage

        self.node = _node_or_default(node, "static_tf_broadcaster")
        self._message = TFMessage
        self._by_child: dict[str, Any] = {}
        self.pub = self.node.create_publisher("/tf_static", TFMessage, queue_size=100, latch=True)

    def send_transform(self, transform: Any) -> None:
        """Add or replace static transforms and republish the whole set."""
        for item in _as_list(transform):
            self._by_child[item.child_frame_id] = item
        msg = self._message()
        msg.transforms = list(self._by_child.values())
        self.pub.publish(msg)

    sendTransform = send_transform  # noqa: N815 - tf2_ros's ROS 1 name


def make_transform(
    parent: str,
    child: str,
    translation: Iterable[float],
    rotation: Iterable[float],
    stamp: Any = None,
) -> Any:
    """A ``geometry_msgs/TransformStamped``: ``child`` at ``translation`` (m), ``rotation`` (xyzw) in ``parent``.

    Args:
        stamp: A Time, seconds, or ``None`` for time 0.
    """
    from workbench.msgs.geometry_msgs import TransformStamped
    from workbench.tf.buffer import stamp_msg
    from workbench.tf.timeconv import to_ns

    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.header.stamp = stamp_msg(to_ns(stamp, what="stamp"))
    msg.child_frame_id = child
    t = msg.transform.translation
    t.x, t.y, t.z = (float(v) for v in translation)
    r = msg.transform.rotation
    r.x, r.y, r.z, r.w = (float(v) for v in rotation)
    return msg
