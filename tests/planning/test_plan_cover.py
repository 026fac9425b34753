"""Sphere covers contain their shapes and bulge out little; the layout groups them faithfully."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.spatial import ConvexHull

from workbench.planning import sphere_cover
from workbench.planning.sphere_cover import _cover_box, _cover_cylinder, _cover_hull
from workbench.planning.sphere_layout import CLUSTER_SIZE, build_layout


def _outside(points: np.ndarray, centres: np.ndarray, radii: np.ndarray) -> np.ndarray:
    """How far each point lies outside the union of the spheres (negative: inside)."""
    return (np.linalg.norm(points[:, None] - centres[None], axis=2) - radii).min(axis=1)


def _bulge(hull_points: np.ndarray, centres: np.ndarray, radii: np.ndarray) -> float:
    """Largest distance a sphere reaches beyond the hull's face planes, m."""
    equations = ConvexHull(hull_points).equations
    # the farthest point of a sphere beyond a plane: centre's signed distance + radius
    return float((centres @ equations[:, :3].T + equations[:, 3] + radii[:, None]).max())


def _random_hull(seed: int, scale) -> np.ndarray:
    points = np.random.default_rng(seed).normal(size=(200, 3)) * scale
    return points[ConvexHull(points).vertices]


@pytest.mark.parametrize("seed", [3, 4])
def test_hull_cover_contains_the_hull_and_bulges_about_the_allowed_amount(seed):
    hull = _random_hull(seed, (0.025, 0.02, 0.06))  # a robot link's size
    centres, radii = _cover_hull(hull, seed=0)
    mesh = trimesh.convex.convex_hull(hull)
    # independent samples (another seed, uniform rather than even) of surface and volume
    surface, _ = trimesh.sample.sample_surface(mesh, 30000, seed=11)
    equations = ConvexHull(hull).equations
    box = np.random.default_rng(12).uniform(hull.min(axis=0), hull.max(axis=0), (20000, 3))
    volume = box[(box @ equations[:, :3].T + equations[:, 3]).max(axis=1) < 0]
    assert _outside(surface, centres, radii).max() <= 0.0
    assert _outside(volume, centres, radii).max() <= 0.0
    assert (centres @ equations[:, :3].T + equations[:, 3]).max() < 0.0  # centres inside
    spacing = np.sqrt(mesh.area / sphere_cover.SURFACE_SAMPLES)
    assert _bulge(hull, centres, radii) <= sphere_cover.COVER_BULGE + 2 * spacing
    assert len(radii) <= sphere_cover.MAX_SPHERES_PER_SHAPE


def test_box_and_cylinder_covers_contain_them():
    half = np.array([0.04, 0.1, 0.02])
    centres, radii = _cover_box(half)
    box = trimesh.creation.box(extents=2 * half)
    surface, _ = trimesh.sample.sample_surface(box, 20000, seed=1)
    assert _outside(surface, centres, radii).max() <= 0.0
    corners = np.array(np.meshgrid(*[[-h, h] for h in half], indexing="ij")).reshape(3, -1).T
    assert _outside(corners, centres, radii).max() <= 0.0
    assert _bulge(corners, centres, radii) < 2 * sphere_cover.COVER_BULGE

    centres, radii = _cover_cylinder(0.03, 0.2)
    cylinder = trimesh.creation.cylinder(radius=0.03, height=0.2, sections=256)
    surface, _ = trimesh.sample.sample_surface(cylinder, 20000, seed=2)
    assert _outside(surface, centres, radii).max() <= 0.0
    rim = np.stack([0.03 * np.cos(np.linspace(0, 6.3, 200)), 0.03 * np.sin(np.linspace(0, 6.3, 200)), np.full(200, 0.1)], 1)  # fmt: skip
    assert _outside(rim, centres, radii).max() <= 0.0


def test_a_thin_plate_stays_within_the_sphere_budget():
    half = np.array([0.002, 0.3, 0.3])
    centres, radii = _cover_box(half)
    assert len(radii) <= sphere_cover.MAX_SPHERES_PER_SHAPE
    surface, _ = trimesh.sample.sample_surface(
        trimesh.creation.box(extents=2 * half), 20000, seed=3
    )
    assert _outside(surface, centres, radii).max() <= 0.0


def test_layout_groups_each_body_into_contiguous_enclosed_clusters():
    rng = np.random.default_rng(5)
    centres = rng.normal(size=(90, 3)) * 0.1
    radii = rng.uniform(0.005, 0.03, size=90)
    body = np.repeat([7, 3, 9], 30)
    slot = np.repeat([1, 1, 2], 30)
    layout = build_layout(centres, radii, body, slot)
    assert sorted(layout.order.tolist()) == list(range(90))
    c, r, b = centres[layout.order], radii[layout.order], body[layout.order]
    assert layout.part_body.tolist() == [7, 3, 9]
    for p, (c0, c1) in enumerate(layout.part_clusters):
        first, last = layout.cluster_spheres[c0, 0], layout.cluster_spheres[c1 - 1, 1]
        assert set(b[first:last]) == {layout.part_body[p]}
        assert last - first == 30
        reach = np.linalg.norm(c[first:last] - layout.part_centre[p], axis=1) + r[first:last]
        assert reach.max() <= layout.part_radius[p] + 1e-12
        assert set(layout.cluster_slot[c0:c1]) == {layout.part_slot[p]}
    spans = layout.cluster_spheres
    assert spans[0, 0] == 0 and spans[-1, 1] == 90
    assert np.all(spans[1:, 0] == spans[:-1, 1])  # contiguous, in order
    for k, (s0, s1) in enumerate(spans):
        assert 1 <= s1 - s0 <= CLUSTER_SIZE
        reach = np.linalg.norm(c[s0:s1] - layout.cluster_centre[k], axis=1) + r[s0:s1]
        assert reach.max() <= layout.cluster_radius[k] + 1e-12
