"""Graph SLAM on simulated and real (Intel Research Lab) laser data."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import SlamConfig, build_map, read_log, run_slam
from workbench.mapping.geometry import between, compose
from workbench.mapping.simulate import demo_world, loop_trajectory, simulate_scans


def _position_error(poses, scans):
    truth = np.array([s.reference for s in scans])
    return np.hypot(*(poses[:, :2] - truth[:, :2]).T)


@pytest.fixture(scope="module")
def simulated():
    return simulate_scans(
        demo_world(), loop_trajectory(), odometry_noise=(0.03, 0.015), range_noise=0.01, seed=7
    )


def test_slam_beats_dead_reckoning_and_closes_the_loop(simulated):
    result = run_slam(simulated)
    odom_error = _position_error(np.array([s.odom for s in simulated]), simulated)
    slam_error = _position_error(result.poses, simulated)
    assert len(result.loop_closures) > 0
    assert slam_error.max() < 0.05
    assert slam_error.max() < 0.2 * odom_error.max()
    # The map shows the dividing wall at x = 4 m as occupied and the rooms as free.
    grid = build_map(simulated, result.poses, resolution=0.05).to_map()
    (wx, wy), (fx, fy) = grid.world_to_cell(np.array([[4.0, 1.0], [2.5, 2.0]]))
    assert grid.data[wy, wx - 1 : wx + 1].max() >= 65
    assert 0 <= grid.data[fy, fx] <= 25


def test_slam_is_deterministic(simulated):
    a = run_slam(simulated[:30])
    b = run_slam(simulated[:30])
    np.testing.assert_array_equal(a.poses, b.poses)


def test_bad_readings_and_people_walking_through_do_not_break_matching(simulated):
    rng = np.random.default_rng(3)
    scans = []
    for scan in simulated:
        ranges = scan.ranges.copy()
        bad = rng.choice(len(ranges), 30, replace=False)
        ranges[bad[:10]] = np.nan
        ranges[bad[10:20]] = np.inf
        ranges[bad[20:]] = 0.0
        # A person: a 0.4 m blob one metre ahead in a third of the scans.
        if rng.random() < 0.33:
            ahead = np.abs(scan.angles) < 0.2
            ranges[ahead] = 1.0
        scans.append(type(scan)(**{**scan.__dict__, "ranges": ranges}))
    # A short scan (3 readings) in the middle is carried by odometry.
    short = scans[40]
    scans[40] = type(short)(
        **{**short.__dict__, "ranges": short.ranges[:3], "angles": short.angles[:3]}
    )
    result = run_slam(scans)
    assert np.all(np.isfinite(result.poses))
    assert _position_error(result.poses, scans).max() < 0.1


def test_keyframes_are_made_after_enough_motion(simulated):
    # The same pose repeated: only the first scan becomes a keyframe.
    still = [type(simulated[0])(**{**simulated[0].__dict__, "stamp": float(k)}) for k in range(5)]
    result = run_slam(still, SlamConfig(keyframe_distance=0.2))
    assert result.keyframes == [0]
    np.testing.assert_allclose(result.poses, np.repeat(simulated[0].odom[None], 5, 0), atol=0.02)


def _noisy_odometry(reference, alphas, seed):
    rng = np.random.default_rng(seed)
    out = [reference[0]]
    for k in range(1, len(reference)):
        d = between(reference[k - 1], reference[k])
        step = d + rng.normal(0, 1, 3) * np.array([alphas[0], alphas[0], alphas[1]])
        out.append(compose(out[-1], step))
    return np.array(out)


@pytest.mark.slow
def test_loop_closure_reduces_error_on_the_intel_log(intel_log):
    log = read_log(intel_log)
    scans = log.scans[:330]
    reference = np.array([s.reference for s in scans])
    odom = _noisy_odometry(reference, (0.02, 0.01), seed=0)
    for scan, o in zip(scans, odom, strict=True):
        scan.odom = o
    with_loops = run_slam(scans)
    without = run_slam(scans, SlamConfig(loop_search_radius=0.0))
    assert len(with_loops.loop_closures) > 0 and len(without.loop_closures) == 0

    def rms(poses):
        # Position error after aligning the first pose (a rigid offset is not an error).
        aligned = compose(reference[0][None], between(poses[0][None], poses))
        return float(np.sqrt(np.mean(np.sum((aligned[:, :2] - reference[:, :2]) ** 2, axis=1))))

    assert rms(with_loops.poses) < rms(without.poses)
    assert rms(with_loops.poses) < rms(odom)
