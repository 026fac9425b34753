"""Experiment 10 as processes: the TurtleBot3 in the house (``turtlebot3_house.launch``),
``turtlebot3_slam.launch`` (robot_state_publisher and slam_gmapping), a drive on ``/cmd_vel``,
then ``map_saver -f mymap``: the saved map's walls are the house's walls and the map pose
of the robot follows the simulator's ground truth."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
from process_helpers import REPO, Processes, private_core

from workbench.bus import Bus, Node
from workbench.mapping import load_map
from workbench.msgs.gazebo_msgs import GetModelState
from workbench.msgs.geometry_msgs import Twist
from workbench.sim.building import blocked_cells, load_plan
from workbench.tf import Buffer, TransformException, TransformListener

pytestmark = [pytest.mark.slow, pytest.mark.multiprocess]

#: Height of the burger's scan plane above the floor (base_scan), m.
SCAN_HEIGHT = 0.182
#: (linear m/s, angular rad/s, simulated seconds): turn round, cross the living room, look.
DRIVE = [(0.0, 0.8, 8.0), (0.2, 0.0, 7.0), (0.0, 0.8, 4.0), (0.2, 0.0, 5.0), (0.0, -0.8, 4.0)]


def true_obstacles(xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Cells (rows along y) where the house has something at the scan's height."""
    pieces = load_plan(REPO / "mapping" / "plans" / "house.yaml").pieces()
    return blocked_cells(pieces, xs, ys, (SCAN_HEIGHT, SCAN_HEIGHT))


def dilate(mask: np.ndarray, cells: int) -> np.ndarray:
    out = mask.copy()
    for dy in range(-cells, cells + 1):
        for dx in range(-cells, cells + 1):
            out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return out


def map_quality(path) -> tuple[float, float]:
    """Precision and recall of the saved map's occupied cells against the house, within one
    cell; recall counts the walls next to space the map saw free."""
    grid = load_map(path)
    res = grid.resolution
    height, width = grid.data.shape
    xs = grid.origin[0] + (np.arange(width) + 0.5) * res
    ys = grid.origin[1] + (np.arange(height) + 0.5) * res
    truth = true_obstacles(xs, ys)
    surface = truth & dilate(~truth, 1)  # the faces a laser can see
    occupied = grid.data >= 65
    free = (grid.data >= 0) & (grid.data <= 25)
    precision = float((occupied & dilate(truth, 1)).sum() / max(occupied.sum(), 1))
    seen = surface & dilate(free, 1)
    recall = float((seen & dilate(occupied, 1)).sum() / max(seen.sum(), 1))
    return precision, recall


def _yaw(q) -> float:
    return 2 * math.atan2(q.z, q.w)


def test_the_turtlebot3_maps_the_house(tmp_path):
    begin = time.monotonic()
    with private_core(tmp_path) as uri:
        procs = Processes(uri, tmp_path)
        try:
            sim = procs.start(
                "-m", "workbench", "launch", "turtlebot3_gazebo", "turtlebot3_house.launch",
                "gui:=false", name="sim",
            )  # fmt: skip
            slam = procs.start(
                "-m", "workbench", "launch", "turtlebot3_slam", "turtlebot3_slam.launch",
                "open_rviz:=false", name="slam",
            )  # fmt: skip
            procs.wait_output(slam, "Initialization complete", timeout=60)
            assert "Laser is mounted upwards." in procs.output(slam)
            errors = _drive(uri)
            saver = procs.start(
                "-m", "workbench", "run", "map_server", "map_saver", "-f", "mymap", name="saver"
            )
            assert saver.wait(30) == 0, procs.output(saver)
            assert sim.poll() is None and slam.poll() is None
            out = procs.output(slam)
        finally:
            procs.stop_all()
    assert (load_map(tmp_path / "mymap.yaml").data >= 65).sum() > 200
    precision, recall = map_quality(tmp_path / "mymap.yaml")
    ate = float(np.sqrt(np.mean(np.square(errors))))
    print(
        f"map precision {precision:.3f} recall {recall:.3f}; ATE {ate:.3f} m "
        f"(max {max(errors):.3f} m, {len(errors)} samples); {time.monotonic() - begin:.0f} s wall"
    )
    assert "Traceback" not in out
    assert precision > 0.85 and recall > 0.6
    assert ate < 0.1


def _drive(uri: str) -> list[float]:
    """Drive the schedule; the distances between the simulator's pose of the robot and the
    map pose slam_gmapping's tf gives it, sampled every half simulated second."""
    errors: list[float] = []
    with Bus.connect(uri) as bus:
        node = Node("experiment_10", bus=bus)
        cmd = node.create_publisher("/cmd_vel", Twist, 1)
        buffer = Buffer()
        TransformListener(buffer, node)
        state = node.create_client("/gazebo/get_model_state", GetModelState)
        bus.wait_for_service("/gazebo/get_model_state", timeout=30)
        for linear, angular, seconds in [*DRIVE, (0.0, 0.0, 1.0)]:
            start = node.now().to_sec()
            next_sample = start
            while node.now().to_sec() - start < seconds:
                cmd.publish(Twist(linear={"x": linear}, angular={"z": angular}))
                if node.now().to_sec() >= next_sample:
                    next_sample += 0.5
                    errors.extend(_sample(buffer, state))
                time.sleep(0.05)
    return errors


def _sample(buffer: Buffer, state) -> list[float]:
    truth = state.call(GetModelState.Request(model_name="turtlebot3_burger"), timeout=10)
    try:
        est = buffer.lookup_transform("map", "base_footprint", 0)
    except TransformException:
        return []
    p = truth.pose.position
    t = est.transform.translation
    return [math.hypot(p.x - t.x, p.y - t.y)]
