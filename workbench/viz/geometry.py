"""What a robot looks like: its visual geometries, colours and extents, from Drake."""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product
from typing import Any

import numpy as np

from workbench.errors import ViewerError
from workbench.spatial import Mesh, shape_from_drake

#: Colour of a visual with no material (Drake's illustration default).
DEFAULT_RGBA = (0.9, 0.9, 0.9, 1.0)


@dataclass
class Visual:
    """One visual geometry of one link.

    Attributes:
        link: Link (body) name.
        name: Unique name within the link.
        shape: The pydrake Shape.
        X_LG: Pose of the geometry in the link frame.
        rgba: Colour (r, g, b, a), each in [0, 1].
    """

    link: str
    name: str
    shape: Any
    X_LG: Any
    rgba: tuple[float, float, float, float]


def robot_visuals(robot) -> list[Visual]:
    """The illustration geometry of every link of ``robot``, with colours.

    Raises:
        ViewerError: The robot was loaded without a scene graph.
    """
    if robot.scene_graph is None:
        raise ViewerError(
            f"robot '{robot.name}' has no scene graph to read its geometry from",
            hint="load it with load_robot(..., builder=...) or without plant=",
        )
    inspector = robot.scene_graph.model_inspector()
    visuals: list[Visual] = []
    for body in robot.link_bodies():
        for index, geometry_id in enumerate(robot.plant.GetVisualGeometriesForBody(body)):
            rgba = DEFAULT_RGBA
            properties = inspector.GetIllustrationProperties(geometry_id)
            if properties is not None and properties.HasProperty("phong", "diffuse"):
                color = properties.GetProperty("phong", "diffuse")
                rgba = (color.r(), color.g(), color.b(), color.a())
            visuals.append(
                Visual(
                    body.name(),
                    f"visual_{index}",
                    inspector.GetShape(geometry_id),
                    inspector.GetPoseInFrame(geometry_id),
                    rgba,
                )
            )
    return visuals


def shape_corners(shape) -> np.ndarray:
    """The 8 corners of a box around ``shape`` in its own frame (metres), shape (8, 3)."""
    from pydrake.geometry import Capsule, Ellipsoid

    low, high = -np.full(3, 0.05), np.full(3, 0.05)
    known = shape_from_drake(shape)
    if isinstance(known, Mesh):
        low, high = _mesh_bounds(known)
    elif known is not None:
        high = known.half_extents()
        low = -high
    elif isinstance(shape, Capsule):
        high = np.array([shape.radius(), shape.radius(), shape.length() / 2 + shape.radius()])
        low = -high
    elif isinstance(shape, Ellipsoid):
        high = np.array([shape.a(), shape.b(), shape.c()])
        low = -high
    return np.array(
        [
            [(low, high)[i][0], (low, high)[j][1], (low, high)[k][2]]
            for i, j, k in product((0, 1), repeat=3)
        ]
    )


def _mesh_bounds(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    try:
        return mesh.bounds()
    except Exception:  # an unreadable mesh still gets a small box for framing
        return -np.full(3, 0.05), np.full(3, 0.05)
