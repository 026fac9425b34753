"""slam_gmapping with bad input: a laser frame tf does not know, NaN and inf readings, a beam
count that changes, GMapping parameters it ignores, a fast laser; and as a process, stopped
by SIGINT or SIGTERM."""

from __future__ import annotations

import signal
import time

import numpy as np
import pytest
from gmapping_feed import PARAMS, Feeder, start, wait_until
from process_helpers import Processes, private_core

from workbench.mapping.gmapping_node import SKIPPED_AT_START
from workbench.mapping.simulate import loop_trajectory


def _skip_start(feeder: Feeder, pose: np.ndarray) -> None:
    for _ in range(SKIPPED_AT_START):
        feeder.step(pose, pose)


def test_a_laser_frame_without_a_transform_warns_and_the_node_keeps_running(bus, capsys):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    feeder.mount("laser")
    mapper = start(bus, PARAMS)
    pose = loop_trajectory(0.1)[0]
    _skip_start(feeder, pose)
    text: list[str] = []

    def said(words: str, count: int) -> bool:
        text.append(capsys.readouterr().out)
        return "".join(text).count(words) >= count

    for n in range(1, 4):
        feeder.step(pose, pose, feeder.scan_msg(pose, 0.0, frame="nowhere"))
        assert wait_until(lambda n=n: said("Couldn't initialize mapper", n))
    assert mapper.slam is None and mapper._worker.is_alive()
    feeder.step(pose, pose)  # the laser's own frame: the mapper starts
    assert wait_until(lambda: mapper.processed == 1)
    assert wait_until(lambda: said("Initialization complete", 1))


def test_the_laser_pose_warning_is_gmappings(bus, capsys):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    mapper = start(bus, PARAMS)
    pose = loop_trajectory(0.1)[0]
    _skip_start(feeder, pose)
    feeder.step(pose, pose, feeder.scan_msg(pose, 0.0, frame="nowhere"))
    assert wait_until(lambda: mapper.received == SKIPPED_AT_START + 1)
    lines: list[str] = []

    def seen() -> bool:
        captured = capsys.readouterr()
        lines.extend((captured.out + captured.err).splitlines())
        return any("Returning" in line for line in lines)

    assert wait_until(seen)
    warnings = [line for line in lines if line.startswith("[WARN]")]
    assert len(warnings) == 1
    assert "Failed to compute laser pose, aborting initialization (" in warnings[0]
    assert "nowhere" in warnings[0]
    assert "Couldn't initialize mapper on the first scan. Returning" in lines


def test_nan_and_inf_readings_are_ignored(bus):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    feeder.mount()
    mapper = start(bus, PARAMS)
    truth = loop_trajectory(0.1)[:25]
    _skip_start(feeder, truth[0])
    rng = np.random.default_rng(3)
    for n, pose in enumerate(truth):
        msg = feeder.scan_msg(pose, 0.0)
        ranges = np.asarray(msg.ranges).copy()
        ranges[rng.choice(len(ranges), 60, replace=False)] = np.nan
        ranges[rng.choice(len(ranges), 20, replace=False)] = np.inf
        ranges[:5] = 0.01  # below range_min
        msg.ranges = ranges.astype(np.float32)
        feeder.step(pose, pose, msg)
        assert wait_until(lambda n=n: mapper.processed == n + 1)
    assert mapper.slam is not None
    assert np.all(np.isfinite(mapper.map_to_odom()))
    assert np.abs(mapper.map_to_odom()).max() < 0.05  # exact odometry: nothing to correct
    grid = mapper.slam.map()
    assert np.all(np.isfinite(grid.log_odds))


def test_a_changed_beam_count_is_refused_with_one_warning(bus, capsys):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    feeder.mount()
    mapper = start(bus, PARAMS)
    truth = loop_trajectory(0.1)[:12]
    _skip_start(feeder, truth[0])
    feeder.step(truth[0], truth[0])
    assert wait_until(lambda: mapper.processed == 1)
    short = Feeder.__new__(Feeder)
    short.__dict__.update(feeder.__dict__, beams=180)
    for pose in truth[1:6]:
        feeder.step(pose, pose, short.scan_msg(pose, 0.0))
        time.sleep(0.02)
    for n, pose in enumerate(truth[6:]):
        feeder.step(pose, pose)
        assert wait_until(lambda n=n: mapper.processed == 2 + n)
    assert mapper.dropped == 0
    captured = capsys.readouterr()
    refusals = [line for line in captured.err.splitlines() if "180 beams is refused" in line]
    assert len(refusals) == 1 and "360" in refusals[0]


def test_ignored_parameters_get_one_notice_each(bus, capsys):
    start(bus, {"particles": 80, "sigma": 0.05, "srr": 0.1, "lstep": 0.05})
    out = capsys.readouterr().out
    assert out.count("~particles (80) is ignored") == 1
    notice = [line for line in out.splitlines() if "ignored GMapping parameters" in line]
    assert len(notice) == 1 and notice[0].endswith("sigma, lstep, srr")


def test_a_fast_laser_is_kept_up_with_by_dropping_scans(bus):
    # A 40 Hz, 720-beam laser for 3 simulated seconds, published in real time.
    feeder = Feeder(bus, beams=720, dt=0.025)
    feeder.tick(feeder.t)
    feeder.mount()
    mapper = start(bus, {**PARAMS, "linearUpdate": 0.0, "angularUpdate": 0.0})
    truth = loop_trajectory(0.01)[:140]
    scans = [feeder.scan_msg(pose, 0.0) for pose in truth]
    _skip_start(feeder, truth[0])
    begin = time.monotonic()
    queued = []
    for k, pose in enumerate(truth[:120]):
        feeder.step(pose, pose, scans[k])
        queued.append(mapper.waiting)
        time.sleep(max(0.0, begin + 0.025 * (k + 1) - time.monotonic()))
    assert wait_until(lambda: mapper.processed + mapper.dropped == 120, 5.0)
    assert mapper.processed > 10
    # While it was busy the newest scan waited in the slot; now none does.
    assert any(queued) and not mapper.waiting
    # It finished the scans in hand within a scan period or two of the last one.
    assert time.monotonic() - begin < 3.0 + 1.0


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_the_process_stops_cleanly_on_a_signal(tmp_path, sig, status):
    with private_core(tmp_path) as uri:
        procs = Processes(uri, tmp_path)
        try:
            node = procs.start(
                "-m", "workbench", "run", "gmapping", "slam_gmapping", "scan:=/scan",
                "_particles:=30", name="gmapping",
            )  # fmt: skip
            procs.wait_output(node, "~particles (30) is ignored")
            time.sleep(0.5)
            node.send_signal(sig)
            assert node.wait(15) == status
            assert "Traceback" not in procs.output(node)
        finally:
            procs.stop_all()


def test_the_published_map_covers_gmappings_initial_bounds_and_grows_past_them():
    from workbench.mapping.grid import OccupancyGrid
    from workbench.mapping.live_map import gmapping_cells

    grid = OccupancyGrid(40, 20, 0.05, (98.0, -0.5, 0.0))
    grid.integrate_scan(np.array([99.0, 0.0, 0.0]), np.array([0.52]), np.array([0.0]))
    cells, origin = gmapping_cells(grid, (-100.0, -100.0, 100.0, 100.0))
    assert origin == pytest.approx((-100.0, -100.0))
    assert cells.shape == (4000, 4000)  # GMapping's default -100..100 m at 5 cm
    row = round((0.0 + 100.0) / 0.05)
    assert cells[row, round((99.51 + 100.0) / 0.05)] == 100  # the hit
    assert cells[row, round((99.25 + 100.0) / 0.05)] == 0  # the beam
    assert cells[0, 0] == -1 and (cells >= 0).sum() == 11
    grid.grow_to(np.array([[102.0, 0.0]]), margin=0.0)
    cells, origin = gmapping_cells(grid, (-100.0, -100.0, 100.0, 100.0))
    assert cells.shape[1] > 4000 and set(np.unique(cells).tolist()) <= {-1, 0, 100}


def test_the_shipped_rviz_config_shows_robot_scan_and_map_in_the_map_frame():
    from process_helpers import REPO

    from workbench.rviz.config import load_config

    config = load_config(REPO / "examples/packages/turtlebot3_slam/rviz/turtlebot3_gmapping.rviz")
    assert config.fixed_frame == "map" and config.unknown == []
    shown = {d.class_name: d for d in config.displays if d.enabled}
    assert {"RobotModel", "LaserScan", "Map"} <= set(shown)
    assert (
        shown["LaserScan"].options.get("topic", shown["LaserScan"].options.get("Topic")) == "/scan"
    )
    assert shown["Map"].options.get("topic", shown["Map"].options.get("Topic")) == "/map"
