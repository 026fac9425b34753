"""A bounding-sphere hierarchy over a robot's spheres: body parts, then small clusters.

Checking hundreds of spheres one by one costs more than the question needs:
most of a link is far from every obstacle and from the other links. The
spheres are therefore grouped, per robot body, into clusters of a few nearby
spheres, each cluster and each body enclosed by a bounding sphere. A check
tests a body's bounding sphere first, then its clusters', and looks at single
spheres only where a cluster's bounding sphere touches something.

:func:`build_layout` reorders the spheres so every cluster (and every body)
is a contiguous range, which is what the compiled kernel walks.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Most spheres in one cluster.
CLUSTER_SIZE = 8


@dataclass
class SphereLayout:
    """Spheres reordered into bodies and clusters, with their bounding spheres.

    Attributes:
        order: (S,) the input sphere indices in their new order.
        part_body: (P,) body id of each part (one part per body with spheres).
        part_slot: (P,) the moving frame the part rides in.
        part_centre, part_radius: (P, 3) in the slot's frame and (P,) bounding spheres, m.
        part_clusters: (P, 2) the part's clusters, [start, end).
        cluster_slot: (C,) the moving frame of each cluster.
        cluster_centre, cluster_radius: (C, 3) and (C,) bounding spheres, m.
        cluster_spheres: (C, 2) the cluster's spheres (in the new order), [start, end).
    """

    order: np.ndarray
    part_body: np.ndarray
    part_slot: np.ndarray
    part_centre: np.ndarray
    part_radius: np.ndarray
    part_clusters: np.ndarray
    cluster_slot: np.ndarray
    cluster_centre: np.ndarray
    cluster_radius: np.ndarray
    cluster_spheres: np.ndarray


def bounding_sphere(centres: np.ndarray, radii: np.ndarray) -> tuple[np.ndarray, float]:
    """A sphere enclosing the given spheres (centred on their centres' bounding box)."""
    centre = (centres.min(axis=0) + centres.max(axis=0)) / 2
    return centre, float(np.max(np.linalg.norm(centres - centre, axis=1) + radii))


def _split(indices: np.ndarray, centres: np.ndarray, size: int) -> list[np.ndarray]:
    """Halve along the widest axis at the median until every group has at most ``size``."""
    if len(indices) <= size:
        return [indices]
    points = centres[indices]
    axis = int(np.argmax(points.max(axis=0) - points.min(axis=0)))
    ranked = indices[np.argsort(points[:, axis], kind="stable")]
    half = len(ranked) // 2
    return _split(ranked[:half], centres, size) + _split(ranked[half:], centres, size)


def build_layout(
    centres: np.ndarray,
    radii: np.ndarray,
    body: np.ndarray,
    slot: np.ndarray,
    cluster_size: int = CLUSTER_SIZE,
) -> SphereLayout:
    """Group spheres (centres in their slot's frame) by body, then into clusters.

    Args:
        centres: (S, 3) sphere centres in the frame of their slot, m.
        radii: (S,) radii, m.
        body: (S,) the body each sphere belongs to.
        slot: (S,) the moving frame each sphere rides in (the same for a body's spheres).
        cluster_size: Most spheres per cluster.
    """
    order: list[int] = []
    part_body, part_slot, part_centre, part_radius, part_clusters = [], [], [], [], []
    cluster_slot, cluster_centre, cluster_radius, cluster_spheres = [], [], [], []
    for b in dict.fromkeys(body.tolist()):  # bodies in order of first appearance
        members = np.nonzero(body == b)[0]
        first_cluster = len(cluster_slot)
        for group in _split(members, centres, cluster_size):
            c, r = bounding_sphere(centres[group], radii[group])
            cluster_spheres.append((len(order), len(order) + len(group)))
            order.extend(group.tolist())
            cluster_slot.append(int(slot[group[0]]))
            cluster_centre.append(c)
            cluster_radius.append(r)
        c, r = bounding_sphere(centres[members], radii[members])
        part_body.append(int(b))
        part_slot.append(int(slot[members[0]]))
        part_centre.append(c)
        part_radius.append(r)
        part_clusters.append((first_cluster, len(cluster_slot)))
    return SphereLayout(
        order=np.array(order, dtype=int),
        part_body=np.array(part_body, dtype=int),
        part_slot=np.array(part_slot, dtype=int),
        part_centre=np.array(part_centre, dtype=float).reshape(-1, 3),
        part_radius=np.array(part_radius, dtype=float),
        part_clusters=np.array(part_clusters, dtype=int).reshape(-1, 2),
        cluster_slot=np.array(cluster_slot, dtype=int),
        cluster_centre=np.array(cluster_centre, dtype=float).reshape(-1, 3),
        cluster_radius=np.array(cluster_radius, dtype=float),
        cluster_spheres=np.array(cluster_spheres, dtype=int).reshape(-1, 2),
    )
