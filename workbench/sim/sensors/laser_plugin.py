"""``libgazebo_ros_laser.so`` and ``libgazebo_ros_gpu_laser.so``: LaserScan from a ray sensor.

Parameters, as gazebo_plugins' gazebo_ros_laser.cpp and gazebo_ros_gpu_laser.cpp
(noetic-devel) read them:

* ``<topicName>``: the LaserScan topic (default ``/world``, the plugins' own
  default), relative names under ``<robotNamespace>``;
* ``<frameName>``: ``header.frame_id`` (default ``/world``), given without its
  leading slash as noetic's ``tf::resolve`` does.

Both plugins publish the sensor's scans unchanged (see
:mod:`workbench.sim.sensors.lidar` for out-of-range readings: +inf beyond
``<range><max>``), stamped with the simulated time of the scan, at the sensor's
``<update_rate>``. Gazebo runs the sensor only while somebody subscribes; here
the scan is computed at every update (it is cheap), so :attr:`latest` is there
for Python code too. Both library names map to the same class: workbench's
``ray`` and ``gpu_ray`` sensors are the same exact ray caster.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.plugins import SdfElement, UpdateInfo
from workbench.sim.sensors.base import RosSensorPlugin, parameter, robot_namespace
from workbench.sim.sensors.lidar import Lidar
from workbench.sim.sensors.messages import laser_scan, resolve_topic, tf_frame
from workbench.sim.sensors.spec import LASER_TYPES, LaserSpec


class GazeboRosLaser(RosSensorPlugin):
    """Publishes ``sensor_msgs/LaserScan`` of a ``ray`` or ``gpu_ray`` sensor."""

    sensor_types = LASER_TYPES
    label = "laser"
    publisher: Any = None

    def setup(self, sdf: SdfElement) -> None:
        assert isinstance(self.spec, LaserSpec)
        self.lidar = Lidar(self.spec, seed=self.seed)
        self.topic = resolve_topic(robot_namespace(sdf), parameter(sdf, "topicName", "/world"))
        self.frame = tf_frame(parameter(sdf, "frameName", "/world"))
        #: The last scan's readings (m, see Lidar.scan), or None before the first.
        self.latest: np.ndarray | None = None
        #: The last LaserScan message, or None.
        self.latest_message: Any = None
        self.publisher = None
        if self.node is not None:
            from workbench.msgs.sensor_msgs import LaserScan

            self.publisher = self.node.create_publisher(self.topic, LaserScan, queue_size=1)

    def update(self, info: UpdateInfo) -> None:
        X_WS, body = self.sensor_pose()
        ranges = self.lidar.scan(self.world, X_WS, exclude_body=int(body.index()))
        assert isinstance(self.spec, LaserSpec)
        self.latest = ranges
        self.latest_message = laser_scan(self.spec, ranges, self.frame, info.sim_time)
        if self.publisher is not None:
            self.publisher.publish(self.latest_message)

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None
