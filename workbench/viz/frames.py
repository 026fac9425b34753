"""Frames as triads in the Meshcat viewer, live (RViz's TF display).

Each frame known to a buffer is drawn as three axes (x red, y green, z blue)
at ``/tf/<frame>``, posed by a lookup from the fixed frame at the latest time.
Call :meth:`TfDisplay.update` (or let a node timer call it) to follow motion.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench import spatial
from workbench.tf.buffer import Buffer
from workbench.tf.exceptions import TransformException


def rigid_transform(translation: Any, rotation: Any) -> Any:
    """A pydrake ``RigidTransform`` from a translation (m) and a quaternion ``(x, y, z, w)``."""
    return spatial.rigid_transform(translation, quaternion=rotation)


def add_triad(meshcat: Any, path: str, length: float = 0.2, radius: float = 0.006) -> None:
    """Draw a triad (x red, y green, z blue) under ``path``; its origin is the frame origin."""
    from pydrake.geometry import Cylinder, Rgba

    axes = {
        "x": ((0, np.pi / 2, 0), [length / 2, 0, 0], Rgba(0.9, 0.1, 0.1, 1)),
        "y": ((np.pi / 2, 0, 0), [0, length / 2, 0], Rgba(0.1, 0.8, 0.1, 1)),
        "z": ((0, 0, 0), [0, 0, length / 2], Rgba(0.1, 0.2, 0.9, 1)),
    }
    for name, (rpy, offset, colour) in axes.items():
        meshcat.SetObject(f"{path}/{name}-axis", Cylinder(radius, length), colour)
        meshcat.SetTransform(f"{path}/{name}-axis", spatial.rigid_transform(offset, rpy=rpy))


class TfDisplay:
    """Draws every frame of ``buffer`` as a triad in ``fixed_frame``.

    Args:
        buffer: The buffer to read (usually filled by a TransformListener).
        viewer: A :class:`workbench.viz.Viewer`; default the process-wide one.
        fixed_frame: The frame the scene is drawn in (RViz's Fixed Frame).
        scale: Triad length in metres.
        prefix: Meshcat path to draw under.
    """

    def __init__(
        self,
        buffer: Buffer,
        viewer: Any = None,
        fixed_frame: str = "world",
        scale: float = 0.2,
        prefix: str = "/tf",
    ) -> None:
        if viewer is None:
            from workbench.viz.viewer import Viewer

            viewer = Viewer.instance()
        self.buffer = buffer
        self.viewer = viewer
        self.fixed_frame = fixed_frame
        self.scale = scale
        self.prefix = prefix
        self._drawn: set[str] = set()
        #: Origins of the frames drawn by the last update, in the fixed frame, m.
        self.origins: dict[str, np.ndarray] = {}

    def frame_camera(self) -> None:
        """Point the camera so every drawn frame is in view (as ``workbench show`` frames)."""
        if not self.origins:
            return
        points = np.array(list(self.origins.values()))
        reach = self.scale * np.vstack([np.eye(3), -np.eye(3)])
        self.viewer.frame_camera(np.vstack([points + r for r in reach]))

    def update(self) -> dict[str, str]:
        """Redraw every frame; returns the frames that could not be placed and why.

        The camera is framed again whenever a frame appears for the first time.
        """
        meshcat = self.viewer.meshcat
        problems: dict[str, str] = {}
        new = False
        with self.buffer._lock:
            frames = self.buffer.get_frame_strings()
        for frame in frames:
            try:
                with self.buffer._lock:
                    st = self.buffer.lookup(self.fixed_frame, frame, 0)
            except TransformException as exc:
                problems[frame] = str(exc)
                continue
            path = f"{self.prefix}/{frame}"
            if frame not in self._drawn:
                add_triad(meshcat, path, self.scale, self.scale * 0.03)
                self._drawn.add(frame)
                new = True
            meshcat.SetTransform(path, rigid_transform(st.translation, st.rotation))
            self.origins[frame] = np.asarray(st.translation, dtype=float)
        if new:
            self.frame_camera()
        return problems

    def clear(self) -> None:
        self.viewer.meshcat.Delete(self.prefix)
        self._drawn.clear()
        self.origins.clear()
