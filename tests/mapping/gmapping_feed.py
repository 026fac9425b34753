"""A simulated robot on an in-process bus for slam_gmapping tests: ``/clock``, ``/tf``
(``odom -> base_link`` from drifting odometry, static ``base_link -> laser``) and ``/scan``
ray-cast in :func:`~workbench.mapping.simulate.demo_world` from known poses."""

from __future__ import annotations

import math

import numpy as np
from laser_robot import MOUNT, LaserRobot, wait_until

from workbench.bus import Bus, Node
from workbench.mapping.geometry import between, compose
from workbench.mapping.gmapping_node import SlamGMapping
from workbench.mapping.gmapping_params import read_params
from workbench.mapping.simulate import demo_world, raycast
from workbench.msgs import Time
from workbench.msgs.sensor_msgs import LaserScan

__all__ = ["wait_until"]  # re-exported for the tests


def drifting_odometry(truth: np.ndarray, scale: float = 1.04, turn: float = 0.006) -> np.ndarray:
    """Odometry of ``truth`` whose steps are ``scale`` too long and turn ``turn`` rad too far."""
    odom = [truth[0].copy()]
    for a, b in zip(truth[:-1], truth[1:], strict=True):
        step = between(a, b)
        step[:2] *= scale
        step[2] += turn if np.hypot(step[0], step[1]) > 1e-9 else 0.0
        odom.append(compose(odom[-1], step))
    return np.array(odom)


class Feeder(LaserRobot):
    """Publishes what a robot driving ``truth`` (base poses) would publish, one step at a time;
    its scans are ray-cast in the demo world."""

    def __init__(self, bus: Bus, beams: int = 360, max_range: float = 3.5, dt: float = 0.2) -> None:
        super().__init__(bus, dt)
        self.world = demo_world()
        self.beams, self.max_range = beams, max_range

    def scan_msg(self, truth: np.ndarray, stamp: float, frame: str = "laser") -> LaserScan:
        sensor = compose(truth, MOUNT)
        angles = -math.pi + np.arange(self.beams) * (2 * math.pi / self.beams)
        ranges = raycast(self.world, sensor, angles, self.max_range)
        ranges = np.where(ranges >= self.max_range, np.inf, ranges)
        msg = LaserScan()
        msg.header.frame_id = frame
        msg.header.stamp = Time.from_sec(stamp)
        msg.angle_min, msg.angle_increment = -math.pi, 2 * math.pi / self.beams
        msg.angle_max = msg.angle_min + (self.beams - 1) * msg.angle_increment
        msg.range_min, msg.range_max = 0.12, self.max_range
        msg.ranges = ranges.astype(np.float32)
        return msg


PARAMS = {
    "base_frame": "base_link",
    "linearUpdate": 0.2,
    "angularUpdate": 0.2,
    "map_update_interval": 1.0,
    "maxUrange": 3.0,
    "xmin": -2.0,
    "ymin": -2.0,
    "xmax": 2.0,
    "ymax": 2.0,
}


#: Mappers started by a test, closed after it.
STARTED: list[SlamGMapping] = []


def start(bus: Bus, params: dict, argv: tuple[str, ...] = ()) -> SlamGMapping:
    for name, value in params.items():
        bus.params.set(f"/slam_gmapping/{name}", value)
    node = Node("slam_gmapping", bus=bus, argv=list(argv))
    mapper = SlamGMapping(node, read_params(node))
    STARTED.append(mapper)
    return mapper
