"""A simulated robot for the amcl tests: a saved map (``mapping/demo_rooms.yaml``), a seeded
drive through its rooms with noisy odometry, and laser scans ray-cast in that map; on an
in-process bus it publishes ``/clock``, ``/tf`` (``odom -> base_link``), ``/tf_static``
(``base_link -> laser``) and ``/scan`` as a robot would."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from laser_robot import MOUNT, LaserRobot, sim_time_bus, wait_until

from workbench.bus import Bus, Node
from workbench.mapping.geometry import compose
from workbench.mapping.map_server_node import LoadedMap, MapServer, load_map_yaml
from workbench.msgs import Time
from workbench.msgs.sensor_msgs import LaserScan
from workbench.navigation.amcl_laser import LaserScanData, prepare_ranges
from workbench.navigation.amcl_map import AmclMap
from workbench.navigation.amcl_node import Amcl
from workbench.navigation.amcl_simulate import noisy_odometry, simulated_ranges

REPO = Path(__file__).resolve().parents[2]
DEMO_ROOMS = REPO / "mapping" / "demo_rooms.yaml"
BEAMS, RANGE_MIN, RANGE_MAX = 360, 0.12, 3.5
ANGLES = -math.pi + np.arange(BEAMS) * (2 * math.pi / BEAMS)
#: A tour of the demo rooms (x, y in m) through the doorway in the dividing wall.
WAYPOINTS = [(1.0, 1.0), (3.0, 1.2), (3.0, 3.1), (5.0, 3.1), (7.0, 3.0), (7.0, 5.0), (5.0, 5.2)]


def loaded_map(path: Path = DEMO_ROOMS) -> LoadedMap:
    return load_map_yaml(str(path))


def amcl_map(path: Path = DEMO_ROOMS) -> AmclMap:
    loaded = loaded_map(path)
    return AmclMap.from_cells(loaded.cells, loaded.meta.resolution, loaded.meta.origin[:2])


def tour(step: float = 0.05, waypoints=WAYPOINTS) -> np.ndarray:
    """Poses every ``step`` m along the waypoints, heading along the path; turns in place."""
    poses = []
    for a, b in zip(waypoints[:-1], waypoints[1:], strict=True):
        a, b = np.asarray(a, float), np.asarray(b, float)
        heading = math.atan2(b[1] - a[1], b[0] - a[0])
        if poses:  # turn on the spot towards the next leg, 0.1 rad per step
            last = poses[-1][2]
            turn = math.atan2(math.sin(heading - last), math.cos(heading - last))
            for f in np.arange(1, int(abs(turn) / 0.1) + 1) / (int(abs(turn) / 0.1) + 1):
                poses.append(np.array([a[0], a[1], last + f * turn]))
        n = max(int(np.ceil(np.hypot(*(b - a)) / step)), 1)
        for t in np.arange(0 if not poses else 1, n + 1) / n:
            p = a + t * (b - a)
            poses.append(np.array([p[0], p[1], heading]))
    return np.array(poses)


def scan_ranges(m: AmclMap, base_pose: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Readings of the laser at ``base_pose`` ray-cast in ``m`` (no return: inf)."""
    return simulated_ranges(m, compose(base_pose, MOUNT), ANGLES, RANGE_MAX, rng)


def scan_data(ranges: np.ndarray) -> LaserScanData:
    """The scan as amcl's localizer takes it: bearings in the base frame."""
    return LaserScanData(prepare_ranges(ranges, RANGE_MIN, RANGE_MAX), ANGLES.copy(), RANGE_MAX)


class Robot(LaserRobot):
    """Publishes what a robot driving through the map publishes, one step at a time; its
    scans are ray-cast in the map with seeded noise."""

    def __init__(self, bus: Bus, m: AmclMap, dt: float = 0.2, seed: int = 0) -> None:
        super().__init__(bus, dt)
        self.map = m
        self.rng = np.random.default_rng(seed)

    def scan_msg(self, truth: np.ndarray, stamp: float, frame: str = "laser") -> LaserScan:
        msg = LaserScan()
        msg.header.frame_id = frame
        msg.header.stamp = Time.from_sec(stamp)
        msg.angle_min, msg.angle_increment = -math.pi, 2 * math.pi / BEAMS
        msg.angle_max = msg.angle_min + (BEAMS - 1) * msg.angle_increment
        msg.range_min, msg.range_max = RANGE_MIN, RANGE_MAX
        msg.ranges = scan_ranges(self.map, truth, self.rng).astype(np.float32)
        return msg


def pose_of(t) -> np.ndarray:
    q = t.transform.rotation
    return np.array(
        [t.transform.translation.x, t.transform.translation.y, 2 * math.atan2(q.z, q.w)]
    )


STARTED: list[Amcl] = []


@pytest.fixture
def bus() -> Iterator[Bus]:
    """An in-process bus on simulated time; the amcl nodes started on it are closed after."""
    yield from sim_time_bus(STARTED)


def start(bus: Bus, params: dict | None = None) -> Amcl:
    node = Node("amcl", bus=bus)
    for key, value in (params or {}).items():
        node.set_param("~" + key, value)
    amcl = Amcl(node)
    STARTED.append(amcl)
    return amcl


def serve_map(bus: Bus) -> MapServer:
    return MapServer(Node("map_server", bus=bus, disable_rosout=True), loaded_map())


class Output:
    """Everything the nodes printed so far (stdout and stderr)."""

    def __init__(self, capsys) -> None:
        self.capsys, self.text = capsys, ""

    def has(self, words: str, timeout: float = 10.0) -> bool:
        def seen() -> bool:
            captured = self.capsys.readouterr()
            self.text += captured.out + captured.err
            return words in self.text

        return wait_until(seen, timeout)


def initial_guess(truth: np.ndarray, offset=(0.5, -0.4, 0.25)) -> dict:
    return {
        "initial_pose_x": float(truth[0] + offset[0]),
        "initial_pose_y": float(truth[1] + offset[1]),
        "initial_pose_a": float(truth[2] + offset[2]),
    }


__all__ = ["noisy_odometry", "wait_until"]  # re-exported for the tests
