"""turtlebot3_drive: wander with the lidar, as turtlebot3_gazebo's node does.

The decision loop (125 Hz) looks at three ranges of the latest ``scan``: ahead,
to the left and to the right, and drives a four-state machine:

* *get direction*: ahead clear (> 0.7 m): if the left is near (< 0.6 m) turn
  right, else if the right is near turn left, else drive forward; ahead blocked
  (< 0.7 m): turn right.
* *drive forward*: publish 0.3 m/s once, then get the direction again.
* *turn right/left*: publish -/+1.5 rad/s until the heading (from ``odom``)
  has changed by 30 deg since the turn began, then get the direction again.

Readings: ``+inf`` (nothing within range) counts as ``range_max``, ``-inf``
(closer than ``range_min``) as 0, and ``NaN`` (no valid return) keeps that
direction's previous reading (``range_max`` before there is one). The angles are
looked up by angle, so scans that start at -pi or cover only the front work too.
Until the first scan arrives nothing is published; on exit a zero Twist is.

Differences from the original, on purpose: each of the three ranges is the nearest
reading in a sector (ahead -15..15 deg, left 15..60 deg, right -60..-15 deg) where the
original reads one beam each (0, 30 and 330 deg): between those beams a 5 cm table leg
stays unseen until the robot touches it (in the house it ran into legs three times in
ten minutes). The turn's heading change is wrapped
to [-pi, pi] (the original ends a turn early when the heading crosses +-pi), and
``cmd_vel_topic_name`` (a parameter of the node's namespace, which the original's
launch file sets to ``/cmd_vel``) defaults to ``cmd_vel``.
"""

from __future__ import annotations

import contextlib
import enum
import math
import threading
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.teleop.keys import Velocity

LINEAR_VELOCITY = 0.3
ANGULAR_VELOCITY = 1.5
CHECK_FORWARD_DIST = 0.7
CHECK_SIDE_DIST = 0.6
ESCAPE_RANGE = math.radians(30.0)
LOOP_HZ = 125.0
#: center, left, right: the sectors whose nearest reading counts, (from, to) in rad.
SECTORS = (
    (math.radians(-15.0), math.radians(15.0)),
    (math.radians(15.0), math.radians(60.0)),
    (math.radians(-60.0), math.radians(-15.0)),
)


class DriveState(enum.IntEnum):
    """The states of the wander loop (numbered as in the original)."""

    GET_DIRECTION = 0
    DRIVE_FORWARD = 1
    RIGHT_TURN = 2
    LEFT_TURN = 3


def sector_min(scan: Any, start: float, end: float) -> float | None:
    """The nearest usable reading of ``scan`` between ``start`` and ``end`` (rad, wrapped),
    with -inf (closer than range_min) as 0 and inf as range_max; None if the sector holds
    no beam or only NaNs."""
    count = len(scan.ranges)
    step = float(scan.angle_increment)
    if count == 0 or step == 0 or not math.isfinite(step):
        return None
    ranges = np.asarray(scan.ranges, dtype=float)
    angles = float(scan.angle_min) + step * np.arange(count)
    middle, half = (start + end) / 2.0, (end - start) / 2.0
    inside = np.abs(np.remainder(angles - middle + math.pi, 2 * math.pi) - math.pi) < half
    values = ranges[inside & ~np.isnan(ranges)]
    if values.size == 0:
        return None
    values = np.where(np.isposinf(values), float(scan.range_max), values)
    return float(np.where(np.isneginf(values), 0.0, values).min())


def yaw_of(orientation: Any) -> float:
    """The heading (rad) of a quaternion with fields x, y, z, w."""
    x, y, z, w = orientation.x, orientation.y, orientation.z, orientation.w
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def angle_between(a: float, b: float) -> float:
    """``|a - b|`` wrapped to [0, pi]."""
    return abs(math.remainder(a - b, 2 * math.pi))


class Turtlebot3Drive:
    """The wander decisions, without a bus: feed scans and headings, call :meth:`step`.

    Attributes:
        readings: (center, left, right) ranges from the latest scan, m; None before one.
        state: The current :class:`DriveState`.
        yaw: The latest heading from odometry, rad.
    """

    def __init__(self) -> None:
        self.readings: tuple[float, float, float] | None = None
        self.state = DriveState.GET_DIRECTION
        self.yaw = 0.0
        self.turn_start_yaw = 0.0
        self._lock = threading.Lock()

    def on_scan(self, scan: Any) -> None:
        """Take the three readings from a ``sensor_msgs/LaserScan``."""
        previous = self.readings or (float(scan.range_max),) * 3
        readings = (sector_min(scan, start, end) for start, end in SECTORS)
        center, left, right = (
            last if value is None else value for value, last in zip(readings, previous, strict=True)
        )
        with self._lock:
            self.readings = (center, left, right)

    def on_odom(self, odom: Any) -> None:
        """Take the heading from a ``nav_msgs/Odometry``."""
        yaw = yaw_of(odom.pose.pose.orientation)
        with self._lock:
            self.yaw = yaw

    def step(self) -> Velocity | None:
        """One pass of the decision loop: the command to publish, or None."""
        with self._lock:
            readings, yaw = self.readings, self.yaw
        if readings is None:
            return None
        center, left, right = readings
        state = self.state
        if state == DriveState.GET_DIRECTION:
            if center > CHECK_FORWARD_DIST:
                if left < CHECK_SIDE_DIST:
                    self._turn(DriveState.RIGHT_TURN, yaw)
                elif right < CHECK_SIDE_DIST:
                    self._turn(DriveState.LEFT_TURN, yaw)
                else:
                    self.state = DriveState.DRIVE_FORWARD
            elif center < CHECK_FORWARD_DIST:
                self._turn(DriveState.RIGHT_TURN, yaw)
            return None
        if state == DriveState.DRIVE_FORWARD:
            self.state = DriveState.GET_DIRECTION
            return Velocity(x=LINEAR_VELOCITY)
        if angle_between(self.turn_start_yaw, yaw) >= ESCAPE_RANGE:
            self.state = DriveState.GET_DIRECTION
            return None
        sign = -1.0 if state == DriveState.RIGHT_TURN else 1.0
        return Velocity(yaw=sign * ANGULAR_VELOCITY)

    def _turn(self, state: DriveState, yaw: float) -> None:
        self.turn_start_yaw = yaw
        self.state = state


def drive(node: Any, stop: threading.Event | None = None) -> int:
    """Run the wander loop on ``node`` until it shuts down (or ``stop`` is set); then a zero Twist.

    Returns:
        0.
    """
    from workbench.bus import ShutdownError, ShutdownInterrupt
    from workbench.msgs.geometry_msgs import Twist
    from workbench.msgs.nav_msgs import Odometry
    from workbench.msgs.sensor_msgs import LaserScan

    topic = str(node.get_param("cmd_vel_topic_name", "") or "cmd_vel")
    publisher = node.create_publisher(topic, Twist, queue_size=10)
    wander = Turtlebot3Drive()
    node.create_subscription("scan", LaserScan, wander.on_scan, queue_size=10)
    node.create_subscription("odom", Odometry, wander.on_odom, queue_size=10)
    node.get_logger().info("TurtleBot3 Simulation Node Init")
    rate = node.create_rate(LOOP_HZ)
    try:
        while not node.is_shutdown and not (stop is not None and stop.is_set()):
            command = wander.step()
            if command is not None:
                publisher.publish(command.to_twist())
            rate.sleep()
    except ShutdownInterrupt:
        pass
    finally:
        with contextlib.suppress(ShutdownError):
            publisher.publish(Twist())
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """``turtlebot3_gazebo/turtlebot3_drive`` for ``workbench run`` and launch files."""
    from workbench.bus import Node

    node = Node("turtlebot3_drive", argv=list(argv or []))
    try:
        return drive(node)
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
