"""Correlative scan matching and the likelihood field."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import LikelihoodField, match_scan, read_log
from workbench.mapping.geometry import compose, transform_points
from workbench.mapping.scan import densify
from workbench.mapping.simulate import demo_world, simulate_scans


def _brute_force(field, points, guess, window, angular_window, step):
    """Exhaustive fine search (the reference the branch and bound must equal)."""
    best = (-1.0, None)
    # The lattice the matcher searches: whole blocks of `factor` cells centred on the guess.
    w = int(np.ceil(window / field.resolution))
    blocks = int(np.ceil((2 * w + 1) / field.factor))
    first = -((blocks * field.factor - 1) // 2)
    offsets = range(first, first + blocks * field.factor)
    n_ang = int(np.ceil(angular_window / step))
    for dt in range(-n_ang, n_ang + 1):
        for du in offsets:
            for dv in offsets:
                pose = guess + np.array([du * field.resolution, dv * field.resolution, dt * step])
                s = field.score(transform_points(pose, points))
                if s > best[0]:
                    best = (s, pose)
    return best


def test_coarse_field_bounds_the_fine_field_over_each_block():
    rng = np.random.default_rng(0)
    field = LikelihoodField(rng.uniform(0, 3, (200, 2)), 0.05, 0.05, margin=0.5, factor=4)
    fine, coarse = field.fine, field.coarse
    rows, cols = fine.shape
    for _ in range(200):
        i, j = rng.integers(1, rows - 5), rng.integers(1, cols - 5)
        assert coarse[i, j] == pytest.approx(fine[i : i + 4, j : j + 4].max())


def test_branch_and_bound_equals_exhaustive_search():
    scans = simulate_scans(demo_world(), np.array([[2.0, 1.5, 0.3], [2.2, 1.6, 0.35]]), seed=4)
    field = LikelihoodField(
        transform_points(scans[0].reference, densify(scans[0].points())), 0.05, 0.05
    )
    points = scans[1].points()[::6]
    guess = np.array([2.15, 1.62, 0.33])
    result = match_scan(
        field,
        points,
        guess,
        linear_window=0.1,
        angular_window=np.radians(2),
        refine=False,
        angular_step=np.radians(1.0),
    )
    score, pose = _brute_force(field, points, guess, 0.1, np.radians(2), np.radians(1.0))
    assert field.score(transform_points(result.grid_pose, points)) == pytest.approx(score)
    np.testing.assert_allclose(result.grid_pose, pose, atol=1e-9)
    assert result.expanded < 8 * 8 * 5  # far fewer blocks than the exhaustive search


def test_recovers_a_known_offset_in_a_simulated_room_below_one_cell():
    true = np.array([[3.0, 3.0, 0.2], [3.3, 3.1, 0.28]])
    scans = simulate_scans(demo_world(), true, range_noise=0.005, seed=5)
    field = LikelihoodField(transform_points(true[0], densify(scans[0].points())), 0.05, 0.05)
    guess = compose(true[1], np.array([0.17, -0.21, np.radians(6.0)]))
    result = match_scan(field, scans[1].points(), guess)
    assert np.hypot(*(result.pose[:2] - true[1, :2])) < 0.025  # half a cell
    assert abs(result.pose[2] - true[1, 2]) < np.radians(0.5)
    assert result.score > 0.8


def test_recovers_a_known_offset_between_two_real_intel_scans(intel_log):
    log = read_log(intel_log)
    a, b = log.scans[300], log.scans[301]
    field = LikelihoodField(transform_points(a.reference, densify(a.points(20.0))), 0.05, 0.05)
    offset = np.array([0.25, -0.2, np.radians(7.0)])
    guess = compose(b.reference, offset)
    result = match_scan(field, b.points(20.0), guess, prior=(0.2, np.radians(10.0)))
    # The corrected log's own pose is the reference: recovered to within one 5 cm cell.
    assert np.hypot(*(result.pose[:2] - b.reference[:2])) < 0.05
    assert abs(result.pose[2] - b.reference[2]) < np.radians(1.0)


def test_the_odometry_prior_keeps_a_corridor_match_near_the_guess():
    # Two long parallel walls: every shift along the corridor fits equally well.
    xs = np.linspace(-10, 10, 800)
    walls = np.concatenate(
        [
            np.column_stack([xs, np.full_like(xs, 1.0)]),
            np.column_stack([xs, np.full_like(xs, -1.0)]),
        ]
    )
    field = LikelihoodField(walls, 0.05, 0.05)
    points = np.concatenate(
        [
            np.column_stack([np.linspace(-3, 3, 60), np.full(60, 1.0)]),
            np.column_stack([np.linspace(-3, 3, 60), np.full(60, -1.0)]),
        ]
    )
    guess = np.array([0.12, 0.03, 0.0])
    result = match_scan(field, points, guess, prior=(0.2, np.radians(10.0)))
    assert abs(result.pose[0] - 0.12) < 0.06  # along the corridor: stays at the guess
    assert abs(result.pose[1]) < 0.02  # across: snapped onto the walls
