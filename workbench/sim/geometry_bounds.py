"""World-aligned bounding boxes of a body's collision shapes (Gazebo's ``Link::BoundingBox``).

Exact for boxes, spheres, cylinders, capsules and ellipsoids; meshes and convex
shapes by their convex hull's vertices (what Drake collides with). Half spaces
are unbounded and left out.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.errors import SimulationError


def shape_half_extents(shape: Any, R_WG: np.ndarray) -> np.ndarray | None:
    """Half extents in W of a Drake shape rotated by ``R_WG`` about its centre (None: a mesh
    or an unbounded shape)."""
    from pydrake.geometry import Box, Capsule, Cylinder, Ellipsoid, Sphere

    if isinstance(shape, Sphere):
        return np.full(3, shape.radius())
    if isinstance(shape, Box):
        half = np.array([shape.width(), shape.depth(), shape.height()]) / 2.0
        return np.abs(R_WG) @ half
    if isinstance(shape, Ellipsoid):
        axes = np.array([shape.a(), shape.b(), shape.c()])
        return np.sqrt((R_WG**2) @ (axes**2))
    if isinstance(shape, (Cylinder, Capsule)):
        axis = R_WG[:, 2]
        radius = shape.radius()
        half = radius * np.sqrt(np.clip(1.0 - axis**2, 0.0, 1.0)) + shape.length() / 2.0 * np.abs(
            axis
        )
        return half + (radius if isinstance(shape, Capsule) else 0.0)
    return None


def body_bounds(world: Any, body: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(low, high)`` in W of a plant body's collision shapes as the world is now, m.

    Raises:
        SimulationError: The body has no bounded collision shape.
    """
    from pydrake.geometry import Convex, Mesh

    plant = world.plant
    inspector = world.scene_graph.model_inspector()
    X_WB = plant.EvalBodyPoseInWorld(plant.GetMyContextFromRoot(world.context), body)
    lows, highs = [], []
    for geometry in plant.GetCollisionGeometriesForBody(body):
        shape = inspector.GetShape(geometry)
        X_WG = X_WB.multiply(inspector.GetPoseInFrame(geometry))
        R, p = X_WG.rotation().matrix(), X_WG.translation()
        if isinstance(shape, (Mesh, Convex)):
            hull = shape.GetConvexHull()
            vertices = np.array([hull.vertex(i) for i in range(hull.num_vertices())], dtype=float)
            points = vertices @ R.T + p
            lows.append(points.min(axis=0))
            highs.append(points.max(axis=0))
            continue
        half = shape_half_extents(shape, R)
        if half is not None:
            lows.append(p - half)
            highs.append(p + half)
    if not lows:
        raise SimulationError(f"link '{body.name()}' has no bounded collision shape")
    return np.min(lows, axis=0), np.max(highs, axis=0)
