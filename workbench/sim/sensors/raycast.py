"""Exact ray casting against convex shapes, vectorised with numpy.

A :class:`ShapeTable` holds shapes of seven kinds in their own frames G (Drake's
conventions: a box centred at G's origin, a cylinder and capsule along G's z,
an ellipsoid with semi-axes along G's axes, a half space whose surface is
G's z = 0 plane with the solid below it, a convex polytope as half planes), and
each shape's pose X_WG. :func:`cast_rays` returns, for each ray, the distance to
the first surface it crosses at or beyond ``t_min`` (inf when none within
``t_max``); a ray that starts inside a shape crosses its surface on the way out.

Every kind is convex, so a ray meets a shape in one interval ``[t_in, t_out]``:
boxes and polytopes by slabs, spheres, ellipsoids and cylinder sides by the
quadratic, capsules as the union of a cylinder and two spheres.

Broad phase (what a BVH would save): shapes whose bounding sphere lies wholly
beyond ``t_max`` (or before ``t_min``) from the origin are dropped; the rays are
sorted by azimuth about the sensor's z axis, and each shape is tested only
against the rays inside the azimuth interval its bounding sphere spans; the
pairs left are checked against the bounding sphere exactly before the narrow
phase. So the work per ray grows with the shapes near that ray, not with the
shapes in the world.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

BOX, SPHERE, CYLINDER, CAPSULE, ELLIPSOID, HALFSPACE, CONVEX = range(7)
KIND_NAMES = ("box", "sphere", "cylinder", "capsule", "ellipsoid", "half space", "convex")
_TINY = 1e-300


@dataclass
class ShapeTable:
    """Shapes and their poses in W, one row per shape.

    Attributes:
        kind: (n,) kind codes (``BOX`` ...).
        params: (n, 3) size parameters: box half extents; sphere (r, 0, 0);
            cylinder and capsule (r, half length, 0); ellipsoid semi-axes; unused for
            half spaces and polytopes.
        R_WG: (n, 3, 3) rotations of the shape frames in W.
        p_WG: (n, 3) origins of the shape frames in W.
        center_G: (n, 3) centre of each shape's bounding sphere in G.
        radius: (n,) bounding sphere radii (inf for half spaces).
        planes: per polytope row, an (m, 4) array of ``n_x n_y n_z b`` with ``n . x <= b``
            inside (in G), keyed by row.
    """

    kind: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    params: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    R_WG: np.ndarray = field(default_factory=lambda: np.zeros((0, 3, 3)))
    p_WG: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    center_G: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    radius: np.ndarray = field(default_factory=lambda: np.zeros(0))
    planes: dict[int, np.ndarray] = field(default_factory=dict)

    def __len__(self) -> int:
        return int(self.kind.shape[0])


def cast_rays(
    shapes: ShapeTable,
    origin: np.ndarray,
    directions: np.ndarray,
    t_min: float = 0.0,
    t_max: float = np.inf,
    *,
    R_WS: np.ndarray | None = None,
    active: np.ndarray | None = None,
) -> np.ndarray:
    """Distance along each ray to the first surface crossed in ``[t_min, t_max]``.

    Args:
        shapes: The shapes, posed in W.
        origin: (3,) the rays' common origin in W.
        directions: (B, 3) unit directions in W.
        t_min: Crossings closer than this are ignored, m.
        t_max: Crossings beyond this are ignored (reported as inf), m.
        R_WS: Rotation whose z axis the azimuth sort uses (default: W's z).
        active: (n,) bool mask of the shapes to consider (default: all).

    Returns:
        (B,) distances, inf where a ray crosses nothing in range.
    """
    origin = np.asarray(origin, dtype=float).reshape(3)
    directions = np.asarray(directions, dtype=float).reshape(-1, 3)
    result = np.full(directions.shape[0], np.inf)
    if len(shapes) == 0 or directions.shape[0] == 0:
        return result
    beams, rows, nearest = _candidate_pairs(shapes, origin, directions, t_min, t_max, R_WS, active)
    if beams.size == 0:
        return result
    # nearest first: each beam's pair whose bounding sphere starts first, then only the
    # pairs whose sphere starts before the hit found (occluded shapes are skipped)
    unbounded = ~np.isfinite(nearest)  # half spaces: always tested
    floor = np.full(directions.shape[0], np.inf)
    np.minimum.at(floor, beams[~unbounded], nearest[~unbounded])
    first = unbounded | (nearest <= floor[beams])
    np.minimum.at(
        result, beams[first], _narrow(shapes, origin, directions, beams[first], rows[first], t_min)
    )
    rest = ~first & (nearest <= result[beams])
    if rest.any():
        np.minimum.at(
            result, beams[rest], _narrow(shapes, origin, directions, beams[rest], rows[rest], t_min)
        )
    result[result > t_max] = np.inf
    return result


def _narrow(
    shapes: ShapeTable,
    origin: np.ndarray,
    directions: np.ndarray,
    beams: np.ndarray,
    rows: np.ndarray,
    t_min: float,
) -> np.ndarray:
    """Exact first crossing of each (beam, shape) pair."""
    t = np.full(beams.shape[0], np.inf)
    R = shapes.R_WG[rows]
    o_G = np.einsum("pji,pj->pi", R, origin - shapes.p_WG[rows])
    d_G = np.einsum("pji,pj->pi", R, directions[beams])
    kinds = shapes.kind[rows]
    for kind, kernel in _KERNELS.items():
        pick = np.nonzero(kinds == kind)[0]
        if pick.size:
            t_in, t_out = kernel(o_G[pick], d_G[pick], shapes.params[rows[pick]])
            t[pick] = _first_crossing(t_in, t_out, t_min)
    pick = np.nonzero(kinds == CONVEX)[0]
    if pick.size:
        t[pick] = _convex(o_G[pick], d_G[pick], rows[pick], shapes.planes, t_min)
    return t


def _candidate_pairs(
    shapes: ShapeTable,
    origin: np.ndarray,
    directions: np.ndarray,
    t_min: float,
    t_max: float,
    R_WS: np.ndarray | None,
    active: np.ndarray | None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(beam, shape row, distance to the bounding sphere) of pairs whose ray may meet the sphere."""
    centers = np.einsum("nij,nj->ni", shapes.R_WG, shapes.center_G) + shapes.p_WG
    rel = centers - origin
    distance = np.linalg.norm(rel, axis=1)
    radius = shapes.radius
    infinite = ~np.isfinite(radius)
    keep = infinite | ((distance - radius <= t_max) & (distance + radius >= t_min))
    if active is not None:
        keep &= active
    rows = np.nonzero(keep)[0]
    if rows.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros(0)
    R = np.eye(3) if R_WS is None else np.asarray(R_WS, dtype=float)
    d_S = directions @ R
    rel_S = rel[rows] @ R
    beam_az = np.arctan2(d_S[:, 1], d_S[:, 0])
    polar = np.hypot(d_S[:, 0], d_S[:, 1]) < 1e-9
    order = np.argsort(beam_az, kind="stable")
    sorted_az = beam_az[order]
    rho = np.hypot(rel_S[:, 0], rel_S[:, 1])
    r = radius[rows]
    everywhere = infinite[rows] | (rho <= r)
    with np.errstate(divide="ignore", invalid="ignore"):
        half = np.where(everywhere, np.pi, np.arcsin(np.clip(r / rho, 0.0, 1.0)) + 1e-9)
    center_az = np.arctan2(rel_S[:, 1], rel_S[:, 0])
    lows, highs, owners = [], [], []
    low, high = center_az - half, center_az + half
    # an interval that wraps past +-pi is split in two; "everywhere" covers all
    full = everywhere | (half >= np.pi)
    for lo, hi, mask in (
        (np.full(rows.size, -np.pi), np.full(rows.size, np.pi), full),
        (np.maximum(low, -np.pi), np.minimum(high, np.pi), ~full),
        (low + 2 * np.pi, np.full(rows.size, np.pi), ~full & (low < -np.pi)),
        (np.full(rows.size, -np.pi), high - 2 * np.pi, ~full & (high > np.pi)),
    ):
        lows.append(lo[mask])
        highs.append(hi[mask])
        owners.append(rows[mask])
    lo_all, hi_all, owner_all = np.concatenate(lows), np.concatenate(highs), np.concatenate(owners)
    start = np.searchsorted(sorted_az, lo_all, side="left")
    stop = np.searchsorted(sorted_az, hi_all, side="right")
    counts = np.maximum(stop - start, 0)
    total = int(counts.sum())
    offsets = np.repeat(start - (np.cumsum(counts) - counts), counts)
    beams = order[np.arange(total) + offsets]
    pair_rows = np.repeat(owner_all, counts)
    if polar.any():  # straight up or down: no azimuth, test every shape
        up = np.nonzero(polar)[0]
        sideways = ~polar[beams]
        beams = np.concatenate([beams[sideways], np.repeat(up, rows.size)])
        pair_rows = np.concatenate([pair_rows[sideways], np.tile(rows, up.size)])
    # exact bounding-sphere test of each pair
    rel_p = rel[pair_rows]
    along = np.einsum("pi,pi->p", rel_p, directions[beams])
    miss2 = np.einsum("pi,pi->p", rel_p, rel_p) - along**2
    r_p = radius[pair_rows]
    finite = np.isfinite(r_p)
    hit = ~finite | (
        (miss2 <= r_p**2 * (1 + 1e-9) + 1e-12) & (along + r_p >= t_min) & (along - r_p <= t_max)
    )
    with np.errstate(invalid="ignore"):
        entry = np.where(finite, along - np.sqrt(np.maximum(r_p**2 - miss2, 0.0)), -np.inf)
    return beams[hit], pair_rows[hit], entry[hit]


def _first_crossing(t_in: np.ndarray, t_out: np.ndarray, t_min: float) -> np.ndarray:
    """The first of the interval's ends at or beyond ``t_min`` (inf for an empty interval)."""
    empty = ~(t_in <= t_out)
    t = np.where(t_in >= t_min, t_in, np.where(t_out >= t_min, t_out, np.inf))
    t[empty] = np.inf
    return t


def _slab(o: np.ndarray, d: np.ndarray, half: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where the rays are inside ``|x_i| <= half_i`` for every column i."""
    safe = np.where(np.abs(d) < _TINY, _TINY, d)
    with np.errstate(over="ignore", invalid="ignore"):
        a = (-half - o) / safe
        b = (half - o) / safe
    return np.minimum(a, b).max(axis=1), np.maximum(a, b).min(axis=1)


def _quadratic(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Roots of ``a t^2 + 2 b t + c`` as an interval (empty as (inf, -inf)); a == 0: all or none."""
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        root = np.sqrt(np.maximum(disc, 0.0))
        t_in = np.where(disc >= 0, (-b - root) / a, np.inf)
        t_out = np.where(disc >= 0, (-b + root) / a, -np.inf)
    flat = a <= _TINY
    t_in = np.where(flat, np.where(c <= 0, -np.inf, np.inf), t_in)
    t_out = np.where(flat, np.where(c <= 0, np.inf, -np.inf), t_out)
    return t_in, t_out


def _box(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return _slab(o, d, p)


def _sphere(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    r = p[:, 0]
    return _quadratic(
        np.einsum("pi,pi->p", d, d),
        np.einsum("pi,pi->p", o, d),
        np.einsum("pi,pi->p", o, o) - r * r,
    )


def _ellipsoid(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return _sphere(o / p, d / p, np.ones_like(p))


def _side(o: np.ndarray, d: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The infinite cylinder ``x^2 + y^2 <= r^2``."""
    return _quadratic(
        d[:, 0] ** 2 + d[:, 1] ** 2,
        o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1],
        o[:, 0] ** 2 + o[:, 1] ** 2 - r * r,
    )


def _cylinder(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    s_in, s_out = _side(o, d, p[:, 0])
    z_in, z_out = _slab(o[:, 2:3], d[:, 2:3], p[:, 1:2])
    return np.maximum(s_in, z_in), np.minimum(s_out, z_out)


def _capsule(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    t_in, t_out = _cylinder(o, d, p)
    radius = np.stack([p[:, 0], np.zeros(len(p)), np.zeros(len(p))], axis=1)
    for sign in (-1.0, 1.0):
        end = o.copy()
        end[:, 2] -= sign * p[:, 1]
        s_in, s_out = _sphere(end, d, radius)
        present = s_in <= s_out
        none = ~(t_in <= t_out)
        t_in = np.where(present, np.where(none, s_in, np.minimum(t_in, s_in)), t_in)
        t_out = np.where(present, np.where(none, s_out, np.maximum(t_out, s_out)), t_out)
    return t_in, t_out


def _halfspace(o: np.ndarray, d: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    inside = o[:, 2] <= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -o[:, 2] / d[:, 2]
    down = d[:, 2] < 0
    up = d[:, 2] > 0
    t_in = np.where(inside, -np.inf, np.where(down, t, np.inf))
    t_out = np.where(inside, np.where(up, t, np.inf), np.where(down, np.inf, -np.inf))
    return t_in, t_out


def _convex(
    o: np.ndarray, d: np.ndarray, rows: np.ndarray, planes: dict[int, np.ndarray], t_min: float
) -> np.ndarray:
    t = np.full(rows.shape[0], np.inf)
    for row in np.unique(rows):
        pick = np.nonzero(rows == row)[0]
        P = planes[int(row)]
        normal, offset = P[:, :3], P[:, 3]
        along = d[pick] @ normal.T  # (k, m)
        gap = offset[None, :] - o[pick] @ normal.T  # n . x <= b  <=>  gap - t along >= 0
        with np.errstate(divide="ignore", invalid="ignore"):
            cross = gap / np.where(np.abs(along) < _TINY, _TINY, along)
        entering = along < 0
        leaving = along > 0
        parallel_out = (~entering & ~leaving) & (gap < 0)
        t_in = np.where(entering, cross, -np.inf).max(axis=1)
        t_out = np.where(leaving, cross, np.inf).min(axis=1)
        t_in[parallel_out.any(axis=1)] = np.inf
        t[pick] = _first_crossing(t_in, t_out, t_min)
    return t


_KERNELS = {
    BOX: _box,
    SPHERE: _sphere,
    CYLINDER: _cylinder,
    CAPSULE: _capsule,
    ELLIPSOID: _ellipsoid,
    HALFSPACE: _halfspace,
}
