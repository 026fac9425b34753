"""A concave collision mesh as convex pieces, so that it collides (and is seen) as it is drawn.

Drake's point contact, and the laser's ray caster, take a mesh as its convex
hull. That is right for a convex part and wrong for a wall that goes round a
room: its hull fills the room. Gazebo collides with the triangles themselves.
A concave mesh of a static model (walls, a course) is therefore given to Drake
as one thin convex prism per triangle: the triangle and a copy of it moved
:data:`THICKNESS` into the solid (along the inward normal of a closed,
consistently wound mesh; half each way otherwise), so every face is where the
file puts it. Meshes of more than :data:`MAX_PIECES` triangles stay hulls.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

#: How thick each triangle's prism is, m.
THICKNESS = 0.02
#: Most triangles a concave mesh may have to be split into prisms.
MAX_PIECES = 4096
#: Relative tolerance of the convexity test (of the mesh's size).
_FLAT = 1e-6


def load_triangles(path: Path) -> Any:
    """The triangles of a mesh file Drake reads (OBJ, as :func:`prepare_mesh` writes it)."""
    import trimesh

    return trimesh.load(str(path), force="mesh")


def is_convex(vertices: np.ndarray, faces: np.ndarray) -> bool:
    """True when every triangle's plane has all vertices on one side (the mesh bounds its hull)."""
    if len(faces) == 0:
        return True
    size = float(np.ptp(vertices, axis=0).max()) or 1.0
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-12 * size * size
    normals = normals[keep] / lengths[keep, None]
    offsets = np.einsum("ij,ij->i", normals, a[keep])
    for start in range(0, len(normals), 256):  # (faces x vertices) in blocks
        side = normals[start : start + 256] @ vertices.T - offsets[start : start + 256, None]
        if np.any((side.max(axis=1) > _FLAT * size) & (side.min(axis=1) < -_FLAT * size)):
            return False
    return True


def convex_pieces(path: Path, scale: np.ndarray) -> list[np.ndarray] | None:
    """Prisms (each (6, 3) points, in the mesh's frame, scaled) that make up a concave mesh.

    Args:
        path: A mesh file (OBJ).
        scale: (3,) the ``<scale>`` of the mesh element.

    Returns:
        One prism per triangle, or None when the mesh is convex (its hull is exact), has
        more than :data:`MAX_PIECES` triangles, or has none.
    """
    mesh = load_triangles(path)
    vertices = np.asarray(mesh.vertices, dtype=float) * np.asarray(scale, dtype=float)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(faces) == 0 or len(faces) > MAX_PIECES or is_convex(vertices, faces):
        return None
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-15
    a, b, c = a[keep], b[keep], c[keep]
    normals = normals[keep] / lengths[keep, None]
    if np.linalg.det(np.diag(np.sign(scale))) < 0:
        normals = -normals  # a mirroring scale turns the winding inside out
    closed = bool(mesh.is_watertight and mesh.is_winding_consistent)
    if closed and mesh.volume < 0:
        normals = -normals
    inward = -normals * THICKNESS
    outward = np.zeros_like(inward) if closed else -inward / 2.0
    if not closed:
        inward = inward / 2.0
    pieces = np.stack(
        [a + outward, b + outward, c + outward, a + inward, b + inward, c + inward], 1
    )
    return list(pieces)
