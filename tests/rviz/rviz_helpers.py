"""A Meshcat that remembers what was drawn, and markers to draw."""

from __future__ import annotations

import numpy as np
from meshcat_client import msgpack

from workbench.msgs.geometry_msgs import Point

_MESHCAT = None


def recording_meshcat():
    """A real Meshcat (127.0.0.1) that also records transforms and objects set from Python.

    One per test process, emptied for each caller: Drake's Meshcat must be destroyed
    on the thread that made it, and a viewer freed by the garbage collector on a bus
    thread would abort the process.
    """
    global _MESHCAT
    if _MESHCAT is None:
        _MESHCAT = _make_recording_meshcat()
    _MESHCAT.Delete()
    for name in _MESHCAT.GetSliderNames():
        _MESHCAT.DeleteSlider(name)
    for name in _MESHCAT.GetButtonNames():
        _MESHCAT.DeleteButton(name)
    _MESHCAT.transforms.clear()
    _MESHCAT.objects.clear()
    _MESHCAT.lines.clear()
    return _MESHCAT


def _make_recording_meshcat():
    from pydrake.geometry import Meshcat, MeshcatParams

    class RecordingMeshcat(Meshcat):
        def __init__(self) -> None:
            super().__init__(MeshcatParams(host="127.0.0.1"))
            self.transforms: dict[str, np.ndarray] = {}
            self.objects: dict[str, object] = {}
            # path -> (starts (3, N), ends (3, N) or None for a strip, rgba)
            self.lines: dict[str, tuple[np.ndarray, np.ndarray | None, tuple]] = {}

        def SetTransform(self, path, X, *args):  # noqa: N802 - Meshcat's name
            self.transforms[path] = X.GetAsMatrix4()
            return super().SetTransform(path, X, *args)

        def SetObject(self, path, thing, *args):  # noqa: N802 - Meshcat's name
            self.objects[path] = thing
            return super().SetObject(path, thing, *args)

        def SetLine(self, path, vertices, width, rgba, *args):  # noqa: N802 - Meshcat's name
            self.lines[path] = (np.array(vertices), None, _rgba_tuple(rgba))
            return super().SetLine(path, vertices, width, rgba, *args)

        def SetLineSegments(self, path, starts, ends, width, rgba, *args):  # noqa: N802
            self.lines[path] = (np.array(starts), np.array(ends), _rgba_tuple(rgba))
            return super().SetLineSegments(path, starts, ends, width, rgba, *args)

    return RecordingMeshcat()


def _rgba_tuple(rgba) -> tuple[float, float, float, float]:
    return (rgba.r(), rgba.g(), rgba.b(), rgba.a())


def click(meshcat, label: str) -> None:
    """A click on button ``label``, as the browser's control panel reports it."""
    meshcat._InjectWebsocketMessage(msgpack({"type": "button", "name": label}))


def marker(kind: int, marker_id: int = 0, ns: str = "test", frame: str = "map", **fields):
    """A valid marker of ``kind`` (points where the type needs them), then ``fields``."""
    from workbench.msgs.visualization_msgs import Marker

    m = Marker(type=kind, id=marker_id, ns=ns)
    m.header.frame_id = frame
    m.pose.orientation.w = 1.0
    m.scale.x = m.scale.y = m.scale.z = 0.5
    m.color.r = m.color.a = 1.0
    if kind in (
        Marker.LINE_STRIP,
        Marker.LINE_LIST,
        Marker.CUBE_LIST,
        Marker.SPHERE_LIST,
        Marker.POINTS,
    ):
        m.points = [Point(x=0.0, y=0.0, z=0.0), Point(x=1.0, y=0.0, z=0.0)]
    if kind == Marker.TRIANGLE_LIST:
        m.points = [
            Point(x=0.0, y=0.0, z=0.0),
            Point(x=1.0, y=0.0, z=0.0),
            Point(x=0.0, y=1.0, z=0.0),
        ]
    if kind == Marker.TEXT_VIEW_FACING:
        m.text = "hello"
    for key, value in fields.items():
        setattr(m, key, value)
    return m
