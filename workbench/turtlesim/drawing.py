"""Turtles drawn with code: shell, head, legs and tail as polygons on a PIL image.

A turtle is about 36 px long, close to the 45 px images of the original, and
faces along its heading. Several colour styles stand in for the original's
per-distribution turtle pictures.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from PIL import Image, ImageDraw


@dataclass(frozen=True)
class TurtleStyle:
    """Colours of one turtle drawing (RGB 0-255)."""

    shell: tuple[int, int, int]
    pattern: tuple[int, int, int]
    skin: tuple[int, int, int]


TURTLE_STYLES: tuple[TurtleStyle, ...] = (
    TurtleStyle((46, 139, 87), (20, 90, 50), (154, 205, 50)),
    TurtleStyle((160, 110, 45), (110, 70, 25), (210, 180, 120)),
    TurtleStyle((70, 130, 180), (30, 80, 130), (150, 200, 160)),
    TurtleStyle((128, 128, 0), (85, 85, 0), (189, 183, 107)),
    TurtleStyle((205, 92, 92), (140, 50, 50), (240, 200, 150)),
    TurtleStyle((95, 95, 95), (50, 50, 50), (170, 170, 170)),
)

_OUTLINE = (20, 20, 20)


def _ellipse(cx: float, cy: float, rx: float, ry: float, n: int = 20) -> list[tuple[float, float]]:
    return [
        (cx + rx * math.cos(2 * math.pi * i / n), cy + ry * math.sin(2 * math.pi * i / n))
        for i in range(n)
    ]


def _hexagon(cx: float, cy: float, r: float) -> list[tuple[float, float]]:
    return [
        (cx + r * math.cos(math.pi / 3 * i), cy + r * math.sin(math.pi / 3 * i)) for i in range(6)
    ]


def draw_turtle(image: Image.Image, px: float, py: float, theta: float, style: int = 0) -> None:
    """Draw one turtle onto ``image`` in place.

    Args:
        image: An RGB canvas (y down).
        px, py: The turtle's centre in pixels.
        theta: Heading in radians, counter-clockwise from +x in the world (y up).
        style: Index into :data:`TURTLE_STYLES` (wraps around).
    """
    colours = TURTLE_STYLES[style % len(TURTLE_STYLES)]
    c, s = math.cos(theta), math.sin(theta)

    def to_canvas(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
        # body frame: x forward, y to the turtle's left; canvas: y down
        return [(px + bx * c - by * s, py - bx * s - by * c) for bx, by in points]

    draw = ImageDraw.Draw(image)
    for lx, ly in ((8.0, 10.0), (8.0, -10.0), (-8.0, 10.0), (-8.0, -10.0)):
        draw.polygon(to_canvas(_ellipse(lx, ly, 4.0, 3.0, 12)), fill=colours.skin, outline=_OUTLINE)
    draw.polygon(to_canvas([(-12.0, 2.5), (-19.0, 0.0), (-12.0, -2.5)]), fill=colours.skin)
    draw.polygon(to_canvas(_ellipse(15.0, 0.0, 5.0, 4.5, 14)), fill=colours.skin, outline=_OUTLINE)
    draw.polygon(to_canvas(_ellipse(0.0, 0.0, 13.0, 10.5)), fill=colours.shell, outline=_OUTLINE)
    draw.polygon(to_canvas(_hexagon(0.0, 0.0, 5.0)), fill=colours.pattern)
    for hx, hy in ((8.0, 0.0), (-8.0, 0.0), (0.0, 7.0), (0.0, -7.0)):
        draw.polygon(to_canvas(_hexagon(hx, hy, 2.2)), fill=colours.pattern)
    # eyes show which way the turtle faces
    for ey in (2.0, -2.0):
        draw.polygon(to_canvas(_ellipse(17.5, ey, 1.0, 1.0, 6)), fill=_OUTLINE)
