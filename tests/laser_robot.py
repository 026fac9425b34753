"""A simulated laser robot on an in-process bus, shared by the slam_gmapping and amcl tests.

It publishes ``/clock``, ``/tf`` (``odom -> base_link``), ``/tf_static`` (``base_link ->
laser``) and ``/scan`` one step at a time; a subclass says how its scans are ray-cast
(:meth:`LaserRobot.scan_msg`). Importable by name from any test folder.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import TransformStamped
from workbench.msgs.rosgraph_msgs import Clock
from workbench.msgs.sensor_msgs import LaserScan
from workbench.msgs.tf2_msgs import TFMessage

#: Where the laser sits on the robot (x, y, theta in base_link) and its height (m).
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


class LaserRobot:
    """Publishes what a robot driving known poses would publish, one step at a time."""

    def __init__(self, bus: Bus, dt: float = 0.2) -> None:
        self.bus = bus
        self.node = Node("robot", bus=bus, disable_rosout=True)
        self.clock = self.node.create_publisher("/clock", Clock, 10)
        self.tf = self.node.create_publisher("/tf", TFMessage, 100)
        self.tf_static = self.node.create_publisher("/tf_static", TFMessage, 10, latch=True)
        self.scan = self.node.create_publisher("/scan", LaserScan, 10)
        self.dt = dt
        self.t = 100.0

    def mount(self, frame: str = "laser", upside_down: bool = False) -> None:
        msg = transform("base_link", frame, MOUNT, 0.0, MOUNT_Z)
        if upside_down:  # roll by pi
            msg.transform.rotation.x, msg.transform.rotation.w = 1.0, 0.0
        self.tf_static.publish(TFMessage(transforms=[msg]))

    def tick(self, stamp: float) -> None:
        self.clock.publish(Clock(clock=Time.from_sec(stamp)))

    def scan_msg(self, truth: np.ndarray, stamp: float, frame: str = "laser") -> LaserScan:
        raise NotImplementedError

    def step(self, truth: np.ndarray, odom: np.ndarray, scan: LaserScan | None = None) -> float:
        """Advance the clock by ``dt``, publish ``odom -> base_link`` and a scan; the stamp."""
        self.t += self.dt
        self.tick(self.t)
        self.tf.publish(TFMessage(transforms=[transform("odom", "base_link", odom, self.t)]))
        msg = scan if scan is not None else self.scan_msg(truth, self.t)
        msg.header.stamp = Time.from_sec(self.t)
        self.scan.publish(msg)
        return self.t


def wait_until(predicate: Callable[[], Any], timeout: float = 20.0) -> bool:
    """:func:`process_helpers.wait_for` polling every 5 ms (a stepped bus answers at once)."""
    return wait_for(predicate, timeout, poll=0.005)


def sim_time_bus(started: list[Any]) -> Iterator[Bus]:
    """An in-process bus on simulated time for a fixture; the nodes in ``started`` (each
    with ``close()``) are closed after it."""
    bus = Bus()
    bus.params.set("/use_sim_time", True)
    yield bus
    bus.shutdown()
    for node in started:
        node.close()
    started.clear()
