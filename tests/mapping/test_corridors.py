"""SLAM in long corridors: the simulated corridor log, degenerate matches, max-range readings."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import LikelihoodField, Scan, SlamConfig, build_map, match_scan, run_slam
from workbench.mapping.corridors import corridor_log, corridor_world
from workbench.mapping.evaluate import absolute_trajectory_error
from workbench.mapping.incremental import fuse_with_odometry, lean_on_odometry
from workbench.mapping.scan import densify
from workbench.mapping.uncertainty import score_surface_covariance


def _segment_distance(points: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """Distance from each point to the nearest segment."""
    a, b = segments[:, 0], segments[:, 1]
    ab = b - a
    t = ((points[:, None] - a[None]) * ab[None]).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-12)
    nearest = a[None] + np.clip(t, 0.0, 1.0)[..., None] * ab[None]
    return np.hypot(*(points[:, None] - nearest).transpose(2, 0, 1)).min(axis=1)


def test_the_corridor_log_is_seeded_and_has_no_return_readings():
    a, b = corridor_log(3, step=2.0), corridor_log(3, step=2.0)
    np.testing.assert_array_equal(a.odometry, b.odometry)
    np.testing.assert_array_equal(a.scans[5].ranges, b.scans[5].ranges)
    assert a.errors != corridor_log(4, step=2.0).errors
    ranges = np.concatenate([s.ranges for s in a.scans])
    assert (ranges == 30.0).any()  # beams along a corridor: no return
    assert len(a.scans[0].ranges) == 360
    # Two laps: the path comes back to where it started.
    assert np.hypot(*(a.truth[-1, :2] - a.truth[0, :2])) < 2.0


@pytest.mark.slow
def test_slam_on_the_corridor_log_is_accurate_and_puts_no_wall_where_there_is_none():
    log = corridor_log(0, step=0.25, length=30.0, depth=14.0)
    result = run_slam(log.scans)
    assert absolute_trajectory_error(log.odometry, log.truth) > 0.25
    assert absolute_trajectory_error(result.poses, log.truth) <= 0.15
    # The map: every occupied cell lies on (near) a true wall; none beyond the walls.
    grid = build_map(log.scans, result.poses, 0.05).to_map()
    iy, ix = np.nonzero(grid.data >= 65)
    centres = grid.cell_to_world(np.column_stack([ix, iy]))
    assert len(centres) > 1000
    far = _segment_distance(centres, log.world.segments) > 0.25
    assert far.sum() == 0, centres[far][:5]


def test_max_range_readings_never_mark_an_obstacle():
    # A sensor in a 2 m wide corridor: walls at y = +-1, nothing ahead or behind
    # within range. CARMEN's FLASER lines cannot say the sensor's range, so a reader
    # takes 81 m: the 30 m no-return readings look like real ones.
    world = corridor_world(60.0, 20.0)
    angles = -np.pi + 2 * np.pi * np.arange(360) / 360
    from workbench.mapping.simulate import raycast

    pose = np.array([10.0, 1.0, 0.0])
    ranges = raycast(world.segments, pose, angles, 30.0)
    assert ranges[180] == 30.0  # straight ahead: 50 m of corridor
    scan = Scan(0.0, ranges, angles, pose, max_range=81.0)
    grid = build_map([scan], pose[None], 0.05, max_range=30.0)
    occupied = grid.probabilities() > 0.6
    iy, ix = np.nonzero(occupied)
    centres = grid.to_map().cell_to_world(np.column_stack([ix, iy]))
    assert len(centres) > 0
    assert _segment_distance(centres, world.segments).max() < 0.1
    # Free space along the no-return beam straight ahead, up to (not past) 30 m.
    msg = grid.to_map()
    (ax, ay), (bx, by) = msg.world_to_cell(np.array([[35.0, 1.0], [41.0, 1.0]]))
    assert 0 <= msg.data[ay, ax] < 50  # seen once: free
    assert msg.data[by, bx] == -1 or bx >= msg.width
    # The same holds for a sensor that knows its range, and for infinite readings.
    for stated, value in ((30.0, 30.0), (30.0, np.inf)):
        r = np.where(ranges >= 30.0, value, ranges)
        grid = build_map([Scan(0.0, r, angles, pose, max_range=stated)], pose[None], 0.05)
        iy, ix = np.nonzero(grid.probabilities() > 0.6)
        centres = grid.to_map().cell_to_world(np.column_stack([ix, iy]))
        assert _segment_distance(centres, world.segments).max() < 0.1
    # Readings beyond the sensor's range (error codes such as a SICK's 81.83 m) mark nothing.
    r = np.where(ranges >= 30.0, 81.83, ranges)
    grid = build_map([Scan(0.0, r, angles, pose, max_range=81.0)], pose[None], 0.05)
    (ax, ay), _ = grid.to_map().world_to_cell(np.array([[35.0, 1.0], [41.0, 1.0]]))
    assert ax >= grid.width or not grid.observed[ay, ax]


def _corridor_field():
    xs = np.linspace(-10, 10, 800)
    walls = np.concatenate(
        [
            np.column_stack([xs, np.full_like(xs, 1.0)]),
            np.column_stack([xs, np.full_like(xs, -1.0)]),
        ]
    )
    points = np.concatenate(
        [
            np.column_stack([np.linspace(-3, 3, 60), np.full(60, 1.0)]),
            np.column_stack([np.linspace(-3, 3, 60), np.full(60, -1.0)]),
        ]
    )
    return LikelihoodField(walls, 0.05, 0.05), points


def test_a_corridor_match_is_unconstrained_along_the_corridor_and_odometry_fills_in():
    field, points = _corridor_field()
    guess = np.array([0.12, 0.03, 0.0])
    result = match_scan(field, points, guess, prior=(0.2, np.radians(10.0)), covariance=True)
    assert result.covariance is not None
    sx, sy, st = np.sqrt(np.diag(result.covariance))
    assert sx > 1.0  # along the corridor: nothing known
    assert sy < 0.05 and st < np.radians(1.0)  # across and in heading: well known
    # The fused pose keeps the odometry along the corridor, the match across it.
    odometry = np.array([0.31, 0.2, 0.0])
    fused = lean_on_odometry(result.pose, odometry, result.covariance)
    assert fused[0] == pytest.approx(0.31, abs=1e-9)
    assert fused[1] == pytest.approx(result.pose[1], abs=1e-9)
    # Weighed by the two variances: along the corridor nearly all odometry, across it
    # (where the match is surer than the odometry) the match.
    odometry_covariance = np.diag([0.03**2, 0.03**2, np.radians(2.0) ** 2])
    weighed = fuse_with_odometry(result.pose, result.covariance, odometry, odometry_covariance)
    assert weighed[0] == pytest.approx(0.31, abs=0.01)
    assert weighed[1] == pytest.approx(result.pose[1], abs=1e-9)
    assert weighed[2] == result.pose[2]


def test_a_wall_across_the_corridor_constrains_the_match_along_it():
    field, points = _corridor_field()
    end = np.column_stack([np.full(40, 4.0), np.linspace(-1, 1, 40)])
    walls = np.concatenate([field.points, end])
    closed = LikelihoodField(walls, 0.05, 0.05)
    cov = score_surface_covariance(closed, np.concatenate([points, end]), np.zeros(3))
    assert np.sqrt(cov[0, 0]) < 0.05


def test_collinear_far_points_are_joined_so_a_scan_does_not_stick_to_itself():
    # Beams grazing a wall 1 m to the side hit it metres apart far ahead.
    angles = np.radians(np.arange(5, 60, 1.0))
    wall = np.column_stack([1.0 / np.tan(angles), np.ones_like(angles)])
    plain = densify(wall, 0.025, 0.3)
    joined = densify(wall, 0.025, 0.3, bridge=3.0)
    assert len(joined) > 2 * len(plain)
    covered = np.sort(joined[(joined[:, 0] > 2.0) & (joined[:, 0] < 5.0), 0])
    assert np.diff(covered).max() < 0.05 < np.diff(np.sort(plain[:, 0])).max()
    assert np.abs(joined[:, 1] - 1.0).max() < 1e-9  # all on the wall
    # A corner (points turning away) is not bridged.
    corner = np.array([[0.0, 0.0], [0.1, 0.0], [0.2, 0.0], [2.0, 1.5], [2.0, 1.6], [2.0, 1.7]])
    assert len(densify(corner, 0.025, 0.3, bridge=3.0)) == len(densify(corner, 0.025, 0.3))


def test_without_match_covariance_run_slam_still_runs():
    log = corridor_log(1, step=1.0, length=20.0, depth=10.0, laps=1)
    result = run_slam(log.scans[:20], SlamConfig(match_covariance=False))
    assert np.all(np.isfinite(result.poses))
