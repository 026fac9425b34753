"""The robot footprint as costmap_2d handles it (``costmap_2d/src/footprint.cpp``, Noetic).

A footprint is a polygon in the robot's base frame, ``[(x, y), ...]`` (m). It comes
from the ``footprint`` parameter (a list of ``[x, y]`` pairs or the same as a string
``"[[x, y], ...]"``) or, when that is unset or ``[]``, from ``robot_radius`` as a
16-gon. ``footprint_padding`` moves each vertex outwards by the padding along x and
y (``padFootprint``). The inscribed radius is the polygon's smallest distance from the
centre to an edge or vertex; the circumscribed radius its largest.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.navigation.costmap_errors import CostmapError

Point = tuple[float, float]

_EXAMPLE = "e.g. [[0.2, 0.2], [-0.2, 0.2], [-0.2, -0.2], [0.2, -0.2]]"


def _number(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value) if math.isfinite(value) else None


def parse_footprint(value: Any, param: str) -> list[Point]:
    """The polygon a ``footprint`` parameter value describes.

    Args:
        value: A list of ``[x, y]`` pairs (m), or that list written as a string.
        param: The parameter's full name, for the error.

    Raises:
        CostmapError: Not a list of at least three ``[x, y]`` number pairs (one line
            naming ``param``).
    """
    if isinstance(value, str):
        try:
            value = ast.literal_eval(value.strip())
        except (ValueError, SyntaxError, MemoryError, RecursionError):
            raise CostmapError(
                f"parameter {param} is not a polygon: cannot read {value!r} as "
                f"[[x1, y1], [x2, y2], ...] ({_EXAMPLE})"
            ) from None
    if not isinstance(value, (list, tuple)) or len(value) < 3:
        raise CostmapError(
            f"parameter {param} is not a polygon: it must list at least three [x, y] "
            f"points ({_EXAMPLE}), got {value!r}"
        )
    points: list[Point] = []
    for i, point in enumerate(value):
        if not isinstance(point, (list, tuple)) or len(point) != 2:
            raise CostmapError(
                f"parameter {param} is not a polygon: point {i} is {point!r}, not a pair "
                f"[x, y] ({_EXAMPLE})"
            )
        x, y = _number(point[0]), _number(point[1])
        if x is None or y is None:
            raise CostmapError(
                f"parameter {param} is not a polygon: point {i} is {point!r}; its values "
                "must be finite numbers (m)"
            )
        points.append((x, y))
    return points


def footprint_from_radius(radius: float) -> list[Point]:
    """A circular robot's footprint: 16 points on the circle (``makeFootprintFromRadius``)."""
    n = 16
    return [
        (math.cos(i * 2 * math.pi / n) * radius, math.sin(i * 2 * math.pi / n) * radius)
        for i in range(n)
    ]


def _sign0(value: float) -> float:
    return -1.0 if value < 0 else (1.0 if value > 0 else 0.0)


def pad_footprint(points: Sequence[Point], padding: float) -> list[Point]:
    """Each vertex moved ``padding`` (m) away from the axes (``padFootprint``)."""
    return [(x + _sign0(x) * padding, y + _sign0(y) * padding) for x, y in points]


def _distance_to_segment(x0: float, y0: float, x1: float, y1: float) -> float:
    """Distance from the origin to the segment ``(x0, y0)``-``(x1, y1)`` (``distanceToLine``)."""
    c, d = x1 - x0, y1 - y0
    length_sq = c * c + d * d
    t = -1.0 if length_sq == 0 else (-x0 * c - y0 * d) / length_sq
    if t < 0:
        px, py = x0, y0
    elif t > 1:
        px, py = x1, y1
    else:
        px, py = x0 + t * c, y0 + t * d
    return math.hypot(px, py)


def inscribed_and_circumscribed(points: Sequence[Point]) -> tuple[float, float]:
    """``(inscribed, circumscribed)`` radii (m) of a footprint (``calculateMinAndMaxDistances``).

    With fewer than three points costmap_2d leaves them at (largest double, 0).
    """
    if len(points) <= 2:
        return float(np.finfo(float).max), 0.0
    low, high = math.inf, 0.0
    for i, (x, y) in enumerate(points):
        nx, ny = points[(i + 1) % len(points)]
        vertex = math.hypot(x, y)
        edge = _distance_to_segment(x, y, nx, ny)
        low = min(low, vertex, edge)
        high = max(high, vertex, edge)
    return low, high


def transform_footprint(x: float, y: float, theta: float, points: Sequence[Point]) -> np.ndarray:
    """The footprint placed at pose ``(x, y, theta)``: an ``(N, 2)`` array (m)."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    c, s = math.cos(theta), math.sin(theta)
    return np.column_stack((x + p[:, 0] * c - p[:, 1] * s, y + p[:, 0] * s + p[:, 1] * c))


def footprint_string(points: Sequence[Point]) -> str:
    """The footprint as costmap_2d writes it back to its parameter: ``[[x,y],[x,y],...]``."""
    return "[" + ",".join(f"[{x:g},{y:g}]" for x, y in points) + "]"


__all__ = [
    "Point",
    "footprint_from_radius",
    "footprint_string",
    "inscribed_and_circumscribed",
    "pad_footprint",
    "parse_footprint",
    "transform_footprint",
]
