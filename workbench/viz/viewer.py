"""The one Meshcat viewer of a process: robots, joint sliders, camera, snapshots."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from workbench.errors import ViewerError
from workbench.viz.geometry import robot_visuals, shape_corners

#: Vertical field of view of Meshcat's default perspective camera, degrees.
CAMERA_FOV_DEG = 75.0


class _Shown:
    def __init__(self, robot, prefix: str, visuals) -> None:
        self.robot = robot
        self.prefix = prefix
        self.visuals = visuals
        self.q = robot.default_positions()


class Viewer:
    """Wraps one pydrake ``Meshcat`` bound to 127.0.0.1.

    Use :meth:`instance` for the process-wide viewer (created on first use).

    Args:
        meshcat: An existing ``Meshcat`` to wrap; None starts a new server.
        port: Port for a new server (None: the first free one from 7000).
    """

    _instance: Viewer | None = None

    def __init__(self, meshcat: Any = None, port: int | None = None) -> None:
        if meshcat is None:
            # Drake aborts on a port below 1024 (but 0) and raises a TypeError past 2^31
            if port is not None and not (port == 0 or 1024 <= port <= 65535):
                raise ViewerError(
                    f"--port must be 0 (any free port) or 1024..65535, got {port}",
                    hint="ports below 1024 are the system's",
                )
            from pydrake.geometry import Meshcat, MeshcatParams

            try:
                meshcat = Meshcat(MeshcatParams(host="127.0.0.1", port=port, show_stats_plot=False))
            except RuntimeError as error:
                raise ViewerError(
                    f"cannot start the Meshcat server: {error}",
                    hint="free a port or pass another one",
                ) from None
        self.meshcat = meshcat
        self._shown: dict[str, _Shown] = {}
        self.camera_pose: tuple[np.ndarray, np.ndarray] | None = None
        self._sliders: dict[str, tuple[str, int]] = {}
        self._slider_values: dict[str, float] = {}

    @classmethod
    def instance(cls) -> Viewer:
        """The process-wide viewer, started on first use."""
        if cls._instance is None:
            cls._instance = cls()
        return cls._instance

    @property
    def url(self) -> str:
        """The address to open in a browser."""
        return self.meshcat.web_url()

    # --- robots --------------------------------------------------------------

    def show_robot(
        self, robot, q: Sequence[float] | np.ndarray | None = None, prefix: str | None = None
    ) -> str:
        """Draw ``robot`` (visual geometry in its colours) at positions ``q``.

        Args:
            robot: A loaded :class:`~workbench.model.Robot`, or a ``RobotDescription``,
                ``urdf/`` name or path, loaded here into a plant of the viewer's own
                (then :meth:`robot_at` gives that robot).
            q: Movable-joint positions (rad or m); default: the robot's defaults.
            prefix: Meshcat path to draw under; default ``/robots/<robot name>``.

        Returns:
            The Meshcat path prefix (each link is ``<prefix>/<link name>``).
        """
        from workbench.model import as_robot

        robot = as_robot(robot)
        robot.finalize()
        prefix = prefix or f"/robots/{robot.name}"
        self.meshcat.Delete(prefix)
        visuals = robot_visuals(robot)
        for visual in visuals:
            from pydrake.geometry import Rgba

            path = f"{prefix}/{visual.link}/{visual.name}"
            self.meshcat.SetObject(path, visual.shape, Rgba(*visual.rgba))
            self.meshcat.SetTransform(path, visual.X_LG)
        self._shown[prefix] = _Shown(robot, prefix, visuals)
        self.set_positions(robot, robot.default_positions() if q is None else q, prefix)
        return prefix

    def robot_at(self, prefix: str) -> Any:
        """The :class:`~workbench.model.Robot` drawn under ``prefix``.

        Raises:
            ViewerError: No robot is shown there.
        """
        entry = self._shown.get(prefix)
        if entry is None:
            shown = ", ".join(self._shown) or "none"
            raise ViewerError(f"no robot is shown at {prefix} (shown: {shown})")
        return entry.robot

    def _entry(self, robot, prefix: str | None) -> _Shown:
        prefix = prefix or f"/robots/{robot.name}"
        entry = self._shown.get(prefix)
        if entry is None or entry.robot is not robot:
            raise ViewerError(
                f"robot '{robot.name}' is not shown at {prefix}", hint="call show_robot first"
            )
        return entry

    def set_positions(
        self, robot, q: Sequence[float] | np.ndarray, prefix: str | None = None
    ) -> None:
        """Move a shown robot's links to positions ``q`` (movable joints, rad or m)."""
        entry = self._entry(robot, prefix)
        poses = robot.forward_kinematics(q)
        entry.q = np.asarray(q, dtype=float).copy()
        for link, X_WL in poses.items():
            self.meshcat.SetTransform(f"{entry.prefix}/{link}", X_WL)

    def robot_points(self, robot, q: Sequence[float] | np.ndarray | None = None) -> np.ndarray:
        """Corners of every visual's bounding box in the world at ``q``, shape (N, 3), metres."""
        poses = robot.forward_kinematics(robot.default_positions() if q is None else q)
        points = [np.zeros(3)]
        for visual in robot_visuals(robot):
            X_WG = poses[visual.link] @ visual.X_LG
            points.extend(X_WG.multiply(shape_corners(visual.shape).T).T)
        return np.array(points)

    def frame_robot(self, robot, q: Sequence[float] | np.ndarray | None = None) -> None:
        """Place the camera so that the whole robot at ``q`` is in view."""
        self.frame_camera(self.robot_points(robot, q))

    # --- sliders -------------------------------------------------------------

    def add_joint_sliders(self, robot, prefix: str | None = None) -> list[str]:
        """One slider per movable joint, like joint_state_publisher's GUI.

        Returns:
            The slider names (the joint names; ``<prefix>/<joint>`` if a name is taken).
        """
        entry = self._entry(robot, prefix)
        names = []
        for index, joint in enumerate(robot.movable_joints):
            low, high = robot.lower_limits[index], robot.upper_limits[index]
            if not np.isfinite(low) or not np.isfinite(high):
                low, high = -math.pi, math.pi
            span = high - low
            step = 0.001 if joint.type == "prismatic" or span < 0.5 else 0.01
            name = joint.name
            if name in self._sliders and self._sliders[name][0] != entry.prefix:
                name = f"{entry.prefix}/{joint.name}"
            value = float(np.clip(entry.q[index], low, high))
            if name in self._sliders:  # adding the sliders again replaces them
                self.meshcat.DeleteSlider(name)
            self.meshcat.AddSlider(name, float(low), float(high), step, value)
            self._sliders[name] = (entry.prefix, index)
            self._slider_values[name] = value
            names.append(name)
        return names

    def poll_sliders(self) -> dict[str, float]:
        """Read every joint slider; move the robots whose sliders changed.

        Returns:
            Slider name -> value (rad or m).
        """
        values: dict[str, float] = {}
        changed: dict[str, _Shown] = {}
        for name, (prefix, index) in self._sliders.items():
            value = float(self.meshcat.GetSliderValue(name))
            values[name] = value
            entry = self._shown[prefix]
            if value != self._slider_values.get(name):
                self._slider_values[name] = value
                entry.q[index] = value
                changed[prefix] = entry
        for entry in changed.values():
            self.set_positions(entry.robot, entry.q, entry.prefix)
        return values

    # --- camera, snapshots ---------------------------------------------------

    def frame_camera(self, points_W: np.ndarray) -> None:
        """Place the camera so the bounding box of ``points_W`` (N x 3, metres) fills the view."""
        points = np.atleast_2d(np.asarray(points_W, dtype=float))
        low, high = points.min(axis=0), points.max(axis=0)
        center = (low + high) / 2
        radius = max(float(np.linalg.norm(high - low)) / 2, 0.05)
        distance = 1.15 * radius / math.sin(math.radians(CAMERA_FOV_DEG) / 2)
        direction = np.array([1.0, -1.0, 0.7])
        direction /= np.linalg.norm(direction)
        self.meshcat.SetCameraPose(center + distance * direction, center)
        self.camera_pose = (center + distance * direction, center)

    def save_html(self, path: str | Path) -> Path:
        """Write a self-contained snapshot of the scene (needs no network or server)."""
        path = Path(path)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(self.meshcat.StaticHtml(), encoding="utf-8")
        except OSError as error:
            raise ViewerError(f"cannot write the snapshot: {error.strerror}", path=path) from None
        return path

    def render_png(
        self, html_path: str | Path, png_path: str | Path, width: int = 1024, height: int = 768
    ) -> Path:
        """Render a snapshot to PNG with headless Chromium (see :func:`workbench.viz.render.render_png`)."""
        from workbench.viz.render import render_png

        return render_png(html_path, png_path, width=width, height=height)

    def clear(self) -> None:
        """Remove every robot, slider and object drawn so far."""
        for prefix in list(self._shown):
            self.meshcat.Delete(prefix)
        for name in list(self._sliders):
            self.meshcat.DeleteSlider(name)
        self._shown.clear()
        self._sliders.clear()
        self._slider_values.clear()
