"""Is a ``visualization_msgs/Marker`` drawable? RViz's checks, with RViz's words.

Matches rviz (noetic) ``marker_utils.cpp`` ``checkMarkerMsg``: per marker type
the same fields are checked and the same status text is produced; an *error*
means the marker is not drawn, a *warning* or *info* is shown in its status and
the marker is drawn. Only ADD/MODIFY markers are checked.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

ARROW, CUBE, SPHERE, CYLINDER = 0, 1, 2, 3
LINE_STRIP, LINE_LIST, CUBE_LIST, SPHERE_LIST, POINTS = 4, 5, 6, 7, 8
TEXT_VIEW_FACING, MESH_RESOURCE, TRIANGLE_LIST = 9, 10, 11
ADD, DELETE, DELETEALL = 0, 2, 3

TYPE_NAMES = {
    ARROW: "Arrow",
    CUBE: "Cube",
    SPHERE: "Sphere",
    CYLINDER: "Cylinder",
    LINE_STRIP: "Line Strip",
    LINE_LIST: "Line List",
    CUBE_LIST: "Cube List",
    SPHERE_LIST: "Sphere List",
    POINTS: "Points",
    TEXT_VIEW_FACING: "Text View Facing",
    MESH_RESOURCE: "Mesh",
    TRIANGLE_LIST: "Triangle List",
}

_LEVELS = {"debug": 0, "info": 1, "warn": 2, "error": 3}


@dataclass(frozen=True)
class MarkerStatus:
    """The outcome of checking one marker: ``level`` is info, warn or error."""

    level: str
    text: str

    @property
    def fatal(self) -> bool:
        """An error: the marker is not drawn."""
        return self.level == "error"


class _Report:
    def __init__(self) -> None:
        self.lines: list[str] = []
        self.level = "debug"

    def add(self, level: str, text: str) -> None:
        self.lines.append(text)
        if _LEVELS[level] > _LEVELS[self.level]:
            self.level = level


def _finite(values: Iterable[float]) -> bool:
    return all(math.isfinite(v) for v in values)


def _xyz(v: Any) -> tuple[float, float, float]:
    return (v.x, v.y, v.z)


def _floats(report: _Report, name: str, values: Iterable[float]) -> None:
    if not _finite(values):
        report.add("error", f"{name} contains invalid floating point values (nans or infs)")


def _quaternion(marker: Any, report: _Report) -> None:
    q = marker.pose.orientation
    _floats(report, "Orientation", (q.x, q.y, q.z, q.w))
    norm2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w
    if q.x == 0.0 and q.y == 0.0 and q.z == 0.0 and q.w == 0.0:
        report.add("info", "Uninitialized quaternion, assuming identity.")
    elif math.isfinite(norm2) and abs(norm2 - 1.0) > 1e-3:
        report.add("warn", "Unnormalized quaternion in marker message.")


def _scale(marker: Any, report: _Report) -> None:
    s = marker.scale
    _floats(report, "Scale", _xyz(s))
    if marker.type == ARROW and s.x != 0.0 and s.y != 0.0:
        return  # an arrow's scale.z is the optional head length
    if s.x == 0.0 or s.y == 0.0 or s.z == 0.0:
        report.add("warn", "Scale contains 0.0 in x, y or z.")
    if s.x < 0.0 or s.y < 0.0 or s.z < 0.0:
        # not one of RViz's checks (Ogre mirrors the shape); workbench draws the mirror image
        report.add("warn", "Scale contains a negative value; its absolute value is used.")


def _color(marker: Any, report: _Report) -> None:
    c = marker.color
    _floats(report, "Color", (c.r, c.g, c.b, c.a))
    embedded = (
        marker.type == MESH_RESOURCE
        and marker.mesh_use_embedded_materials
        and c.r == 0.0
        and c.g == 0.0
        and c.b == 0.0
    )
    if c.a == 0.0 and not embedded:
        report.add("info", "Marker is fully transparent (color.a is 0.0).")


def _colors(marker: Any, report: _Report, multiple: int) -> None:
    if not marker.colors:
        _color(marker, report)
        return
    n_colors, n_points = len(marker.colors), len(marker.points)
    if n_colors != n_points and (multiple == 1 or multiple * n_colors != n_points):
        report.add("error", "Number of colors doesn't match number of points.")


def _points_not_empty(marker: Any, report: _Report) -> None:
    n = len(marker.points)
    if n == 0:
        report.add("error", "Points should not be empty for specified marker type.")
    if marker.type == TRIANGLE_LIST and n % 3:
        report.add("error", "Number of points should be a multiple of 3 for TRIANGLE_LIST marker.")
    elif marker.type == LINE_LIST and n % 2:
        report.add("error", "Number of points should be a multiple of 2 for LINE_LIST marker.")
    elif marker.type == LINE_STRIP and n <= 1:
        report.add("error", "At least two points are required for a LINE_STRIP marker.")


def _ignored(
    marker: Any, report: _Report, points: bool, colors: bool, text: bool, mesh: bool
) -> None:
    if points and marker.points:
        report.add("warn", "Non-empty points array is ignored.")
    if colors and marker.colors:
        report.add("warn", "Non-empty colors array is ignored.")
    if text and marker.text:
        report.add("info", "Non-empty text is ignored.")
    if mesh:
        if marker.mesh_resource:
            report.add("info", "Non-empty mesh_resource is ignored.")
        if marker.mesh_use_embedded_materials:
            report.add("info", "mesh_use_embedded_materials is ignored.")


def check_marker(marker: Any) -> MarkerStatus | None:
    """RViz's verdict on an ADD/MODIFY marker: None when all is well.

    The same checks, per type, as rviz's ``checkMarkerMsg``; several findings are
    joined with a newline, the most severe one gives the level.
    """
    if marker.action != ADD:
        return None
    report = _Report()
    _floats(report, "Position", _xyz(marker.pose.position))
    kind = marker.type
    if kind == ARROW:
        _quaternion(marker, report)
        _scale(marker, report)
        _color(marker, report)
        if marker.points and len(marker.points) != 2:
            report.add("error", "Number of points for an ARROW marker should be either 0 or 2.")
        else:
            for p in marker.points:
                _floats(report, "Position", _xyz(p))
        _ignored(marker, report, points=False, colors=True, text=True, mesh=True)
    elif kind in (CUBE, CYLINDER, SPHERE):
        _quaternion(marker, report)
        _scale(marker, report)
        _color(marker, report)
        _ignored(marker, report, points=True, colors=True, text=True, mesh=True)
    elif kind in (LINE_STRIP, LINE_LIST):
        _quaternion(marker, report)
        if marker.scale.x == 0.0:
            report.add("warn", "Width LINE_LIST or LINE_STRIP is 0.0 (scale.x).")
        _points_not_empty(marker, report)
        _colors(marker, report, 1)
        _ignored(marker, report, points=False, colors=False, text=True, mesh=True)
    elif kind in (SPHERE_LIST, CUBE_LIST, TRIANGLE_LIST):
        _quaternion(marker, report)
        _scale(marker, report)
        _points_not_empty(marker, report)
        _colors(marker, report, 3 if kind == TRIANGLE_LIST else 1)
        _ignored(marker, report, points=False, colors=False, text=True, mesh=True)
    elif kind == POINTS:
        if marker.scale.x == 0.0 or marker.scale.y == 0.0:
            report.add("warn", "Width and/or height of POINTS is 0.0 (scale.x, scale.y).")
        _points_not_empty(marker, report)
        _colors(marker, report, 1)
        _ignored(marker, report, points=False, colors=False, text=True, mesh=True)
    elif kind == TEXT_VIEW_FACING:
        _color(marker, report)
        if marker.scale.z == 0.0:
            report.add("warn", "Text height of TEXT_VIEW_FACING is 0.0 (scale.z).")
        if not marker.text.strip():
            report.add("error", "Text is empty or only consists of whitespace.")
        _ignored(marker, report, points=True, colors=True, text=False, mesh=True)
    elif kind == MESH_RESOURCE:
        _quaternion(marker, report)
        _color(marker, report)
        _scale(marker, report)
        _ignored(marker, report, points=True, colors=True, text=True, mesh=False)
        if not marker.mesh_resource:
            report.add("error", "Empty mesh_resource path.")
    else:
        report.add("error", f"Unknown marker type: {kind}.")
    if not report.lines:
        return None
    return MarkerStatus(
        "warn" if report.level in ("debug",) else report.level, "\n".join(report.lines)
    )
