"""AMCL's pieces against amcl's sources (ros-planning/navigation, noetic-devel): the odometry
models' noise (amcl_odom.cpp), the likelihood field (amcl_laser.cpp, map_cspace.cpp), KLD
sample counts and clusters (pf.c, pf_kdtree.c) and the resampler."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.navigation.amcl_filter import ParticleFilter
from workbench.navigation.amcl_kld import (
    cluster_labels,
    cluster_stats,
    kld_count,
    resample_limits,
)
from workbench.navigation.amcl_laser import (
    LaserScanData,
    LikelihoodFieldModel,
    beam_indices,
    prepare_ranges,
)
from workbench.navigation.amcl_map import FREE, OCCUPIED, UNKNOWN, AmclMap
from workbench.navigation.amcl_motion import OdomModel, angle_diff

N = 40000


def moved(model: OdomModel, delta, start=(0.0, 0.0, 0.0), seed: int = 0) -> np.ndarray:
    poses = np.tile(np.asarray(start, float), (N, 1))
    odom_pose = np.asarray(delta, float)  # from an odometry pose at the origin
    model.sample(poses, odom_pose, np.asarray(delta, float), np.random.default_rng(seed))
    return poses


# ---------------------------------------------------------------- motion models
def test_angle_diff_is_amcls():
    assert angle_diff(0.1, -0.1) == pytest.approx(0.2)
    assert angle_diff(3.1, -3.1) == pytest.approx(-(2 * math.pi - 6.2))
    assert angle_diff(-3.1, 3.1) == pytest.approx(2 * math.pi - 6.2)
    assert angle_diff(np.pi, 0.0) == pytest.approx(-np.pi)  # a tie goes to the negative side


def test_without_noise_every_particle_moves_as_the_odometry():
    model = OdomModel("diff", 0.0, 0.0, 0.0, 0.0)
    poses = np.array([[1.0, 2.0, 0.0], [0.0, 0.0, np.pi / 2]])
    model.sample(
        poses, np.array([0.3, 0.4, 0.2]), np.array([0.3, 0.4, 0.2]), np.random.default_rng(0)
    )
    rot1 = math.atan2(0.4, 0.3)
    assert poses[0] == pytest.approx([1.0 + 0.5 * math.cos(rot1), 2.0 + 0.5 * math.sin(rot1), 0.2])
    # the same motion in the particle's own frame
    assert poses[1] == pytest.approx(
        [0.5 * math.cos(np.pi / 2 + rot1), 0.5 * math.sin(np.pi / 2 + rot1), np.pi / 2 + 0.2]
    )


def test_diff_uses_the_variance_expressions_as_standard_deviations():
    """amcl's "diff": sd(trans) = a3 t² + a4 (r1² + r2²), sd(rot1) = a1 r1² + a2 t²."""
    a1, a2, a3, a4 = 0.4, 0.3, 0.1, 0.2
    t, r1, r2 = 1.0, 0.0, 0.5  # straight ahead 1 m, then a 0.5 rad turn
    poses = moved(OdomModel("diff", a1, a2, a3, a4), (t, 0.0, r2))
    trans = np.hypot(poses[:, 0], poses[:, 1])
    assert trans.mean() == pytest.approx(t, abs=0.01)
    assert trans.std() == pytest.approx(a3 * t**2 + a4 * r2**2, rel=0.05)
    heading = np.arctan2(poses[:, 1], poses[:, 0])  # rot1_hat
    assert heading.std() == pytest.approx(a1 * r1**2 + a2 * t**2, rel=0.05)
    total = poses[:, 2]
    sd_rot2 = a1 * r2**2 + a2 * t**2
    assert total.std() == pytest.approx(math.hypot(a2 * t**2, sd_rot2), rel=0.05)


def test_diff_corrected_takes_square_roots():
    a1, a2, a3, a4 = 0.04, 0.03, 0.05, 0.02
    poses = moved(OdomModel("diff-corrected", a1, a2, a3, a4), (0.5, 0.0, 0.0))
    assert poses[:, 0].std() == pytest.approx(math.sqrt(a3 * 0.25), rel=0.05)
    heading = np.arctan2(poses[:, 1], poses[:, 0])
    assert heading.std() == pytest.approx(math.sqrt(a2 * 0.25), rel=0.05)


def test_backward_motion_gets_the_same_noise_as_forward():
    model = OdomModel("diff-corrected", 0.1, 0.1, 0.1, 0.1)
    forward = moved(model, (0.5, 0.0, 0.0))
    backward = moved(model, (-0.5, 0.0, 0.0))
    assert backward[:, 0].mean() == pytest.approx(-0.5, abs=0.01)
    assert backward[:, 0].std() == pytest.approx(forward[:, 0].std(), rel=0.05)
    assert backward[:, 2].std() == pytest.approx(forward[:, 2].std(), rel=0.05)


def test_a_turn_in_place_has_no_bearing():
    poses = moved(OdomModel("diff", 0.2, 0.2, 0.2, 0.2), (0.005, 0.0, 1.0))
    # trans < 0.01: rot1 = 0, so the noise comes from the turn alone (a4 r2² = 0.2)
    assert poses[:, 2].mean() == pytest.approx(1.0, abs=0.01)
    assert poses[:, 2].std() == pytest.approx(0.2 * 1.0 + 0.2 * 0.005**2, rel=0.05)


def test_omni_strafes_with_alpha5():
    a5 = 0.3
    poses = moved(OdomModel("omni", 0.0, 0.0, 0.0, 0.0, a5), (1.0, 0.0, 0.0))
    assert poses[:, 0].std() == pytest.approx(0.0, abs=1e-9)
    assert poses[:, 1].std() == pytest.approx(a5 * 1.0, rel=0.05)
    corrected = moved(OdomModel("omni-corrected", 0.0, 0.0, 0.0, 0.0, a5), (1.0, 0.0, 0.0))
    assert corrected[:, 1].std() == pytest.approx(math.sqrt(a5), rel=0.05)


def test_the_same_seed_gives_the_same_particles():
    model = OdomModel("diff")
    assert np.array_equal(
        moved(model, (0.3, 0.1, 0.2), seed=4), moved(model, (0.3, 0.1, 0.2), seed=4)
    )
    assert not np.array_equal(
        moved(model, (0.3, 0.1, 0.2), seed=4), moved(model, (0.3, 0.1, 0.2), seed=5)
    )


# ----------------------------------------------------------- likelihood field
def wall_map() -> AmclMap:
    """A 4 m x 2 m map at 0.1 m: one occupied column at x = 2.0..2.1, unknown at the top row."""
    cells = np.zeros((20, 40), dtype=np.int16)
    cells[:, 20] = 100
    cells[19, :] = -1
    return AmclMap.from_cells(cells, 0.1, (0.0, 0.0))


def test_occupancy_states_are_amcls():
    m = wall_map()
    assert m.states[0, 0] == FREE and m.states[0, 20] == OCCUPIED and m.states[19, 3] == UNKNOWN


def test_the_distance_field_is_capped_as_map_update_cspace():
    m = wall_map()
    m.update_cspace(0.35)
    assert m.occ_dist[5, 20] == 0.0
    assert m.occ_dist[5, 21] == pytest.approx(0.1)
    assert m.occ_dist[5, 23] == pytest.approx(0.3)
    assert m.occ_dist[5, 24] == pytest.approx(0.35)  # 4 cells > floor(0.35 / 0.1): the cap
    assert m.occ_dist[5, 0] == pytest.approx(0.35)


def test_a_beam_scores_z_hit_gauss_plus_z_rand_over_range_max():
    m = wall_map()
    model = LikelihoodFieldModel(
        m, z_hit=0.8, z_rand=0.2, sigma_hit=0.2, max_occ_dist=2.0, max_beams=2
    )
    data = LaserScanData(np.array([1.0, 1.23]), np.array([0.0, 0.0]), 4.0)
    poses = np.array([[1.0, 0.55, 0.0]])
    pz = model.beam_likelihoods(poses, data)
    # beam 0 ends at x = 2.0 (in the wall cell): z = 0; beam 1 at 2.23: cell 22, z = 0.2
    assert pz[0, 0] == pytest.approx(0.8 + 0.2 / 4.0)
    assert pz[0, 1] == pytest.approx(0.8 * math.exp(-0.04 / 0.08) + 0.2 / 4.0)
    expected = 1.0 + pz[0, 0] ** 3 + pz[0, 1] ** 3
    assert model.likelihoods(poses, data)[0] == pytest.approx(expected)


def test_endpoints_off_the_map_read_the_maximum_distance():
    m = wall_map()
    model = LikelihoodFieldModel(
        m, z_hit=0.9, z_rand=0.1, sigma_hit=0.5, max_occ_dist=1.5, max_beams=2
    )
    data = LaserScanData(np.array([3.0, 3.0]), np.array([np.pi, np.pi]), 5.0)
    pz = model.beam_likelihoods(np.array([[1.0, 1.0, 0.0]]), data)
    assert pz[0, 0] == pytest.approx(0.9 * math.exp(-(1.5**2) / 0.5) + 0.1 / 5.0)


def test_max_range_nan_and_inf_readings_are_skipped():
    m = wall_map()
    model = LikelihoodFieldModel(m, max_beams=30)
    ranges = prepare_ranges(np.array([1.0, np.nan, np.inf, 3.5, 0.05, 9.0]), 0.1, 3.5)
    assert ranges[3] == 3.5 and ranges[4] == 3.5 and np.isinf(ranges[5]) and np.isnan(ranges[1])
    data = LaserScanData(ranges, np.zeros(6), 3.5)
    pz = model.beam_likelihoods(np.array([[1.0, 0.5, 0.0]]), data)
    assert pz.shape == (1, 1)  # only the 1.0 m reading counts


def test_the_laser_pose_on_the_robot_shifts_the_endpoints():
    m = wall_map()
    model = LikelihoodFieldModel(m, max_beams=2, laser_pose=(0.5, 0.0, 0.0))
    data = LaserScanData(np.array([0.5, 0.5]), np.array([0.0, 0.0]), 4.0)
    on_wall = model.beam_likelihoods(np.array([[1.0, 0.5, 0.0]]), data)
    model.laser_pose = np.zeros(3)
    off_wall = model.beam_likelihoods(np.array([[1.0, 0.5, 0.0]]), data)
    assert on_wall[0, 0] > off_wall[0, 0]


@pytest.mark.parametrize(
    ("count", "beams", "first"),
    [(360, 30, [0, 12, 24]), (30, 30, [0, 1, 2]), (10, 30, [0, 1, 2]), (181, 2, [0, 180])],
)
def test_beams_are_evenly_subsampled_as_amcl(count, beams, first):
    index = beam_indices(count, beams)
    step = max((count - 1) // (beams - 1), 1)
    assert index.tolist()[: len(first)] == first
    assert index.tolist() == list(range(0, count, step))
    assert beam_indices(100, 1).size == 0  # max_beams < 2: amcl skips the sensor update


def test_ray_casting_stops_at_the_first_non_free_cell():
    m = wall_map()
    ranges = m.calc_ranges(np.array([1.05, 0.55, 0.0]), np.array([0.0, np.pi / 2, np.pi]), 3.0)
    assert ranges[0] == pytest.approx(0.95, abs=0.05)  # the wall at x = 2.0
    assert ranges[1] == pytest.approx(1.35, abs=0.05)  # the unknown top row at y = 1.9
    assert ranges[2] == pytest.approx(1.05, abs=0.06)  # the map's edge at x = 0


# ----------------------------------------------------------------- KLD sampling
def amcl_limit(k: int, err: float = 0.01, z: float = 0.99, lo: int = 100, hi: int = 5000) -> int:
    """pf_resample_limit, written out from pf.c."""
    if k <= 1:
        return hi
    b = 2 / (9 * (k - 1))
    x = 1 - b + math.sqrt(b) * z
    n = math.ceil((k - 1) / (2 * err) * x**3)
    return min(max(n, lo), hi)


def test_resample_limits_follow_fox():
    limits = resample_limits(100, 5000, 0.01, 0.99)
    for k in (1, 2, 3, 5, 10, 20, 50, 100, 5000):
        assert limits[k] == amcl_limit(k), k
    assert limits[2] == 100 and limits[5] == amcl_limit(5) > 300


def test_the_kld_count_stops_once_the_samples_exceed_the_limit_of_their_bins():
    limits = resample_limits(10, 1000, 0.01, 0.99)
    rng = np.random.default_rng(0)
    # five bins (0.5 m apart), visited in random order
    poses = np.column_stack(
        [rng.integers(0, 5, 1000) * 0.5 + 0.25, np.full(1000, 0.25), np.zeros(1000)]
    )
    count = kld_count(poses, limits)
    assert count == limits[5] + 1
    one_bin = np.zeros((1000, 3)) + 0.1
    assert kld_count(one_bin, limits) == 1000  # k = 1: amcl keeps max_samples


def test_clusters_are_connected_bins_and_headings_wrap():
    rng = np.random.default_rng(1)
    a = rng.normal([1.0, 1.0, 0.0], [0.1, 0.1, 0.05], (300, 3))
    b = rng.normal([4.0, 1.0, 0.0], [0.1, 0.1, 0.05], (100, 3))
    labels = cluster_labels(np.vstack([a, b]))
    assert len(set(labels[:300])) == 1 and len(set(labels[300:])) == 1
    assert labels[0] != labels[300]
    near_pi = np.column_stack([np.full(50, 1.0), np.full(50, 1.0), np.linspace(3.0, 3.3, 50)])
    near_pi[:, 2] = np.angle(np.exp(1j * near_pi[:, 2]))  # both sides of +-pi
    assert len(set(cluster_labels(near_pi))) == 1


def test_cluster_statistics_are_amcls():
    poses = np.array([[1.0, 2.0, 0.1], [1.2, 2.2, -0.1], [5.0, 5.0, 3.0]])
    weights = np.array([0.25, 0.25, 0.5])
    clusters = cluster_stats(poses, weights, cluster_labels(poses))
    first = clusters[0]
    assert first.count == 2 and first.weight == pytest.approx(0.5)
    assert first.mean == pytest.approx([1.1, 2.1, 0.0])
    assert first.cov[0, 0] == pytest.approx(0.01) and first.cov[0, 1] == pytest.approx(0.01)
    assert first.cov[2, 2] == pytest.approx(-2 * math.log(math.cos(0.1)))


# ------------------------------------------------------------------ resampling
def uniform_square(count: int, rng: np.random.Generator) -> np.ndarray:
    return np.column_stack(
        [rng.uniform(10, 20, count), rng.uniform(10, 20, count), rng.uniform(-np.pi, np.pi, count)]
    )


def test_resampling_copies_particles_in_proportion_to_their_weight():
    # min_particles = max_particles: the whole low-variance comb is kept
    pf = ParticleFilter(2000, 2000, 0.0, 0.0, uniform_square, rng=np.random.default_rng(2))
    pf.poses = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [6.0, 0.0, 0.0], [9.0, 0.0, 0.0]])
    pf.weights = np.array([0.5, 0.25, 0.25, 0.0])
    pf.resample()
    share = np.array([(pf.poses[:, 0] == x).mean() for x in (0.0, 3.0, 6.0, 9.0)])
    assert share == pytest.approx([0.5, 0.25, 0.25, 0.0], abs=0.001)
    assert pf.weights == pytest.approx(np.full(pf.count, 1.0 / pf.count))


def test_random_particles_are_injected_when_the_fast_average_drops():
    pf = ParticleFilter(100, 2000, 0.001, 0.1, uniform_square, rng=np.random.default_rng(3))
    pf.init_gaussian(np.zeros(3), np.diag([0.01, 0.01, 0.01]))
    pf.w_slow, pf.w_fast = 1.0, 0.7  # the scans fit far worse than they used to
    pf.resample()
    random_share = (pf.poses[:, 0] > 5.0).mean()
    assert random_share == pytest.approx(0.3, abs=0.05)
    assert pf.w_slow == pf.w_fast == 0.0  # reset after injecting
    pf2 = ParticleFilter(100, 2000, 0.001, 0.1, uniform_square, rng=np.random.default_rng(3))
    pf2.init_gaussian(np.zeros(3), np.diag([0.01, 0.01, 0.01]))
    pf2.w_slow, pf2.w_fast = 0.7, 1.0
    pf2.resample()
    assert (pf2.poses[:, 0] > 5.0).sum() == 0


def test_the_sensor_update_keeps_the_running_averages():
    pf = ParticleFilter(10, 100, 0.5, 0.9, uniform_square, rng=np.random.default_rng(4))
    pf.init_gaussian(np.zeros(3), np.eye(3))
    pf.update_sensor(np.full(100, 2.0))
    assert pf.w_slow == pytest.approx(0.02) and pf.w_fast == pytest.approx(0.02)
    pf.update_sensor(np.full(100, 4.0))
    assert pf.w_slow == pytest.approx(0.02 + 0.5 * (0.04 - 0.02))
    assert pf.w_fast == pytest.approx(0.02 + 0.9 * (0.04 - 0.02))
    pf.update_sensor(np.zeros(100))  # nothing fits: uniform weights
    assert pf.weights == pytest.approx(np.full(100, 0.01))


def test_the_gaussian_initialisation_has_the_requested_covariance():
    pf = ParticleFilter(100, 5000, 0.0, 0.0, uniform_square, rng=np.random.default_rng(5))
    cov = np.array([[0.25, 0.1, 0.0], [0.1, 0.16, 0.0], [0.0, 0.0, 0.04]])
    pf.init_gaussian(np.array([1.0, -2.0, 0.5]), cov)
    assert pf.count == 5000
    assert np.cov(pf.poses.T) == pytest.approx(cov, abs=0.015)
    assert pf.mean == pytest.approx([1.0, -2.0, 0.5], abs=0.02)
    assert len(pf.clusters) == 1
