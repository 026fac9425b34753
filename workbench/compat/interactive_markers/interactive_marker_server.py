"""``interactive_markers.interactive_marker_server`` for the lab's rospy scripts.

``from workbench.compat.interactive_markers.interactive_marker_server import *``
gives :class:`InteractiveMarkerServer` with the methods of ROS 1's Python
server (``insert``, ``setPose``, ``erase``, ``clear``, ``setCallback``,
``applyChanges``, ``get``, ``empty``, ``size``) speaking the same protocol on
the bus, so any client (RViz, ``workbench rviz``, a test) works with it:

* ``<topic_ns>/update`` (``visualization_msgs/InteractiveMarkerUpdate``): the
  changes of each ``applyChanges`` (type UPDATE), and a KEEP_ALIVE every 0.5 s;
* ``<topic_ns>/update_full`` (``InteractiveMarkerInit``, latched): all markers
  with the sequence number, republished after each change;
* ``<topic_ns>/feedback`` (``InteractiveMarkerFeedback``, subscribed): a
  POSE_UPDATE moves the marker (the change is sent with the next
  ``applyChanges``), then the marker's callback for that event type runs
  (or its default callback).

As in ROS, feedback from a second client within a second of the first one's is
ignored; feedback for a marker the server does not have is ignored with a
one-line warning.
"""

from __future__ import annotations

import copy
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from workbench.errors import BusError
from workbench.msgs.std_msgs import Header
from workbench.msgs.visualization_msgs import (
    InteractiveMarker,
    InteractiveMarkerFeedback,
    InteractiveMarkerInit,
    InteractiveMarkerPose,
    InteractiveMarkerUpdate,
)

__all__ = ["InteractiveMarkerServer"]

FULL_UPDATE, POSE_UPDATE, ERASE = 0, 1, 2
KEEP_ALIVE_PERIOD = 0.5


@dataclass
class _MarkerContext:
    int_marker: Any
    default_feedback_cb: Callable[[Any], Any] | None = None
    feedback_cbs: dict[int, Callable[[Any], Any]] = field(default_factory=dict)
    last_feedback: float = -1e9
    last_client_id: str = ""


@dataclass
class _UpdateContext:
    update_type: int
    int_marker: Any
    default_feedback_cb: Callable[[Any], Any] | None = None
    feedback_cbs: dict[int, Callable[[Any], Any]] = field(default_factory=dict)


class InteractiveMarkerServer:
    """An interactive marker server on ``topic_ns`` (e.g. ``"simple_marker"``).

    Args:
        topic_ns: Namespace of the three topics.
        server_id: Appended to the node name to make the server id.
        q_size: Feedback queue size.
        node: A ``workbench.bus.Node`` (default: the rospy shim's node, or a new one).
    """

    DEFAULT_FEEDBACK_CB = 255

    def __init__(
        self, topic_ns: str, server_id: str = "", q_size: int = 100, node: Any = None
    ) -> None:
        if node is None:
            node = _default_node()
        self.node = node
        self.topic_ns = topic_ns
        self.server_id = f"{node.name}/{server_id}" if server_id else node.name
        self.seq_num = 0
        self.mutex = threading.RLock()
        self.marker_contexts: dict[str, _MarkerContext] = {}
        self.pending_updates: dict[str, _UpdateContext] = {}
        self.update_pub = node.create_publisher(
            f"{topic_ns}/update", InteractiveMarkerUpdate, queue_size=100
        )
        self.init_pub = node.create_publisher(
            f"{topic_ns}/update_full", InteractiveMarkerInit, queue_size=100, latch=True
        )
        self.feedback_sub = node.create_subscription(
            f"{topic_ns}/feedback",
            InteractiveMarkerFeedback,
            self.processFeedback,
            queue_size=q_size,
        )
        self.keep_alive = node.create_timer(KEEP_ALIVE_PERIOD, lambda event: self._keep_alive())
        self.publishInit()

    # --- the ROS API ------------------------------------------------------------------

    def shutdown(self) -> None:
        """Erase every marker, publish that, and stop."""
        self.clear()
        self.applyChanges()
        self.keep_alive.shutdown()
        self.feedback_sub.unregister()

    def insert(
        self, marker: Any, feedback_cb: Any = -1, feedback_type: int = DEFAULT_FEEDBACK_CB
    ) -> None:
        """Add or replace ``marker`` (sent with the next applyChanges)."""
        if not marker.name:
            raise BusError(
                "an interactive marker needs a name", hint="set marker.name before insert()"
            )
        with self.mutex:
            update = self.pending_updates.get(marker.name)
            if update is None:
                update = _UpdateContext(FULL_UPDATE, marker)
                self.pending_updates[marker.name] = update
            update.update_type = FULL_UPDATE
            update.int_marker = marker
        if feedback_cb != -1:
            self.setCallback(marker.name, feedback_cb, feedback_type)

    def setPose(self, name: str, pose: Any, header: Any = None) -> bool:  # noqa: N802 - ROS's name
        """Move marker ``name`` (sent with the next applyChanges); False if it is unknown."""
        with self.mutex:
            context = self.marker_contexts.get(name)
            update = self.pending_updates.get(name)
            if context is None and update is None:
                return False
            if header is None or not header.frame_id:
                header = (context.int_marker if context is not None else update.int_marker).header  # type: ignore[union-attr]
            self._do_set_pose(update, name, pose, header)
            return True

    def erase(self, name: str) -> bool:
        """Remove marker ``name`` (sent with the next applyChanges)."""
        with self.mutex:
            self.pending_updates[name] = _UpdateContext(ERASE, InteractiveMarker(name=name))
            return True

    def clear(self) -> None:
        """Remove every marker (sent with the next applyChanges)."""
        with self.mutex:
            self.pending_updates = {}
            for name in list(self.marker_contexts):
                self.erase(name)

    def setCallback(  # noqa: N802 - ROS's name
        self, name: str, feedback_cb: Any, feedback_type: int = DEFAULT_FEEDBACK_CB
    ) -> bool:
        """Call ``feedback_cb(feedback)`` for ``feedback_type`` events of marker ``name``."""
        with self.mutex:
            context = self.marker_contexts.get(name)
            update = self.pending_updates.get(name)
            if context is None and update is None:
                return False
            for holder in (context, update):
                if holder is None:
                    continue
                if feedback_type == self.DEFAULT_FEEDBACK_CB:
                    holder.default_feedback_cb = feedback_cb
                elif feedback_cb:
                    holder.feedback_cbs[feedback_type] = feedback_cb
                else:
                    holder.feedback_cbs.pop(feedback_type, None)
            return True

    def applyChanges(self) -> None:  # noqa: N802 - ROS's name
        """Send every change since the last call as one update, and republish the full state."""
        with self.mutex:
            if not self.pending_updates:
                return
            update = InteractiveMarkerUpdate(type=InteractiveMarkerUpdate.UPDATE)
            for name, pending in self.pending_updates.items():
                if pending.update_type == FULL_UPDATE:
                    context = self.marker_contexts.get(name)
                    if context is None:
                        context = _MarkerContext(copy.deepcopy(pending.int_marker))
                        self.marker_contexts[name] = context
                    else:
                        context.int_marker = copy.deepcopy(pending.int_marker)
                    context.default_feedback_cb = pending.default_feedback_cb
                    context.feedback_cbs = dict(pending.feedback_cbs)
                    update.markers.append(context.int_marker)
                elif pending.update_type == POSE_UPDATE:
                    context = self.marker_contexts.get(name)
                    if context is None:
                        _warn(
                            f"interactive marker server {self.server_id}: pose update for unknown marker '{name}' dropped"
                        )
                        continue
                    context.int_marker.pose = pending.int_marker.pose
                    context.int_marker.header = pending.int_marker.header
                    update.poses.append(
                        InteractiveMarkerPose(
                            header=context.int_marker.header,
                            pose=context.int_marker.pose,
                            name=name,
                        )
                    )
                elif name in self.marker_contexts:
                    del self.marker_contexts[name]
                    update.erases.append(name)
            self.pending_updates = {}
            self.seq_num += 1
            self._publish(update)
            self.publishInit()

    def get(self, name: str) -> Any:
        """The marker ``name`` as the next applyChanges will leave it, or None."""
        with self.mutex:
            update = self.pending_updates.get(name)
            if update is None:
                context = self.marker_contexts.get(name)
                return copy.deepcopy(context.int_marker) if context is not None else None
            if update.update_type == ERASE:
                return None
            if update.update_type == POSE_UPDATE:
                context = self.marker_contexts.get(name)
                if context is None:
                    return None
                marker = copy.deepcopy(context.int_marker)
                marker.pose, marker.header = update.int_marker.pose, update.int_marker.header
                return marker
            return copy.deepcopy(update.int_marker)

    def empty(self) -> bool:
        return not self.marker_contexts

    def size(self) -> int:
        return len(self.marker_contexts)

    # --- the protocol -----------------------------------------------------------------

    def processFeedback(self, feedback: Any) -> None:  # noqa: N802 - ROS's name
        """A client's feedback: move the marker on POSE_UPDATE, then call the callback."""
        with self.mutex:
            context = self.marker_contexts.get(feedback.marker_name)
            if context is None:
                _warn(
                    f"interactive marker server {self.server_id}: feedback for unknown marker "
                    f"'{feedback.marker_name}' ignored"
                )
                return
            now = time.monotonic()
            if context.last_client_id != feedback.client_id and now - context.last_feedback < 1.0:
                return  # another client holds this marker (ROS: for a second)
            context.last_feedback = now
            context.last_client_id = feedback.client_id
            if feedback.event_type == InteractiveMarkerFeedback.POSE_UPDATE:
                header = context.int_marker.header
                stamp = header.stamp
                if getattr(stamp, "sec", 0) or getattr(stamp, "nanosec", 0):
                    header = feedback.header
                self._do_set_pose(
                    self.pending_updates.get(feedback.marker_name),
                    feedback.marker_name,
                    feedback.pose,
                    header,
                )
            callback = context.feedback_cbs.get(feedback.event_type, context.default_feedback_cb)
        if callback is not None:
            callback(feedback)

    def publishInit(self) -> None:  # noqa: N802 - ROS's name
        """Publish every marker with the current sequence number on ``update_full``."""
        with self.mutex:
            self.init_pub.publish(
                InteractiveMarkerInit(
                    server_id=self.server_id,
                    seq_num=self.seq_num,
                    markers=[c.int_marker for c in self.marker_contexts.values()],
                )
            )

    def _keep_alive(self) -> None:
        with self.mutex:
            self._publish(InteractiveMarkerUpdate(type=InteractiveMarkerUpdate.KEEP_ALIVE))

    def _publish(self, update: Any) -> None:
        update.server_id = self.server_id
        update.seq_num = self.seq_num
        self.update_pub.publish(update)

    def _do_set_pose(
        self, update: _UpdateContext | None, name: str, pose: Any, header: Any
    ) -> None:
        if update is None:
            update = _UpdateContext(POSE_UPDATE, InteractiveMarker(name=name))
            self.pending_updates[name] = update
        elif update.update_type != FULL_UPDATE:
            update.update_type = POSE_UPDATE
        update.int_marker.pose = pose
        update.int_marker.header = header if header is not None else Header()


def _default_node() -> Any:
    """The rospy shim's node (after ``rospy.init_node``), else a node of its own."""
    from workbench.compat import rospy

    node = rospy.context().node()
    if node is not None:
        return node
    from workbench.bus import Node

    return Node("interactive_marker_server", anonymous=True)


def _warn(text: str) -> None:
    from workbench.compat import rospy

    rospy.logwarn(text)
