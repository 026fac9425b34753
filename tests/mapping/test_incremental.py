"""The incremental SLAM API a live node uses: one scan at a time, a growing map."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import Slam, SlamConfig, run_slam
from workbench.mapping.corridors import corridor_log
from workbench.mapping.geometry import compose
from workbench.mapping.incremental import front_window


def test_add_scan_gives_the_same_poses_as_run_slam():
    scans = corridor_log(2, step=0.5, length=20.0, depth=10.0, laps=1).scans[:40]
    batch = run_slam(scans)
    slam = Slam()
    live = np.array([slam.add_scan(scan) for scan in scans])
    slam.optimize(iterations=20)
    np.testing.assert_allclose(slam.poses(), batch.poses, atol=1e-9)
    # Before the final optimisation each returned pose was the estimate at that time.
    assert np.hypot(*(live[:, :2] - batch.poses[:, :2]).T).max() < 0.05
    assert slam.keyframes == batch.keyframes


def test_only_scans_past_the_update_thresholds_are_matched():
    scans = corridor_log(2, step=0.1, length=20.0, depth=10.0, laps=1).scans[:60]
    slam = Slam(SlamConfig(linear_update=0.5, angular_update=0.5))
    poses = np.array([slam.add_scan(scan) for scan in scans])
    matched = np.isfinite(slam.scores)
    assert 8 <= matched.sum() <= 14  # every fifth scan (0.5 m at 0.1 m a scan)
    truth = np.array([s.reference for s in scans])
    assert np.hypot(*(poses[:, :2] - truth[:, :2]).T).max() < 0.1
    # map -> odom puts the latest odometry at the latest pose.
    np.testing.assert_allclose(compose(slam.map_to_odom(), scans[-1].odom), slam.pose(), atol=1e-9)


def test_the_map_grows_beyond_its_first_bounds():
    log = corridor_log(2, step=0.5, length=30.0, depth=10.0, laps=1)
    slam = Slam(SlamConfig(map_size=4.0, max_urange=10.0))
    slam.add_scan(log.scans[0])
    first = slam.map()
    width, height = first.width, first.height
    assert width * 0.05 >= 4.0
    for scan in log.scans[1:50]:
        slam.add_scan(scan)
    grid = slam.map()
    assert grid.width > width and grid.height > height
    # Walls seen along the way are in it, where the poses put them.
    msg = grid.to_map()
    assert (msg.data >= 65).sum() > 200
    far = np.array([s.reference[:2] for s in log.scans[40:50]])
    cells = msg.world_to_cell(far)
    assert np.all((cells >= 0) & (cells < [msg.width, msg.height]))
    assert np.all(msg.data[cells[:, 1], cells[:, 0]].astype(int) >= 0)  # observed


def test_a_live_front_end_searches_as_far_as_the_odometry_can_be_off():
    live = SlamConfig(odometry_window=True)
    # Standing still: the smallest window, its prior a third of it.
    linear, angular, prior = front_window(live, np.zeros(3))
    assert (linear, angular) == pytest.approx(live.min_window)
    assert prior == pytest.approx((linear / 3, angular / 3))
    # Driving 0.5 m: three std devs of the odometry model (10 % of the distance).
    srr, _, str_, _ = live.odometry_noise
    linear, angular, _ = front_window(live, np.array([0.5, 0.0, 0.0]))
    assert linear == pytest.approx(3 * np.sqrt(2) * (srr * 0.5 + 0.002))
    assert angular == pytest.approx(live.min_window[1])  # 3 x 0.6° is below the floor
    # A half turn: capped at the configured window.
    linear, angular, _ = front_window(live, np.array([0.0, 0.0, np.pi]))
    assert angular == pytest.approx(live.angular_window)
    # Logs search the configured window with the configured prior whatever the motion.
    log = SlamConfig()
    assert front_window(log, np.array([0.01, 0.0, 0.0])) == (
        log.linear_window,
        log.angular_window,
        log.prior_sigma,
    )


def test_deferred_loop_closures_are_optimised_once_they_add_up():
    scans = corridor_log(2, step=0.25, length=8.0, depth=6.0, laps=2).scans
    eager = Slam(SlamConfig())
    lazy = Slam(SlamConfig(loop_defer_chi2=1.0))
    for scan in scans:
        eager.add_scan(scan)
        lazy.add_scan(scan)
    accepted = [o for o in lazy.loop_attempts if o.accepted]
    assert accepted, "the second lap closes loops"
    assert any(not o.optimized for o in accepted)
    optimised = [o for o in lazy.loop_attempts if o.optimized]
    assert len(optimised) < len([o for o in eager.loop_attempts if o.optimized])
    truth = np.array([s.reference for s in scans])
    for slam in (eager, lazy):
        assert np.hypot(*(slam.poses()[:, :2] - truth[:, :2]).T).max() < 0.15
