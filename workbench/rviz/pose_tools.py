"""RViz's "2D Pose Estimate" and "2D Nav Goal" tools, as Meshcat controls and as Python calls.

RViz's InitialPoseTool publishes ``geometry_msgs/PoseWithCovarianceStamped`` on its
``Topic`` (default ``initialpose``) with the covariance's x, y and yaw variances the
squares of its ``X std deviation`` (0.5 m), ``Y std deviation`` (0.5 m) and ``Theta
std deviation`` (pi/12 rad); its GoalTool publishes ``geometry_msgs/PoseStamped`` on
its ``Topic`` (``/move_base_simple/goal`` in RViz's default config). Both stamp the
pose now, in the fixed frame, and log ``Setting pose: ...`` / ``Setting goal: ...``.

In Meshcat, where a pose cannot be dragged out on the map, the side panel gets
three sliders (x and y in m, bounded by the map's extent when a Map display has
drawn one, yaw in degrees) and one button per tool; an arrow shows the pose the
sliders set, and a click publishes it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

#: RViz's tool class names (``Tools:`` in an .rviz file) -> button labels.
TOOL_LABELS = {"SetInitialPose": "2D Pose Estimate", "SetGoal": "2D Nav Goal"}
#: Slider names in Meshcat's side panel.
SLIDERS = ("Pose x (m)", "Pose y (m)", "Pose yaw (deg)")
#: Slider range without a map, m.
DEFAULT_EXTENT = (-10.0, 10.0, -10.0, 10.0)


@dataclass
class ToolSettings:
    """What an .rviz file's ``Tools:`` section sets for the two tools (RViz's defaults)."""

    initial_pose_topic: str = "initialpose"
    goal_topic: str = "/move_base_simple/goal"
    std_dev_x: float = 0.5
    std_dev_y: float = 0.5
    std_dev_theta: float = math.pi / 12.0
    tools: tuple[str, ...] = ("SetInitialPose", "SetGoal")


def pose_estimate_message(
    x: float, y: float, yaw: float, frame: str, stamp: Any, settings: ToolSettings
) -> Any:
    """The ``PoseWithCovarianceStamped`` RViz's 2D Pose Estimate sends (m, rad)."""
    from workbench.msgs.geometry_msgs import PoseWithCovarianceStamped

    message = PoseWithCovarianceStamped()
    message.header.frame_id = frame
    message.header.stamp = stamp
    _set_pose(message.pose.pose, x, y, yaw)
    covariance = np.zeros(36)
    covariance[6 * 0 + 0] = settings.std_dev_x**2
    covariance[6 * 1 + 1] = settings.std_dev_y**2
    covariance[6 * 5 + 5] = settings.std_dev_theta**2
    message.pose.covariance = covariance
    return message


def goal_message(x: float, y: float, yaw: float, frame: str, stamp: Any) -> Any:
    """The ``PoseStamped`` RViz's 2D Nav Goal sends (m, rad)."""
    from workbench.msgs.geometry_msgs import PoseStamped

    message = PoseStamped()
    message.header.frame_id = frame
    message.header.stamp = stamp
    _set_pose(message.pose, x, y, yaw)
    return message


def _set_pose(pose: Any, x: float, y: float, yaw: float) -> None:
    pose.position.x, pose.position.y, pose.position.z = float(x), float(y), 0.0
    pose.orientation.x = pose.orientation.y = 0.0
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2.0), math.cos(yaw / 2.0)


def _check_pose(what: str, x: float, y: float, yaw: float) -> None:
    from workbench.errors import ViewerError

    if not all(math.isfinite(float(v)) for v in (x, y, yaw)):
        raise ViewerError(f"{what}: x, y and yaw must be finite numbers, got ({x}, {y}, {yaw})")


class PoseTools:
    """The two tools of one RViz: publishers, and optionally their Meshcat controls.

    Args:
        node: The RViz's node (publishes and logs).
        settings: Topics, standard deviations and which tools there are.
    """

    def __init__(self, node: Any, settings: ToolSettings | None = None) -> None:
        self.node = node
        self.settings = settings or ToolSettings()
        self._publishers: dict[str, Any] = {}
        self.sent: list[Any] = []  # every message published, oldest first
        self._clicks: dict[str, int] = {}
        self._values: tuple[float, float, float] | None = None
        self._extent: tuple[float, float, float, float] | None = None
        self._meshcat: Any = None

    # --- publishing (RViz's onPoseSet) ----------------------------------------------------

    def _publisher(self, tool: str) -> Any:
        if tool not in self._publishers:
            if tool == "SetInitialPose":
                topic, kind = (
                    self.settings.initial_pose_topic,
                    "geometry_msgs/PoseWithCovarianceStamped",
                )
            else:
                topic, kind = self.settings.goal_topic, "geometry_msgs/PoseStamped"
            self._publishers[tool] = self.node.create_publisher(topic, kind, queue_size=1)
        return self._publishers[tool]

    def set_pose_estimate(self, x: float, y: float, yaw: float, frame: str) -> Any:
        """Publish a 2D Pose Estimate at ``(x, y)`` m facing ``yaw`` rad in ``frame``.

        Raises:
            ViewerError: A coordinate that is not a finite number.
        """
        _check_pose("2D Pose Estimate", x, y, yaw)
        message = pose_estimate_message(x, y, yaw, frame, self.node.now(), self.settings)
        self.node.get_logger().info("Setting pose: %.3f %.3f %.3f [frame=%s]", x, y, yaw, frame)
        self._publisher("SetInitialPose").publish(message)
        self.sent.append(message)
        return message

    def send_goal(self, x: float, y: float, yaw: float, frame: str) -> Any:
        """Publish a 2D Nav Goal at ``(x, y)`` m facing ``yaw`` rad in ``frame``.

        Raises:
            ViewerError: A coordinate that is not a finite number.
        """
        _check_pose("2D Nav Goal", x, y, yaw)
        message = goal_message(x, y, yaw, frame, self.node.now())
        p, q = message.pose.position, message.pose.orientation
        self.node.get_logger().info(
            "Setting goal: Frame:%s, Position(%.3f, %.3f, %.3f), "
            "Orientation(%.3f, %.3f, %.3f, %.3f) = Angle: %.3f",
            frame, p.x, p.y, p.z, q.x, q.y, q.z, q.w, yaw,
        )  # fmt: skip
        self._publisher("SetGoal").publish(message)
        self.sent.append(message)
        return message

    # --- Meshcat controls -----------------------------------------------------------------

    @property
    def labels(self) -> list[str]:
        """The buttons, in the config's order."""
        return [TOOL_LABELS[t] for t in self.settings.tools if t in TOOL_LABELS]

    def update(self, context: Any, extent: tuple[float, float, float, float] | None) -> None:
        """Add the controls (first call), follow the map's extent, draw the arrow and
        publish for every click since the last call. From Meshcat's thread."""
        if not self.labels:
            return
        meshcat = context.meshcat
        buttons = set(meshcat.GetButtonNames())
        if self._meshcat is None:  # a button left by an earlier RViz starts again at 0
            for label in self.labels:
                if label in buttons:
                    meshcat.DeleteButton(label)
            buttons = set()
        self._meshcat = meshcat
        for label in self.labels:  # (again if another RViz of this Meshcat removed them)
            if label not in buttons:
                meshcat.AddButton(label)
                self._clicks[label] = 0
        wanted = extent or DEFAULT_EXTENT
        if wanted != self._extent or not set(SLIDERS) <= set(meshcat.GetSliderNames()):
            self._bound_sliders(meshcat, wanted)
        x, y, yaw_deg = (meshcat.GetSliderValue(name) for name in SLIDERS)
        if (x, y, yaw_deg) != self._values:
            self._values = (x, y, yaw_deg)
            self._draw_arrow(context, x, y, math.radians(yaw_deg))
        for label in self.labels:
            clicks = meshcat.GetButtonClicks(label)
            if clicks > self._clicks[label]:
                self._clicks[label] = clicks
                send = self.set_pose_estimate if label == "2D Pose Estimate" else self.send_goal
                send(x, y, math.radians(yaw_deg), context.fixed_frame)

    def _bound_sliders(self, meshcat: Any, extent: tuple[float, float, float, float]) -> None:
        present = set(meshcat.GetSliderNames())
        old = {n: meshcat.GetSliderValue(n) for n in SLIDERS if n in present}
        x_min, x_max, y_min, y_max = extent
        centre = ((x_min + x_max) / 2.0, (y_min + y_max) / 2.0)
        ranges = (
            (x_min, x_max, 0.05, centre[0]),
            (y_min, y_max, 0.05, centre[1]),
            (-180.0, 180.0, 1.0, 0.0),
        )
        for name, (low, high, step, start) in zip(SLIDERS, ranges, strict=True):
            value = float(np.clip(old.get(name, start), low, high))
            if name in present:
                meshcat.DeleteSlider(name)
            meshcat.AddSlider(name, low, high, step, value)
        self._extent = extent
        self._values = None

    def _draw_arrow(self, context: Any, x: float, y: float, yaw: float) -> None:
        from workbench.rviz.displays import _arrow
        from workbench.spatial import rigid_transform

        X = rigid_transform(
            [x, y, 0.0], quaternion=(0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
        )
        _arrow(context, f"{context.prefix}/Tools/pose", X, length=1.0, colour=(0.0, 1.0, 0.0))

    def close(self) -> None:
        """Remove the controls (from Meshcat's thread) and the publishers."""
        if self._meshcat is not None:
            buttons = set(self._meshcat.GetButtonNames())
            sliders = set(self._meshcat.GetSliderNames())
            for label in self.labels:
                if label in buttons:
                    self._meshcat.DeleteButton(label)
            for name in SLIDERS:
                if name in sliders:
                    self._meshcat.DeleteSlider(name)
            self._meshcat = None
        for publisher in self._publishers.values():
            publisher.unregister()
        self._publishers.clear()
