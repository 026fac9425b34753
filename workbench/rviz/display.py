"""What every RViz display shares: a topic, a message queue, statuses, and tf into the fixed frame.

A display subscribes on :meth:`Display.attach`; messages are queued by the bus's
threads and drawn by :meth:`Display.update`, which the :class:`~workbench.rviz.RViz`
calls from one thread. Statuses read like RViz's status tree: ``{"Topic": "OK"}``,
``{"Transform": "No transform from [laser] to fixed frame [map]: ..."}``.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from dataclasses import dataclass
from typing import Any

#: How long a message whose frame tf cannot place yet waits (RViz's message filter), s.
TF_WAIT = 1.0


@dataclass
class Context:
    """What a display draws with: Meshcat, the tf buffer, the fixed frame and the time."""

    meshcat: Any
    buffer: Any
    fixed_frame: str
    node: Any
    prefix: str
    resolve_mesh: Any = None

    def transform(self, frame: str, stamp: Any = 0) -> Any:
        """``X_FS``: frame ``frame`` in the fixed frame at ``stamp`` (0: latest), a RigidTransform.

        Raises:
            TransformException: tf cannot place ``frame`` (RViz shows it as the status).
        """
        from workbench.spatial import rigid_transform

        frame = frame.lstrip("/") or self.fixed_frame
        if frame == self.fixed_frame:
            return rigid_transform([0.0, 0.0, 0.0])
        with self.buffer._lock:
            st = self.buffer.lookup(self.fixed_frame, frame, stamp)
        return rigid_transform(st.translation, quaternion=st.rotation)


class Display:
    """Base of the displays. Subclasses set ``message_type`` and implement ``draw``."""

    message_type: str = ""
    default_topic: str = ""
    #: RViz's name for the display class (the default display name).
    class_name: str = ""
    #: Draw every message that arrived (sensor streams, as RViz processes each scan),
    #: not only the newest.
    draw_every: bool = False

    def __init__(
        self, topic: str | None = None, name: str | None = None, queue_size: int = 10
    ) -> None:
        self.topic = topic if topic is not None else self.default_topic
        self.name = name or self.class_name or type(self).__name__
        self.queue_size = queue_size
        self.status: dict[str, str] = {}
        self.enabled = True
        self._queue: deque[tuple[float, Any]] = deque(maxlen=queue_size or None)
        self._lock = threading.Lock()
        self._subscription: Any = None
        self.received = 0
        self.drawn = 0

    @property
    def path(self) -> str:
        return self.name.replace("/", "_").replace(" ", "_")

    def attach(self, node: Any) -> None:
        """Subscribe (topic displays) and report the topic status as RViz does."""
        if not self.topic or not self.message_type:
            return
        from workbench.errors import WorkbenchError

        try:
            self._subscription = node.create_subscription(
                self.topic, self.message_type, self._on_message, queue_size=self.queue_size
            )
        except WorkbenchError as error:
            # RViz: "Error subscribing: ..." (a topic of another type is the usual one)
            self.status["Topic"] = f"Error subscribing: {error.message}"
            return
        self.status["Topic"] = "OK"

    def _on_message(self, message: Any) -> None:
        with self._lock:
            self._queue.append((time.monotonic(), message))
            self.received += 1

    def take(self) -> list[tuple[float, Any]]:
        """The queued messages (oldest first), removed from the queue."""
        with self._lock:
            items = list(self._queue)
            self._queue.clear()
        return items

    def requeue(self, items: list[tuple[float, Any]], *, expire: bool = True) -> None:
        """Put messages tf cannot place yet back in front of the queue, oldest first (for up
        to ``TF_WAIT`` s, or with ``expire`` False until newer ones push them out)."""
        now = time.monotonic()
        kept = [item for item in items if not expire or now - item[0] < TF_WAIT]
        with self._lock:
            waiting = kept + list(self._queue)
            self._queue.clear()
            self._queue.extend(waiting)  # a full queue drops the oldest, as a subscriber's

    def update(self, context: Context) -> None:
        """Draw what arrived (the default: the newest message only)."""
        items = self.take()
        if not items:
            return
        if not self.draw_every:
            items = items[-1:]
        for k, (arrived, message) in enumerate(items):
            outcome = self._draw_one(context, message)
            if outcome == "held":  # newer than tf: held with everything after it, silently
                self.requeue(items[k:], expire=False)
                return
            if outcome == "failed" and time.monotonic() - arrived < TF_WAIT:
                self.requeue(items[k:])
                return

    def _draw_one(self, context: Context, message: Any) -> str:
        """``"drawn"``, ``"held"`` (tf has not reached its stamp: tf2's MessageFilter holds
        such a message without a status, as a paused simulation's last scan in RViz) or
        ``"failed"`` (the Transform status says why)."""
        from workbench.tf.exceptions import TransformException

        try:
            self.draw(context, message)
        except TransformException as error:
            if "into the future" in str(error):
                return "held"
            frame = getattr(getattr(message, "header", None), "frame_id", "?")
            self.status["Transform"] = (
                f"No transform from [{frame}] to fixed frame [{context.fixed_frame}]: {error}"
            )
            return "failed"
        self.status.pop("Transform", None)
        self.drawn += 1
        return "drawn"

    def draw(self, context: Context, message: Any) -> None:
        """Draw one message (subclasses)."""
        raise NotImplementedError

    def clear(self, context: Context) -> None:
        """Remove what the display drew."""
        context.meshcat.Delete(f"{context.prefix}/{self.path}")

    def close(self) -> None:
        if self._subscription is not None:
            self._subscription.unregister()
            self._subscription = None
