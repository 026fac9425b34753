"""A kinematic robot for the move_base tests: /cmd_vel in, odom, tf, /scan and /map out.

The world is line segments (:mod:`workbench.mapping.simulate`): a 6 x 4 m room with a
box in the middle. The robot integrates the last ``/cmd_vel`` (a planar twist in its own
frame) into ``odom -> base_footprint``, publishes ``/odom`` with that twist, a 360-beam
``/scan`` from ``base_scan`` by ray casting and the room as a latched ``/map``
(``map -> odom`` is the identity, or left to a localiser). It records the closest it came to any wall.
"""

from __future__ import annotations

import math

import numpy as np

from workbench.bus import Bus, Node
from workbench.mapping.simulate import box_segments, raycast
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import TransformStamped, Twist
from workbench.msgs.nav_msgs import OccupancyGrid, Odometry
from workbench.msgs.sensor_msgs import LaserScan
from workbench.msgs.tf2_msgs import TFMessage

RES = 0.05
ROOM = (6.0, 4.0)
BOX = (2.6, 1.1, 3.4, 2.9)


def room_segments() -> np.ndarray:
    return np.concatenate([box_segments(0.0, 0.0, *ROOM), box_segments(*BOX)])


def map_message(segments: np.ndarray) -> OccupancyGrid:
    """The segments rasterised at 5 cm: 100 on a segment, 0 elsewhere."""
    w, h = int(round(ROOM[0] / RES)), int(round(ROOM[1] / RES))
    cells = np.zeros((h, w), dtype=np.int8)
    for a, b in segments:
        n = int(np.ceil(np.hypot(*(b - a)) / (RES / 4))) + 1
        pts = a + np.linspace(0, 1, n)[:, None] * (b - a)
        mx = np.clip((pts[:, 0] / RES).astype(int), 0, w - 1)
        my = np.clip((pts[:, 1] / RES).astype(int), 0, h - 1)
        cells[my, mx] = 100
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.info.resolution = RES
    grid.info.width, grid.info.height = w, h
    grid.info.origin.orientation.w = 1.0
    grid.data = cells.reshape(-1)
    return grid


def _tf(
    parent: str, child: str, x: float, y: float, z: float, yaw: float, stamp: Time
) -> TransformStamped:
    msg = TransformStamped()
    msg.header.frame_id, msg.header.stamp, msg.child_frame_id = parent, stamp, child
    msg.transform.translation.x, msg.transform.translation.y, msg.transform.translation.z = x, y, z
    msg.transform.rotation.z, msg.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return msg


class KinematicRobot:
    """The simulated robot on ``bus`` (a stepped bus on simulated time)."""

    def __init__(
        self,
        bus: Bus,
        pose: tuple[float, float, float],
        radius: float = 0.15,
        map_to_odom: bool = True,
    ) -> None:
        self.bus = bus
        self.pose = np.array(pose, dtype=float)
        self.radius = radius
        self.segments = room_segments()
        self.cmd = np.zeros(3)
        self.cmds: list[tuple[float, float, float]] = []
        self.closest = math.inf
        self.node = Node("robot_sim", bus=bus, disable_rosout=True)
        self.node.create_subscription("/cmd_vel", Twist, self._on_cmd, 10)
        self.tf_pub = self.node.create_publisher("/tf", TFMessage, 100)
        static = self.node.create_publisher("/tf_static", TFMessage, 10, latch=True)
        self.odom_pub = self.node.create_publisher("/odom", Odometry, 10)
        self.scan_pub = self.node.create_publisher("/scan", LaserScan, 10)
        map_pub = self.node.create_publisher("/map", OccupancyGrid, 1, latch=True)
        now = self.node.now()
        mounts = [_tf("base_footprint", "base_scan", 0.0, 0, 0.2, 0.0, now)]
        if map_to_odom:  # without it, a localiser (amcl) sends map -> odom
            mounts.insert(0, _tf("map", "odom", 0, 0, 0, 0.0, now))
        static.publish(TFMessage(transforms=mounts))
        msg = map_message(self.segments)
        msg.header.stamp = now
        map_pub.publish(msg)
        self.angles = np.linspace(-math.pi, math.pi, 360, endpoint=False)
        self.last_scan = -math.inf
        self.publish_state()

    def _on_cmd(self, msg: Twist) -> None:
        self.cmd = np.array([msg.linear.x, msg.linear.y, msg.angular.z], dtype=float)
        self.cmds.append(tuple(self.cmd))

    def add_segments(self, segments: np.ndarray) -> None:
        """Put more walls into the world (seen by the laser from now on; not on the map)."""
        self.segments = np.concatenate([self.segments, segments])

    def wall_distance(self) -> float:
        a, b = self.segments[:, 0], self.segments[:, 1]
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", self.pose[:2] - a, d) / np.einsum("ij,ij->i", d, d), 0, 1)
        return float(np.hypot(*(a + t[:, None] * d - self.pose[:2]).T).min())

    def step(self, dt: float) -> None:
        """Integrate the last command for ``dt`` s (of the bus clock, advanced by the caller)."""
        vx, vy, w = self.cmd
        x, y, th = self.pose
        self.pose = np.array(
            [
                x + (vx * math.cos(th) - vy * math.sin(th)) * dt,
                y + (vx * math.sin(th) + vy * math.cos(th)) * dt,
                th + w * dt,
            ]
        )
        self.closest = min(self.closest, self.wall_distance())

    def publish_state(self, scan_period: float = 0.1) -> None:
        now = self.node.now()
        x, y, th = (float(v) for v in self.pose)
        self.tf_pub.publish(
            TFMessage(transforms=[_tf("odom", "base_footprint", x, y, 0.0, th, now)])
        )
        odom = Odometry()
        odom.header.frame_id, odom.header.stamp, odom.child_frame_id = "odom", now, "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = (
            math.sin(th / 2),
            math.cos(th / 2),
        )
        odom.twist.twist.linear.x, odom.twist.twist.linear.y = (
            float(self.cmd[0]),
            float(self.cmd[1]),
        )
        odom.twist.twist.angular.z = float(self.cmd[2])
        self.odom_pub.publish(odom)
        t = now.to_sec()
        if t - self.last_scan >= scan_period - 1e-9:
            self.last_scan = t
            scan = LaserScan()
            scan.header.frame_id, scan.header.stamp = "base_scan", now
            scan.angle_min, scan.angle_increment = (
                float(self.angles[0]),
                float(self.angles[1] - self.angles[0]),
            )
            scan.angle_max = float(self.angles[-1])
            scan.range_min, scan.range_max = 0.12, 3.5
            scan.ranges = raycast(self.segments, self.pose, self.angles, 3.5).tolist()
            self.scan_pub.publish(scan)


class SimClock:
    """Advances a stepped bus's simulated clock and runs what became due."""

    def __init__(self, bus: Bus, start: float = 1.0) -> None:
        self.bus = bus
        self.t = start
        bus.clock.use_sim_time(True)
        bus.clock.set_time(round(start * 1e9))

    def drain(self) -> None:
        while self.bus.spin_once(0.0):
            pass

    def run(self, robot: KinematicRobot, seconds: float, dt: float = 0.05, until=None) -> bool:
        """Step robot and clock for up to ``seconds``; stops early when ``until()`` is true."""
        end = self.t + seconds
        while self.t < end - 1e-9:
            robot.step(dt)
            self.t += dt
            self.bus.clock.set_time(round(self.t * 1e9))
            robot.publish_state()
            self.drain()
            if until is not None and until():
                return True
        return False
