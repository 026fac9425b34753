"""RViz's Polygon display: ``geometry_msgs/PolygonStamped`` (a costmap's footprint) as a closed line."""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.rviz.display import Context
from workbench.rviz.displays import _ColouredDisplay, _rgba, _stamped_transform


class PolygonDisplay(_ColouredDisplay):
    """The polygon's points joined in order and back to the first, in its header frame.

    As RViz's: colour 25; 255; 0 and alpha 1 by default; a message with a NaN or an
    infinity is not drawn and the Topic status says so; an empty polygon clears it.
    """

    class_name = "Polygon"

    message_type = "geometry_msgs/PolygonStamped"
    default_topic = "footprint"

    def draw(self, context: Context, message: Any) -> None:
        path = f"{context.prefix}/{self.path}"
        points = polygon_points(message.polygon)
        if not np.all(np.isfinite(points)):
            self.status["Topic"] = "Message contained invalid floating point values (nans or infs)"
            return
        self.status["Topic"] = "OK"
        if points.shape[1] == 0:
            context.meshcat.Delete(path)
            return
        X = _stamped_transform(context, message.header)
        closed = np.concatenate([points, points[:, :1]], axis=1)
        context.meshcat.SetLine(path, np.asfortranarray(closed), 2.0, _rgba(self.color, self.alpha))
        context.meshcat.SetTransform(path, X)


def polygon_points(polygon: Any) -> np.ndarray:
    """The (3, N) vertices of a ``geometry_msgs/Polygon`` (m)."""
    return np.array([[p.x, p.y, p.z] for p in polygon.points], dtype=float).reshape(-1, 3).T
