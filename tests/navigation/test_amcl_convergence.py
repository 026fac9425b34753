"""AMCL localises on a real saved map (``mapping/demo_rooms.yaml``): from a wrong initial
guess, with scans ray-cast in that map along a seeded drive and noisy odometry, the pose
converges to within 0.1 m; the particle count shrinks as the filter converges (KLD)."""

from __future__ import annotations

import numpy as np
import pytest
from amcl_feed import MOUNT, amcl_map, noisy_odometry, scan_data, scan_ranges, tour

from workbench.navigation.amcl_localizer import Localizer
from workbench.navigation.amcl_params import AmclParams


def drive(params: AmclParams, seed: int = 0, guess=(0.5, -0.4, 0.25)):
    """Run the localizer along the tour; the published estimates with their truth."""
    m = amcl_map()
    truth = tour()
    odom = noisy_odometry(truth, seed=seed)
    params.initial_pose_x = truth[0, 0] + guess[0]
    params.initial_pose_y = truth[0, 1] + guess[1]
    params.initial_pose_a = truth[0, 2] + guess[2]
    localizer = Localizer(m, params, seed=seed)
    localizer.set_laser_pose(*MOUNT[:2])
    rng = np.random.default_rng(seed + 100)
    published, counts = [], []
    for k in range(len(truth)):
        estimate = localizer.process(odom[k], scan_data(scan_ranges(m, truth[k], rng)))
        if estimate.resampled:
            counts.append(localizer.pf.count)
        if estimate.publish:
            published.append((k, estimate.pose, truth[k]))
    return published, counts, localizer


def errors(published) -> np.ndarray:
    return np.array([np.hypot(*(pose[:2] - truth[:2])) for _, pose, truth in published])


@pytest.mark.parametrize("seed", range(4))
def test_the_pose_converges_from_a_wrong_guess_to_within_10_cm(seed):
    """amcl's defaults; the odometry overestimates every step by 3 % and is noisy."""
    published, _, localizer = drive(AmclParams(max_particles=2000), seed=seed)
    err = errors(published)
    assert err[0] > 0.5  # the first pose is the wrong guess
    converged = err[5:]  # after five resamples (about two metres)
    assert len(converged) > 25
    assert converged.max() <= 0.1, converged.max()
    heading = [abs(np.angle(np.exp(1j * (p[2] - t[2])))) for _, p, t in published[5:]]
    assert max(heading) < 0.1
    assert localizer.pf.converged  # every particle within 0.5 m of the mean


def test_the_particle_count_shrinks_as_the_filter_converges():
    published, counts, _ = drive(
        AmclParams(max_particles=5000, initial_cov_xx=1.0, initial_cov_yy=1.0)
    )
    assert counts[0] > 3000  # the spread guess needs many particles
    assert max(counts[-10:]) < 1000  # converged: a few hundred are enough
    assert min(counts) >= 100
    assert errors(published)[-10:].max() <= 0.1


def test_odometry_alone_drifts_beyond_what_amcl_keeps():
    truth = tour()
    odom = noisy_odometry(truth)
    drift = np.hypot(*(odom[:, :2] - truth[:, :2]).T)
    assert drift.max() > 0.2  # twice what amcl's estimates are off at most


def test_global_localization_finds_the_robot_in_the_rooms():
    m = amcl_map()
    truth = tour()
    odom = noisy_odometry(truth, seed=3)
    localizer = Localizer(m, AmclParams(max_particles=5000), seed=3)
    localizer.set_laser_pose(*MOUNT[:2])
    localizer.global_localization()
    assert localizer.pf.count == 5000
    spread = localizer.pf.poses[:, :2].std(axis=0)
    assert (spread > 1.5).all()  # over both rooms
    rng = np.random.default_rng(7)
    published = []
    for k in range(len(truth)):
        estimate = localizer.process(odom[k], scan_data(scan_ranges(m, truth[k], rng)))
        if estimate.publish:
            published.append((k, estimate.pose, truth[k]))
    assert errors(published)[0] > 1.0
    assert errors(published)[-5:].max() < 0.1
