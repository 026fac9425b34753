"""RViz's Marker and MarkerArray displays (``visualization_msgs``)."""

from __future__ import annotations

import time
from typing import Any

from workbench.rviz.display import TF_WAIT, Context, Display
from workbench.rviz.marker_check import ADD, check_marker
from workbench.rviz.marker_draw import draw_marker
from workbench.rviz.marker_store import MarkerKey, MarkerStore


class MarkerDisplay(Display):
    """Draws ``visualization_msgs/Marker`` messages (default topic ``visualization_marker``)."""

    class_name = "Marker"

    message_type = "visualization_msgs/Marker"
    default_topic = "visualization_marker"

    def __init__(
        self, topic: str | None = None, name: str | None = None, queue_size: int = 100
    ) -> None:
        super().__init__(topic, name, queue_size)
        self.store = MarkerStore()

    def markers_of(self, message: Any) -> list[Any]:
        return [message]

    def update(self, context: Context) -> None:
        from workbench.tf.exceptions import TransformException

        now = time.monotonic()
        waiting = []
        for arrived, message in self.take():
            for marker in self.markers_of(message):
                checked = check_marker(marker)
                if marker.action == ADD and not (checked is not None and checked.fatal):
                    try:
                        pose = _marker_pose(context, marker)
                    except TransformException as error:
                        if now - arrived < TF_WAIT:
                            waiting.append((arrived, _single(self, marker)))
                        else:
                            self.store.statuses[f"{marker.ns}/{marker.id}"] = _no_transform(
                                marker, context, error
                            )
                        continue
                else:
                    pose = None
                drawn, erased = self.store.process(marker, now)
                for key in erased:
                    context.meshcat.Delete(self._key_path(context, key))
                for key in drawn:
                    self.store.markers[key].pose = pose
                    self._draw(context, key)
        if waiting:
            self.requeue(waiting)
        for key in self.store.expire(now):
            context.meshcat.Delete(self._key_path(context, key))
        for key in self.store.frame_locked():
            shown = self.store.markers[key]
            try:
                shown.pose = _marker_pose(context, shown.message, latest=True)
            except TransformException:
                continue
            context.meshcat.SetTransform(self._key_path(context, key), shown.pose)
        self.status = {k: v for k, v in self.status.items() if k in ("Topic",)}
        for label, marker_status in self.store.statuses.items():
            self.status[label] = marker_status.text

    def _draw(self, context: Context, key: MarkerKey) -> None:
        shown = self.store.markers[key]
        path = self._key_path(context, key)
        note = draw_marker(context.meshcat, path, shown.message, context.resolve_mesh)
        context.meshcat.SetTransform(path, shown.pose)
        if note is not None:
            from workbench.rviz.marker_check import MarkerStatus

            self.store.statuses[f"{key[0]}/{key[1]}"] = MarkerStatus("warn", note)
        self.drawn += 1

    def _key_path(self, context: Context, key: MarkerKey) -> str:
        ns = key[0].replace("/", "_") or "_"
        return f"{context.prefix}/{self.path}/{ns}/{key[1]}"


class MarkerArrayDisplay(MarkerDisplay):
    """Draws ``visualization_msgs/MarkerArray`` (default topic ``visualization_marker_array``)."""

    class_name = "MarkerArray"

    message_type = "visualization_msgs/MarkerArray"
    default_topic = "visualization_marker_array"

    def markers_of(self, message: Any) -> list[Any]:
        return list(getattr(message, "markers", [message]))


class _Wrapped:
    """A single marker put back in a MarkerArray display's queue."""

    def __init__(self, marker: Any) -> None:
        self.markers = [marker]


def _single(display: MarkerDisplay, marker: Any) -> Any:
    return _Wrapped(marker) if isinstance(display, MarkerArrayDisplay) else marker


def _marker_pose(context: Context, marker: Any, latest: bool = False) -> Any:
    from workbench.spatial import rigid_transform

    frame = marker.header.frame_id
    stamp = 0 if latest else marker.header.stamp
    X_FH = context.transform(frame, stamp)
    p, q = marker.pose.position, marker.pose.orientation
    quaternion = (q.x, q.y, q.z, q.w)
    if all(v == 0.0 for v in quaternion):
        quaternion = (0.0, 0.0, 0.0, 1.0)  # RViz: "Uninitialized quaternion, assuming identity."
    return X_FH.multiply(rigid_transform([p.x, p.y, p.z], quaternion=quaternion))


def _no_transform(marker: Any, context: Context, error: Exception) -> Any:
    from workbench.rviz.marker_check import MarkerStatus

    return MarkerStatus(
        "error",
        f"No transform from [{marker.header.frame_id}] to fixed frame [{context.fixed_frame}]: {error}",
    )
