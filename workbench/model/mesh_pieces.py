"""A concave collision mesh as convex pieces, so that it collides (and is seen) as it is drawn.

Drake's point contact, and the laser's ray caster, take a mesh as its convex
hull. That is right for a convex part, and close enough for a part whose hull
stays within :data:`CAVITY` of its surface; it is wrong for a wall that goes
round a room: its hull fills the room. Gazebo collides with the triangles
themselves. Such a mesh of a static model (walls, a course, a building) is
therefore given to Drake as thin convex prisms: each flat convex patch of the
surface (connected triangles in one plane whose union is convex; a wall's face,
a floor) and each remaining triangle, with a copy of it moved
:data:`THICKNESS` into the solid (along the inward normal of a closed,
consistently wound mesh; half each way otherwise), so every face is where the
file puts it. A mesh that would need more than :data:`MAX_PIECES` prisms stays
a hull.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

#: How thick each prism is, m.
THICKNESS = 0.02
#: Most prisms one mesh may become.
MAX_PIECES = 512
#: How far a mesh's hull may stand off its surface before the hull is not good enough, m.
CAVITY = 0.1
#: Relative tolerance of the flatness tests (of the mesh's size).
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
    normals, offsets, keep = _planes(vertices, faces)
    normals, offsets = normals[keep], offsets[keep]
    for start in range(0, len(normals), 256):  # (faces x vertices) in blocks
        side = normals[start : start + 256] @ vertices.T - offsets[start : start + 256, None]
        if np.any((side.max(axis=1) > _FLAT * size) & (side.min(axis=1) < -_FLAT * size)):
            return False
    return True


def hull_stands_off(vertices: np.ndarray, faces: np.ndarray, cavity: float = CAVITY) -> bool:
    """True when some facet of the convex hull has its centre more than ``cavity`` from the mesh."""
    from scipy.spatial import ConvexHull, QhullError

    try:
        hull = ConvexHull(vertices)
    except (QhullError, ValueError):
        return False  # flat or degenerate: its hull is itself
    centres = vertices[hull.simplices].mean(axis=1)
    triangles = vertices[faces]
    for start in range(0, len(centres), 64):
        distance = _distance_to_triangles(centres[start : start + 64], triangles)
        if np.any(distance > cavity):
            return True
    return False


class TooManyPieces(Exception):
    """A concave mesh that would need more than :data:`MAX_PIECES` prisms."""


def convex_pieces(path: Path, scale: np.ndarray) -> list[np.ndarray] | None:
    """Prisms (each (k, 3) points, in the mesh's frame, scaled) that make up a concave mesh.

    Args:
        path: A mesh file (OBJ).
        scale: (3,) the ``<scale>`` of the mesh element.

    Returns:
        The prisms, or None when the mesh's hull will do (convex, or no cavity deeper than
        :data:`CAVITY`).

    Raises:
        TooManyPieces: The mesh is concave and would need more than :data:`MAX_PIECES` prisms.
    """
    mesh = load_triangles(path)
    vertices = np.asarray(mesh.vertices, dtype=float) * np.asarray(scale, dtype=float)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(faces) == 0 or is_convex(vertices, faces):
        return None
    if not hull_stands_off(vertices, faces):
        return None
    normals, offsets, keep = _planes(vertices, faces)
    faces, normals, offsets = faces[keep], normals[keep], offsets[keep]
    if np.prod(np.sign(scale)) < 0:
        normals = -normals  # a mirroring scale turns the winding inside out
    closed = bool(mesh.is_watertight and mesh.is_winding_consistent)
    if closed and mesh.volume < 0:
        normals = -normals
    depth = np.array([0.0, -THICKNESS]) if closed else np.array([THICKNESS, -THICKNESS]) / 2
    pieces = []
    for region in _flat_patches(vertices, faces, normals, offsets):
        points = _convex_outline(vertices, faces[region], normals[region[0]])
        outlines = [points] if points is not None else [vertices[f] for f in faces[region]]
        for outline in outlines:
            n = normals[region[0]]
            pieces.append(np.concatenate([outline + n * d for d in depth]))
        if len(pieces) > MAX_PIECES:
            raise TooManyPieces(f"more than {MAX_PIECES} flat pieces")
    return pieces


def _planes(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit normals, offsets (n . x = offset) and which triangles are not degenerate."""
    size = float(np.ptp(vertices, axis=0).max()) or 1.0
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-12 * size * size
    normals = normals / np.where(keep, lengths, 1.0)[:, None]
    return normals, np.einsum("ij,ij->i", normals, a), keep


def _flat_patches(
    vertices: np.ndarray, faces: np.ndarray, normals: np.ndarray, offsets: np.ndarray
) -> list[np.ndarray]:
    """Groups of triangles in one plane (facing one way) that share edges."""
    size = float(np.ptp(vertices, axis=0).max()) or 1.0
    keys = np.column_stack([np.round(normals / 1e-6), np.round(offsets / (1e-6 * size))])
    _, plane = np.unique(keys, axis=0, return_inverse=True)
    plane = plane.ravel()
    parent = np.arange(len(faces))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = int(parent[i])
        return i

    owner: dict[tuple[int, int, int], int] = {}
    for index, face in enumerate(faces):
        for k in range(3):
            edge = (int(plane[index]), *sorted((int(face[k]), int(face[(k + 1) % 3]))))
            other = owner.setdefault(edge, index)  # type: ignore[arg-type]
            if other != index:
                parent[root(index)] = root(other)
    groups: dict[int, list[int]] = {}
    for index in range(len(faces)):
        groups.setdefault(root(index), []).append(index)
    return [np.array(g) for g in groups.values()]


def _convex_outline(
    vertices: np.ndarray, faces: np.ndarray, normal: np.ndarray
) -> np.ndarray | None:
    """The corners of a flat patch whose triangles fill its convex outline exactly, else None."""
    if len(faces) == 1:
        return vertices[faces[0]]
    from scipy.spatial import ConvexHull, QhullError

    u = np.cross(normal, [1.0, 0.0, 0.0])
    if np.linalg.norm(u) < 0.5:
        u = np.cross(normal, [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    corners = vertices[np.unique(faces)]
    flat = np.column_stack([corners @ u, corners @ v])
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
    try:
        hull = ConvexHull(flat)
    except (QhullError, ValueError):
        return None
    if abs(hull.volume - area) > 1e-9 * max(area, 1e-12) + 1e-12:
        return None  # the patch is not convex, or has a hole
    return corners[hull.vertices]


def _distance_to_triangles(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Distance from each point to the nearest of the triangles (points (p, 3), triangles (t, 3, 3))."""
    p = points[:, None, :]
    a, b, c = triangles[None, :, 0], triangles[None, :, 1], triangles[None, :, 2]
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = np.sum(ab * ap, -1), np.sum(ac * ap, -1)
    bp = p - b
    d3, d4 = np.sum(ab * bp, -1), np.sum(ac * bp, -1)
    cp = p - c
    d5, d6 = np.sum(ab * cp, -1), np.sum(ac * cp, -1)
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        denominator = va + vb + vc
        v = np.where(denominator != 0, vb / denominator, 0.0)
        w = np.where(denominator != 0, vc / denominator, 0.0)
        closest = a + ab * v[..., None] + ac * w[..., None]  # inside the face
        t_ab = np.clip(d1 / np.where(d1 - d3 != 0, d1 - d3, 1.0), 0, 1)
        t_ac = np.clip(d2 / np.where(d2 - d6 != 0, d2 - d6, 1.0), 0, 1)
        bc = c - b
        t_bc = np.clip(
            np.sum(bc * bp, -1) / np.where(np.sum(bc * bc, -1) != 0, np.sum(bc * bc, -1), 1.0), 0, 1
        )
    on_edges = [a + ab * t_ab[..., None], a + ac * t_ac[..., None], b + bc * t_bc[..., None]]
    inside = (va >= 0) & (vb >= 0) & (vc >= 0)
    distances = [np.linalg.norm(p - e, axis=-1) for e in on_edges]
    distances.append(np.where(inside, np.linalg.norm(p - closest, axis=-1), np.inf))
    return np.min(np.stack(distances), axis=(0, 2))
