"""The incremental SLAM API a live node uses: one scan at a time, a growing map."""

from __future__ import annotations

import numpy as np

from workbench.mapping import Slam, SlamConfig, run_slam
from workbench.mapping.corridors import corridor_log
from workbench.mapping.geometry import compose


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
