"""A simulated robot on an in-process bus for slam_gmapping tests: ``/clock``, ``/tf``
(``odom -> base_link`` from drifting odometry, static ``base_link -> laser``) and ``/scan``
ray-cast in :func:`~workbench.mapping.simulate.demo_world` from known poses."""

from __future__ import annotations

import math
import time

import numpy as np

from workbench.bus import Bus, Node
from workbench.mapping.geometry import between, compose
from workbench.mapping.gmapping_node import SlamGMapping
from workbench.mapping.gmapping_params import read_params
from workbench.mapping.simulate import demo_world, raycast
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import TransformStamped
from workbench.msgs.rosgraph_msgs import Clock
from workbench.msgs.sensor_msgs import LaserScan
from workbench.msgs.tf2_msgs import TFMessage

#: Where the laser sits on the robot (x, y, theta in base_link) and its height.
MOUNT = np.array([0.1, 0.0, 0.0])
MOUNT_Z = 0.2


def transform(parent: str, child: str, pose: np.ndarray, stamp: float, z: float = 0.0):
    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.header.stamp = Time.from_sec(stamp)
    msg.child_frame_id = child
    msg.transform.translation.x, msg.transform.translation.y = float(pose[0]), float(pose[1])
    msg.transform.translation.z = z
    msg.transform.rotation.z = math.sin(pose[2] / 2)
    msg.transform.rotation.w = math.cos(pose[2] / 2)
    return msg


def drifting_odometry(truth: np.ndarray, scale: float = 1.04, turn: float = 0.006) -> np.ndarray:
    """Odometry of ``truth`` whose steps are ``scale`` too long and turn ``turn`` rad too far."""
    odom = [truth[0].copy()]
    for a, b in zip(truth[:-1], truth[1:], strict=True):
        step = between(a, b)
        step[:2] *= scale
        step[2] += turn if np.hypot(step[0], step[1]) > 1e-9 else 0.0
        odom.append(compose(odom[-1], step))
    return np.array(odom)


class Feeder:
    """Publishes what a robot driving ``truth`` (base poses) would publish, one step at a time."""

    def __init__(self, bus: Bus, beams: int = 360, max_range: float = 3.5, dt: float = 0.2) -> None:
        self.bus = bus
        self.node = Node("robot", bus=bus, disable_rosout=True)
        self.clock = self.node.create_publisher("/clock", Clock, 10)
        self.tf = self.node.create_publisher("/tf", TFMessage, 100)
        self.tf_static = self.node.create_publisher("/tf_static", TFMessage, 10, latch=True)
        self.scan = self.node.create_publisher("/scan", LaserScan, 10)
        self.world = demo_world()
        self.beams, self.max_range, self.dt = beams, max_range, dt
        self.t = 100.0

    def mount(self, frame: str = "laser", upside_down: bool = False) -> None:
        msg = transform("base_link", frame, MOUNT, 0.0, MOUNT_Z)
        if upside_down:  # roll by pi
            msg.transform.rotation.x, msg.transform.rotation.w = 1.0, 0.0
        self.tf_static.publish(TFMessage(transforms=[msg]))

    def tick(self, stamp: float) -> None:
        self.clock.publish(Clock(clock=Time.from_sec(stamp)))

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

    def step(self, truth: np.ndarray, odom: np.ndarray, scan: LaserScan | None = None) -> float:
        """Advance the clock by ``dt``, publish ``odom -> base_link`` and a scan; the stamp."""
        self.t += self.dt
        self.tick(self.t)
        self.tf.publish(TFMessage(transforms=[transform("odom", "base_link", odom, self.t)]))
        msg = scan if scan is not None else self.scan_msg(truth, self.t)
        msg.header.stamp = Time.from_sec(self.t)
        self.scan.publish(msg)
        return self.t


def wait_until(predicate, timeout: float = 20.0) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.005)
    return bool(predicate())


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
