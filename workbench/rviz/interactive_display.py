"""RViz's InteractiveMarkers display: a client of an interactive marker server.

It reads ``<ns>/update_full`` and ``<ns>/update`` (the server's protocol), draws
every marker's controls in the fixed frame (a control without markers gets
RViz's default look: arrows for MOVE_AXIS, a ring for ROTATE_AXIS, a square
for MOVE_PLANE, a sphere for the 3D modes), and lets the browser operate them:
a Meshcat slider per degree of freedom of each control (MOVE_AXIS, ROTATE_AXIS;
MOVE_PLANE two; MOVE_3D/ROTATE_3D three; MOVE_ROTATE and MOVE_ROTATE_3D their
sum) and a button per BUTTON control and per menu entry. Moving a slider sends
MOUSE_DOWN, POSE_UPDATE and MOUSE_UP feedback with the control's name and the
new pose, as RViz does while dragging; a button sends BUTTON_CLICK or
MENU_SELECT with the entry id. Sliders measure from the pose the server last
set (metres or radians).
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from workbench.rviz.display import Context, Display

CLIENT_ID = "/rviz/InteractiveMarkers"
SLIDER_RANGE = {"move": 5.0, "rotate": math.pi}


@dataclass
class _Dof:
    slider: str
    marker: str
    control: str
    kind: str  # "move" or "rotate"
    axis: np.ndarray  # in the marker frame
    value: float = 0.0


@dataclass
class _Shown:
    message: Any
    base_pose: Any  # the pose the server last set (sliders measure from it)
    dofs: list[_Dof] = field(default_factory=list)
    buttons: dict[str, tuple[str, int, int]] = field(
        default_factory=dict
    )  # name -> (kind, id, clicks)


class InteractiveMarkerDisplay(Display):
    """Shows and operates the markers of the server on ``topic`` (its namespace)."""

    class_name = "InteractiveMarkers"
    default_topic = "basic_controls"

    def __init__(
        self, topic: str | None = None, name: str | None = None, controls: bool = True
    ) -> None:
        super().__init__(topic, name)
        self.controls = controls
        self.markers: dict[str, _Shown] = {}
        self.server_id = ""
        self.seq_num = -1
        self._lock_state = threading.Lock()
        self._feedback: Any = None
        self._updates: list[tuple[str, Any]] = []
        self.sent: list[Any] = []

    def attach(self, node: Any) -> None:
        from workbench.msgs.visualization_msgs import (
            InteractiveMarkerFeedback,
            InteractiveMarkerInit,
            InteractiveMarkerUpdate,
        )

        ns = self.topic.rstrip("/")
        node.create_subscription(
            f"{ns}/update_full", InteractiveMarkerInit, lambda m: self._enqueue("init", m)
        )
        node.create_subscription(
            f"{ns}/update", InteractiveMarkerUpdate, lambda m: self._enqueue("update", m)
        )
        self._feedback = node.create_publisher(f"{ns}/feedback", InteractiveMarkerFeedback)
        self.status["Topic"] = "OK"

    def _enqueue(self, kind: str, message: Any) -> None:
        with self._lock_state:
            self._updates.append((kind, message))
            self.received += 1

    def update(self, context: Context) -> None:
        with self._lock_state:
            updates, self._updates = self._updates, []
        for kind, message in updates:
            self._apply(context, kind, message)
        for name in list(self.markers):
            self._pose(context, name)
        if self.controls:
            self._poll_controls(context)

    # --- the protocol ------------------------------------------------------------------

    def _apply(self, context: Context, kind: str, message: Any) -> None:
        if kind == "init":
            if self.seq_num >= message.seq_num and message.server_id == self.server_id:
                return
            for name in list(self.markers):
                self._erase(context, name)
            self.server_id, self.seq_num = message.server_id, message.seq_num
            for marker in message.markers:
                self._add(context, marker)
            self.status.pop("Server", None)
            return
        if message.type == 0:  # KEEP_ALIVE
            return
        if self.seq_num >= 0 and message.seq_num <= self.seq_num:
            return  # already in the full state we read
        self.seq_num = message.seq_num
        for marker in message.markers:
            self._add(context, marker)
        for pose in message.poses:
            shown = self.markers.get(pose.name)
            if shown is not None:
                shown.message.pose, shown.message.header = pose.pose, pose.header
                shown.base_pose = pose.pose
                self._reset_sliders(context, shown)
        for name in message.erases:
            self._erase(context, name)

    def _add(self, context: Context, marker: Any) -> None:
        if not marker.name:
            self.status["Marker"] = "an interactive marker without a name was ignored"
            return
        if marker.name in self.markers:
            self._erase(context, marker.name)
        shown = _Shown(marker, marker.pose)
        self.markers[marker.name] = shown
        base = self._path(context, marker.name)
        scale = marker.scale if marker.scale > 0 else 1.0
        for c_index, control in enumerate(marker.controls):
            R = _rotation(control.orientation)
            if control.markers:
                from workbench.rviz.marker_draw import draw_marker
                from workbench.spatial import rigid_transform

                for m_index, visual in enumerate(control.markers):
                    path = f"{base}/{c_index}/{m_index}"
                    draw_marker(context.meshcat, path, visual)
                    q = visual.pose.orientation
                    quaternion = (q.x, q.y, q.z, q.w) if any((q.x, q.y, q.z, q.w)) else (0, 0, 0, 1)
                    p = visual.pose.position
                    context.meshcat.SetTransform(
                        path, rigid_transform([p.x, p.y, p.z], quaternion=quaternion)
                    )
            else:
                _default_look(
                    context.meshcat, f"{base}/{c_index}", control.interaction_mode, R, scale
                )
            if self.controls:
                self._make_controls(context, shown, control, R)
        if self.controls:
            for entry in marker.menu_entries:
                label = f"{marker.name}: {entry.title}"
                context.meshcat.AddButton(label)
                shown.buttons[label] = ("menu", entry.id, 0)

    def _make_controls(self, context: Context, shown: _Shown, control: Any, R: np.ndarray) -> None:
        from workbench.msgs.visualization_msgs import InteractiveMarkerControl as C

        mode = control.interaction_mode
        axes = {"x": R[:, 0], "y": R[:, 1], "z": R[:, 2]}
        dofs: list[tuple[str, str, np.ndarray]] = []
        if mode == C.MOVE_AXIS:
            dofs = [("move", "", axes["x"])]
        elif mode == C.ROTATE_AXIS:
            dofs = [("rotate", "", axes["x"])]
        elif mode == C.MOVE_PLANE:
            dofs = [("move", " y", axes["y"]), ("move", " z", axes["z"])]
        elif mode == C.MOVE_ROTATE:
            dofs = [("move", " y", axes["y"]), ("move", " z", axes["z"]), ("rotate", "", axes["x"])]
        elif mode in (C.MOVE_3D, C.ROTATE_3D, C.MOVE_ROTATE_3D):
            kinds = {
                C.MOVE_3D: ["move"],
                C.ROTATE_3D: ["rotate"],
                C.MOVE_ROTATE_3D: ["move", "rotate"],
            }[mode]
            basis = {
                "x": np.array([1.0, 0, 0]),
                "y": np.array([0, 1.0, 0]),
                "z": np.array([0, 0, 1.0]),
            }
            dofs = [
                (k, f" {'rot ' if k == 'rotate' else ''}{a}", v)
                for k in kinds
                for a, v in basis.items()
            ]
        elif mode == C.BUTTON:
            label = f"{shown.message.name}: {control.name or 'button'}"
            context.meshcat.AddButton(label)
            shown.buttons[label] = ("button", 0, 0)
            return
        for kind, suffix, axis in dofs:
            slider = f"{shown.message.name}: {control.name}{suffix}"
            limit = SLIDER_RANGE[kind]
            step = 0.01
            context.meshcat.AddSlider(slider, -limit, limit, step, 0.0)
            shown.dofs.append(_Dof(slider, shown.message.name, control.name, kind, axis))

    def _reset_sliders(self, context: Context, shown: _Shown) -> None:
        for dof in shown.dofs:
            dof.value = 0.0
            context.meshcat.SetSliderValue(dof.slider, 0.0)

    def _poll_controls(self, context: Context) -> None:
        for shown in self.markers.values():
            moved = None
            for dof in shown.dofs:
                value = context.meshcat.GetSliderValue(dof.slider)
                if abs(value - dof.value) > 1e-9:
                    dof.value = value
                    moved = dof
            if moved is not None:
                pose = _pose_from(shown)
                for event in (4, 1, 5):  # MOUSE_DOWN, POSE_UPDATE, MOUSE_UP
                    self._send(shown.message, moved.control, event, pose)
                shown.message.pose = pose
            for label, (kind, entry_id, seen) in list(shown.buttons.items()):
                clicks = context.meshcat.GetButtonClicks(label)
                if clicks > seen:
                    shown.buttons[label] = (kind, entry_id, clicks)
                    control = label.split(": ", 1)[1] if kind == "button" else ""
                    event = 3 if kind == "button" else 2  # BUTTON_CLICK / MENU_SELECT
                    self._send(shown.message, control, event, shown.message.pose, entry_id)

    def _send(self, marker: Any, control: str, event: int, pose: Any, entry_id: int = 0) -> None:
        from workbench.msgs.visualization_msgs import InteractiveMarkerFeedback

        feedback = InteractiveMarkerFeedback(
            client_id=CLIENT_ID,
            marker_name=marker.name,
            control_name=control,
            event_type=event,
            pose=pose,
            menu_entry_id=entry_id,
        )
        feedback.header.frame_id = marker.header.frame_id
        self._feedback.publish(feedback)
        self.sent.append(feedback)

    # --- drawing -----------------------------------------------------------------------

    def _pose(self, context: Context, name: str) -> None:
        from workbench.tf.exceptions import TransformException

        shown = self.markers[name]
        try:
            X = context.transform(shown.message.header.frame_id).multiply(
                _transform(shown.message.pose)
            )
        except TransformException as error:
            self.status[name] = f"No transform from [{shown.message.header.frame_id}]: {error}"
            return
        self.status.pop(name, None)
        context.meshcat.SetTransform(self._path(context, name), X)

    def _erase(self, context: Context, name: str) -> None:
        shown = self.markers.pop(name, None)
        if shown is None:
            return
        context.meshcat.Delete(self._path(context, name))
        for dof in shown.dofs:
            context.meshcat.DeleteSlider(dof.slider)
        for label in shown.buttons:
            context.meshcat.DeleteButton(label)

    def _path(self, context: Context, name: str) -> str:
        return f"{context.prefix}/{self.path}/{name.replace('/', '_')}"

    def close(self) -> None:
        super().close()


def _rotation(q: Any) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    values = np.array([q.x, q.y, q.z, q.w], dtype=float)
    if not np.any(values) or not np.all(np.isfinite(values)):
        return np.eye(3)
    return Rotation.from_quat(values / np.linalg.norm(values)).as_matrix()


def _transform(pose: Any) -> Any:
    from workbench.spatial import rigid_transform

    q = pose.orientation
    quaternion = (q.x, q.y, q.z, q.w) if any((q.x, q.y, q.z, q.w)) else (0.0, 0.0, 0.0, 1.0)
    return rigid_transform(
        [pose.position.x, pose.position.y, pose.position.z], quaternion=quaternion
    )


def _pose_from(shown: _Shown) -> Any:
    """The base pose moved by every slider: translations, then rotations about the origin."""
    from scipy.spatial.transform import Rotation

    from workbench.msgs.geometry_msgs import Pose

    base = shown.base_pose
    R_base = _rotation(base.orientation)
    position = np.array([base.position.x, base.position.y, base.position.z])
    R = R_base
    for dof in shown.dofs:
        axis_world = R_base @ dof.axis  # controls are in the marker frame (INHERIT)
        if dof.kind == "move":
            position = position + dof.value * axis_world
        else:
            R = Rotation.from_rotvec(axis_world * dof.value).as_matrix() @ R
    x, y, z, w = Rotation.from_matrix(R).as_quat()
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in position)
    pose.orientation.x, pose.orientation.y = float(x), float(y)
    pose.orientation.z, pose.orientation.w = float(z), float(w)
    return pose


def _default_look(meshcat: Any, path: str, mode: int, R: np.ndarray, scale: float) -> None:
    """RViz's automatic control markers, simplified: arrows, a ring, a square or a sphere."""
    from pydrake.geometry import Box, Rgba, Sphere

    from workbench.msgs.visualization_msgs import InteractiveMarkerControl as C

    x = R[:, 0]
    colour = Rgba(abs(x[0]) * 0.8 + 0.1, abs(x[1]) * 0.8 + 0.1, abs(x[2]) * 0.8 + 0.1, 0.8)
    if mode in (C.MOVE_AXIS, C.MOVE_ROTATE):
        starts = np.column_stack([x * 0.5 * scale, -x * 0.5 * scale])
        ends = np.column_stack([x * 0.9 * scale, -x * 0.9 * scale])
        meshcat.SetLineSegments(f"{path}/arrows", starts, ends, 4.0, colour)
    if mode in (C.ROTATE_AXIS, C.MOVE_ROTATE):
        t = np.linspace(0, 2 * np.pi, 49)
        ring = 0.6 * scale * (np.outer(R[:, 1], np.cos(t)) + np.outer(R[:, 2], np.sin(t)))
        meshcat.SetLine(f"{path}/ring", np.asfortranarray(ring), 3.0, colour)
    if mode == C.MOVE_PLANE:
        meshcat.SetObject(f"{path}/plane", Box(0.01 * scale, 0.8 * scale, 0.8 * scale), colour)
    if mode in (C.MOVE_3D, C.ROTATE_3D, C.MOVE_ROTATE_3D):
        meshcat.SetObject(f"{path}/handle", Sphere(0.15 * scale), colour)
