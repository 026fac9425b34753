"""``TransformListener``: fills a :class:`~workbench.tf.Buffer` from ``/tf`` and ``/tf_static``."""

from __future__ import annotations

from typing import Any

from workbench.tf.buffer import Buffer


class TransformListener:
    """Subscribes to ``/tf`` and ``/tf_static`` and stores every transform in ``buffer``.

    Args:
        buffer: The buffer to fill (``tf2_ros.TransformListener(buffer)``).
        node: The node that subscribes; ``None`` creates an anonymous node on the
            default bus.
        queue_size: Subscription queue size (messages kept while busy).

    The buffer's waiting lookups measure their timeout on the bus clock (wall or
    simulated time). On a bus that runs callbacks only when stepped
    (``Bus(threaded=False)``), a waiting lookup steps the bus itself.
    """

    def __init__(self, buffer: Buffer, node: Any = None, queue_size: int = 100) -> None:
        from workbench.msgs.tf2_msgs import TFMessage

        if node is None:
            from workbench.bus import Node

            node = Node("tf_listener", anonymous=True)
        self.buffer = buffer
        self.node = node
        bus = node.bus
        buffer.use_clock(bus.clock.now_ns)
        if not bus.threaded:
            buffer.use_spinner(lambda seconds: bus.spin_once(seconds))
        self.tf_sub = node.create_subscription("/tf", TFMessage, self._on_tf, queue_size=queue_size)
        self.tf_static_sub = node.create_subscription(
            "/tf_static", TFMessage, self._on_tf_static, queue_size=queue_size
        )

    @staticmethod
    def _authority(msg: Any) -> str:
        header = getattr(msg, "_connection_header", None)
        if not isinstance(header, dict):
            from workbench.bus import connection_header  # the publisher of the message at hand

            header = connection_header()
        if isinstance(header, dict) and header.get("callerid"):
            return str(header["callerid"])
        return "default_authority"

    def _on_tf(self, msg: Any) -> None:
        who = self._authority(msg)
        for transform in msg.transforms:
            self.buffer.set_transform(transform, who)

    def _on_tf_static(self, msg: Any) -> None:
        who = self._authority(msg)
        for transform in msg.transforms:
            self.buffer.set_transform_static(transform, who)

    def unregister(self) -> None:
        """Stop listening."""
        self.tf_sub.unregister()
        self.tf_static_sub.unregister()
