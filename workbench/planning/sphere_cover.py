"""Spheres that cover collision shapes: boxes, cylinders, capsules and convex meshes.

Each function returns sphere centres (k, 3) in the shape's own frame and radii
(k,) in metres whose union contains the shape (up to the surface sampling gap
for meshes). :func:`load_sphere_model` reads hand-made decompositions instead.
"""

from __future__ import annotations

import math

import numpy as np


def _cover_box(half: np.ndarray, cells_per_edge: int = 3) -> tuple[np.ndarray, np.ndarray]:
    """Spheres enclosing a box of half extents ``half`` (centred at the origin)."""
    size = 2 * half
    cell = max(size.max() / cells_per_edge, size.min() / 2)
    counts = np.maximum(1, np.ceil(size / cell - 1e-9)).astype(int)
    step = size / counts
    axes = [(-half[i] + step[i] * (np.arange(counts[i]) + 0.5)) for i in range(3)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    radius = float(np.linalg.norm(step / 2))
    return grid, np.full(len(grid), radius)


def _cover_cylinder(radius: float, length: float) -> tuple[np.ndarray, np.ndarray]:
    """Spheres along the z axis enclosing a solid cylinder."""
    count = max(1, math.ceil(length / radius - 1e-9))
    step = length / count
    z = -length / 2 + step * (np.arange(count) + 0.5)
    centres = np.stack([np.zeros(count), np.zeros(count), z], axis=1)
    return centres, np.full(count, math.hypot(radius, step / 2))


def hull_vertices(shape) -> np.ndarray:
    """Vertices (k, 3) of a Mesh or Convex shape's convex hull (scaled), in the shape's frame.

    Drake checks mesh geometry as its convex hull, so the hull is what must be covered.
    """
    hull = shape.GetConvexHull()
    return np.array([hull.vertex(i) for i in range(hull.num_vertices())], dtype=float)


_MESH_COVERS: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}


def _cover_mesh(shape, seed: int = 0):
    """Spheres covering a mesh's convex hull (cached per hull: robots are rebuilt per scene)."""
    vertices = hull_vertices(shape)
    key = (vertices.shape, vertices.round(9).tobytes(), seed)
    if key not in _MESH_COVERS:
        _MESH_COVERS[key] = _cover_hull(vertices, seed)
    centres, radii = _MESH_COVERS[key]
    return centres.copy(), radii.copy()


def _cover_hull(hull: np.ndarray, seed: int):
    """Spheres covering a convex hull, centred deep inside it.

    Centres are k-means clusters of the hull's deepest interior points (near its
    medial axis), so every sphere is nearly as wide as the hull where it sits and
    bulges out of it little; each sphere reaches the farthest hull surface sample
    nearest to it, plus the sampling gap.
    """
    import trimesh
    from scipy.cluster.vq import kmeans2
    from scipy.spatial import ConvexHull

    rng = np.random.default_rng(seed)
    equations = ConvexHull(hull).equations
    lo, hi = hull.min(axis=0), hull.max(axis=0)
    candidates = rng.uniform(lo, hi, size=(60000, 3))
    depth = -(candidates @ equations[:, :3].T + equations[:, 3]).max(axis=1)
    inside = depth > 0
    mesh = trimesh.convex.convex_hull(hull)
    samples, _ = trimesh.sample.sample_surface_even(mesh, 4000, seed=seed)
    surface = np.vstack([hull, samples])
    spacing = math.sqrt(max(mesh.area, 1e-12) / max(len(samples), 1))
    extent = float(np.linalg.norm(hi - lo))
    count = int(np.clip(round(extent / 0.025), 2, 24))
    if inside.sum() < 10 * count:  # a flat or tiny hull: cluster its surface
        deep = surface
    else:
        deep = candidates[inside & (depth >= 0.6 * depth[inside].max())]
    count = min(count, len(deep))
    centres, _ = kmeans2(deep, count, seed=seed, minit="++")
    nearest = np.argmin(((surface[:, None, :] - centres[None]) ** 2).sum(-1), axis=1)
    keep_c, keep_r = [], []
    for k in range(len(centres)):
        members = surface[nearest == k]
        if len(members):
            keep_c.append(centres[k])
            keep_r.append(np.linalg.norm(members - centres[k], axis=1).max() + spacing)
    return np.array(keep_c), np.array(keep_r)


def cover_shape(shape) -> tuple[np.ndarray, np.ndarray]:
    """Centres (k, 3) in the shape's frame and radii (k,) of spheres covering a pydrake shape."""
    from pydrake.geometry import Box, Capsule, Convex, Cylinder, Ellipsoid, Mesh, Sphere

    if isinstance(shape, Sphere):
        return np.zeros((1, 3)), np.array([shape.radius()])
    if isinstance(shape, Box):
        return _cover_box(np.array([shape.width(), shape.depth(), shape.height()]) / 2)
    if isinstance(shape, Cylinder):
        return _cover_cylinder(shape.radius(), shape.length())
    if isinstance(shape, Capsule):
        r, length = shape.radius(), shape.length()
        count = max(2, math.ceil(length / r) + 1)
        z = np.linspace(-length / 2, length / 2, count)
        step = length / (count - 1)
        return np.stack([0 * z, 0 * z, z], 1), np.full(count, math.hypot(r, step / 2))
    if isinstance(shape, Ellipsoid):
        return _cover_box(np.array([shape.a(), shape.b(), shape.c()]))
    if isinstance(shape, Mesh | Convex):
        return _cover_mesh(shape)
    raise TypeError(f"no sphere cover for shape {type(shape).__name__}")


def load_sphere_model(path) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Spheres per link from a "spherized" URDF (every ``<collision>`` a ``<sphere>``).

    This is the format robot sphere decompositions ship in (e.g. the Panda's
    ``panda_spherized.urdf`` beside MotionBenchMaker's problems).

    Returns:
        ``{link: (centres (k, 3) in the link frame, radii (k,))}`` in metres.
    """
    from lxml import etree

    from workbench.errors import ModelError

    try:
        root = etree.parse(str(path)).getroot()
    except (OSError, etree.XMLSyntaxError) as exc:
        raise ModelError(f"cannot read the sphere model: {exc}", path=path) from None
    model: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for link in root.iter("link"):
        centres, radii = [], []
        for collision in link.iter("collision"):
            sphere = collision.find("geometry/sphere")
            if sphere is None:
                continue
            origin = collision.find("origin")
            xyz = origin.get("xyz", "0 0 0") if origin is not None else "0 0 0"
            centres.append([float(v) for v in xyz.split()])
            radii.append(float(sphere.get("radius")))
        if radii:
            model[link.get("name")] = (np.array(centres), np.array(radii))
    return model
