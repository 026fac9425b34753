"""A small world for the costmap tests: a map, tf and laser scans on an in-process bus.

The map is 4 x 4 m at 0.05 m (80 x 80 cells, origin (-2, -2)): free, a wall of
occupied cells in column 70 (x = 1.5 .. 1.55 m) and an unknown block in the lower left.
The robot (``base_link``) stands at the origin of ``odom`` = ``map``; its laser
``base_scan`` is 0.1 m ahead and 0.2 m up.
"""

from __future__ import annotations

import math

import numpy as np

from workbench.bus import Node
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import TransformStamped
from workbench.msgs.nav_msgs import OccupancyGrid
from workbench.msgs.sensor_msgs import LaserScan
from workbench.msgs.tf2_msgs import TFMessage

RESOLUTION = 0.05
SIZE = 80
ORIGIN = (-2.0, -2.0)
WALL_COLUMN = 70
LASER = (0.1, 0.0, 0.2)


def map_cells() -> np.ndarray:
    """The map's cells (row 0 at the origin): 0 free, 100 wall, -1 unknown."""
    cells = np.zeros((SIZE, SIZE), dtype=np.int8)
    cells[:, WALL_COLUMN] = 100
    cells[0:10, 0:10] = -1
    return cells


def map_message(stamp: Time) -> OccupancyGrid:
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.header.stamp = stamp
    grid.info.resolution = RESOLUTION
    grid.info.width = grid.info.height = SIZE
    grid.info.origin.position.x, grid.info.origin.position.y = ORIGIN
    grid.info.origin.orientation.w = 1.0
    grid.data = map_cells().reshape(-1)
    return grid


def transform(parent: str, child: str, xyz, yaw: float, stamp: Time) -> TransformStamped:
    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.header.stamp = stamp
    msg.child_frame_id = child
    t = msg.transform.translation
    t.x, t.y, t.z = (float(v) for v in xyz)
    msg.transform.rotation.z = math.sin(yaw / 2)
    msg.transform.rotation.w = math.cos(yaw / 2)
    return msg


class World:
    """Publishes ``/map``, ``/tf``, ``/tf_static`` and ``/scan`` from a node ``world``."""

    def __init__(self, bus) -> None:
        self.node = Node("world", bus=bus, disable_rosout=True)
        self.map_pub = self.node.create_publisher("/map", OccupancyGrid, 1, latch=True)
        self.tf_pub = self.node.create_publisher("/tf", TFMessage, 100)
        self.static_pub = self.node.create_publisher("/tf_static", TFMessage, 10, latch=True)
        self.scan_pub = self.node.create_publisher("/scan", LaserScan, 10)

    def publish_map(self) -> None:
        self.map_pub.publish(map_message(self.node.now()))

    def publish_static(self) -> None:
        stamp = self.node.now()
        self.static_pub.publish(
            TFMessage(
                transforms=[
                    transform("map", "odom", (0, 0, 0), 0.0, stamp),
                    transform("base_link", "base_scan", LASER, 0.0, stamp),
                ]
            )
        )

    def publish_pose(self, x: float, y: float, yaw: float, stamp: Time) -> None:
        self.tf_pub.publish(
            TFMessage(transforms=[transform("odom", "base_link", (x, y, 0), yaw, stamp)])
        )

    def scan(self, ranges, stamp: Time, range_max: float = 3.5) -> LaserScan:
        """A scan of ``len(ranges)`` beams over the full circle from angle 0."""
        msg = LaserScan()
        msg.header.frame_id = "base_scan"
        msg.header.stamp = stamp
        n = len(ranges)
        msg.angle_min = 0.0
        msg.angle_increment = 2 * math.pi / n
        msg.angle_max = msg.angle_increment * (n - 1)
        msg.range_min = 0.12
        msg.range_max = range_max
        msg.ranges = [float(r) for r in ranges]
        return msg


#: The lab's global costmap, in pre-Hydro keys (costmap_common_params.yaml loaded into
#: global_costmap, then global_costmap_params.yaml).
GLOBAL_PARAMS = {
    "obstacle_range": 2.5,
    "raytrace_range": 3.0,
    "footprint": [[0.2, 0.2], [-0.2, 0.2], [-0.2, -0.2], [0.2, -0.2]],
    "inflation_radius": 0.55,
    "observation_sources": "laser_scan_sensor",
    "laser_scan_sensor": {
        "sensor_frame": "base_scan",
        "data_type": "LaserScan",
        "topic": "scan",
        "marking": True,
        "clearing": True,
    },
    "global_frame": "map",
    "robot_base_frame": "base_link",
    "update_frequency": 5.0,
    "static_map": True,
}


def set_params(bus, namespace: str, params: dict) -> None:
    for key, value in params.items():
        bus.params.set(f"{namespace}/{key}", value)
