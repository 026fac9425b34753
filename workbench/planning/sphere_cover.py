"""Spheres that cover collision shapes: boxes, cylinders, capsules and convex meshes.

Each function returns sphere centres (k, 3) in the shape's own frame and radii
(k,) in metres whose union contains the shape. Boxes, cylinders (through the
prism circumscribing them) and meshes (through their convex hulls, which Drake
checks) are covered by :func:`_cover_hull`: spheres centred deep inside that
bulge out of the surface by about :data:`COVER_BULGE`. :func:`load_sphere_model`
reads hand-made decompositions instead.
"""

from __future__ import annotations

import math

import numpy as np

#: How far a covering sphere may reach beyond the face nearest its centre, before the
#: surface sampling gap is added, m. Thinner is a tighter model with more spheres.
COVER_BULGE = 0.008
#: Most spheres per shape: a thin or flat shape would need many small spheres, so its
#: allowed bulge grows until it fits.
MAX_SPHERES_PER_SHAPE = 160
#: Most surface samples per shape (each sphere grows by their spacing, so denser is
#: tighter; a shape gets about one per (bulge / 4)^2 of its area).
SURFACE_SAMPLES = 12000
#: Most candidate centres per shape, drawn uniformly inside it.
CANDIDATES = 4000


def _cover_box(half: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Spheres enclosing a box of half extents ``half`` (centred at the origin)."""
    corners = np.array(np.meshgrid(*[[-h, h] for h in half], indexing="ij")).reshape(3, -1).T
    return _cached_hull_cover(corners)


def _cover_cylinder(radius: float, length: float, sides: int = 32) -> tuple[np.ndarray, np.ndarray]:
    """Spheres enclosing a solid cylinder along z (through the prism circumscribing it)."""
    outer = radius / math.cos(math.pi / sides)
    angle = 2 * math.pi * np.arange(sides) / sides
    ring = np.stack([outer * np.cos(angle), outer * np.sin(angle)], axis=1)
    prism = np.vstack(
        [np.column_stack([ring, np.full(sides, z)]) for z in (-length / 2, length / 2)]
    )
    return _cached_hull_cover(prism)


def hull_vertices(shape) -> np.ndarray:
    """Vertices (k, 3) of a Mesh or Convex shape's convex hull (scaled), in the shape's frame.

    Drake checks mesh geometry as its convex hull, so the hull is what must be covered.
    """
    hull = shape.GetConvexHull()
    return np.array([hull.vertex(i) for i in range(hull.num_vertices())], dtype=float)


#: Bumped whenever the cover algorithm changes, so stale covers on disk are ignored.
COVER_VERSION = 1


def _cached_hull_cover(points: np.ndarray, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Spheres covering the convex hull of ``points``, cached in the process and on disk
    (:mod:`workbench.planning.array_cache`): a robot's covers are the same every run."""
    from workbench.planning.array_cache import cached_arrays, digest

    points = np.asarray(points, float)
    settings = (
        COVER_VERSION,
        seed,
        COVER_BULGE,
        MAX_SPHERES_PER_SHAPE,
        SURFACE_SAMPLES,
        CANDIDATES,
    )
    key = digest(points.round(9), settings)

    def compute() -> dict[str, np.ndarray]:
        centres, radii = _cover_hull(points, seed)
        return {"centres": centres, "radii": radii}

    stored = cached_arrays("sphere-covers", key, compute)
    return stored["centres"].copy(), stored["radii"].copy()


def _cover_hull(points: np.ndarray, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Few spheres whose union contains the convex hull of ``points`` and bulges out little.

    A sphere centred at a point of depth ``d`` (its distance to the nearest face
    plane) with radius ``d + bulge`` crosses no face plane by more than ``bulge``.
    Among thousands of such candidates inside the hull, a greedy set cover picks
    spheres until every surface sample (and a set of interior samples) is
    covered; radii then grow by the samples' spacing so the surface between
    samples is covered too. When that needs more than
    :data:`MAX_SPHERES_PER_SHAPE` spheres (a thin plate) the bulge doubles.
    """
    import trimesh
    from scipy.spatial import ConvexHull, QhullError

    rng = np.random.default_rng(seed)
    points = np.asarray(points, float)
    lo, hi = points.min(axis=0), points.max(axis=0)
    try:
        convex = ConvexHull(points)
    except QhullError:  # flat or degenerate: one sphere around its bounding box
        centre = (lo + hi) / 2
        return centre[None], np.array([np.linalg.norm(points - centre, axis=1).max()])
    equations = convex.equations
    hull = points[convex.vertices]
    mesh = trimesh.convex.convex_hull(hull)
    # samples about a quarter of the bulge apart (fewer on small shapes, which a few
    # spheres cover: the cover's cost grows with samples times candidates)
    wanted = int(np.clip(mesh.area / (COVER_BULGE / 4) ** 2, 500, SURFACE_SAMPLES))
    surface, _ = trimesh.sample.sample_surface_even(mesh, wanted, seed=seed)
    spacing = math.sqrt(max(mesh.area, 1e-12) / max(len(surface), 1))
    count = int(np.clip(len(surface) // 3, 300, CANDIDATES))
    interior_count = count // 4
    candidates = np.zeros((0, 3))
    for _ in range(20):  # rejection sampling; a hull fills at least a sliver of its box
        sample = rng.uniform(lo, hi, size=(4 * count, 3))
        depth = -(sample @ equations[:, :3].T + equations[:, 3]).max(axis=1)
        candidates = np.vstack([candidates, sample[depth > 0]])
        if len(candidates) >= count + interior_count:
            break
    interior = candidates[count : count + interior_count]
    centroid = hull.mean(axis=0)
    targets = np.vstack([hull, surface, interior])
    # Points just inside the hull's vertices and some surface samples reach them within the
    # bulge, so sharp corners and edges are covered without a sphere that bulges more.
    edge = np.vstack([hull, surface[rng.choice(len(surface), min(count, len(surface)), False)]])
    inward = centroid - edge
    inward_length = np.linalg.norm(inward, axis=1, keepdims=True)
    inward /= np.maximum(inward_length, 1e-12)
    extent = float(np.linalg.norm(hi - lo))
    bulge = COVER_BULGE
    while True:
        near_edge = edge + inward * np.minimum(0.9 * bulge, 0.5 * inward_length)
        centres = np.vstack([candidates[:count], centroid, near_edge])
        depth = np.maximum(-(centres @ equations[:, :3].T + equations[:, 3]).max(axis=1), 0.0)
        limit = MAX_SPHERES_PER_SHAPE if bulge <= extent else len(centres)
        cover = _greedy_cover(targets, centres, depth + bulge, limit)
        if cover is not None:
            chosen, radii = cover
            return centres[chosen], radii + spacing
        bulge *= 2


def _greedy_cover(
    targets: np.ndarray, centres: np.ndarray, reach: np.ndarray, limit: int
) -> tuple[np.ndarray, np.ndarray] | None:
    """Greedy set cover of ``targets`` by balls (centres, reach): chosen indices and radii.

    A target no ball reaches is covered by growing the ball that misses it least.
    Returns None as soon as more than ``limit`` balls would be needed.
    """
    from scipy.sparse import csr_matrix
    from scipy.spatial import cKDTree

    reach = reach.copy()
    tree = cKDTree(targets)
    members = tree.query_ball_point(centres, reach)
    rows = np.repeat(np.arange(len(centres)), [len(m) for m in members])
    cols = np.concatenate([np.asarray(m, dtype=np.int64) for m in members])
    covers = csr_matrix((np.ones(len(cols), bool), (rows, cols)), (len(centres), len(targets)))
    covered_by = covers.T.tocsr()
    counts = np.diff(covers.indptr).astype(np.int64)
    uncovered = np.ones(len(targets), dtype=bool)
    chosen: list[int] = []
    while uncovered.any():
        k = int(np.argmax(counts))
        if counts[k] == 0:
            t = int(np.nonzero(uncovered)[0][0])
            miss = np.linalg.norm(centres - targets[t], axis=1) - reach
            k = int(np.argmin(miss))
            reach[k] += miss[k] + 1e-12
            row = np.nonzero(np.linalg.norm(targets - centres[k], axis=1) <= reach[k])[0]
        else:
            row = covers.indices[covers.indptr[k] : covers.indptr[k + 1]]
        new = row[uncovered[row]]
        chosen.append(k)
        if len(chosen) > limit:
            return None
        uncovered[new] = False
        if len(new):
            # every ball covering a newly covered target now covers one fewer uncovered
            starts, ends = covered_by.indptr[new], covered_by.indptr[new + 1]
            lengths = ends - starts
            offsets = np.arange(lengths.sum()) - np.repeat(np.cumsum(lengths) - lengths, lengths)
            balls = covered_by.indices[np.repeat(starts, lengths) + offsets]
            counts -= np.bincount(balls, minlength=len(counts))
        counts[k] = 0
    index = np.array(chosen, dtype=int)
    return index, reach[index]


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
        return _cached_hull_cover(hull_vertices(shape))
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
