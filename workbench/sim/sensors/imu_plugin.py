"""``libgazebo_ros_imu_sensor.so``: sensor_msgs/Imu of an ``imu`` sensor.

Parameters, as gazebo_plugins' gazebo_ros_imu_sensor.cpp (noetic-devel) reads them:

* ``<topicName>`` (default ``imu_data``), relative to ``<robotNamespace>``,
  which defaults to the model's name: ``/MODEL/imu_data``;
* ``<frameName>``: ``header.frame_id``, required (Gazebo refuses to load without it);
* ``<updateRateHZ>`` (default 1 Hz): publications per second, never faster
  than the sensor's ``<update_rate>``;
* ``<gaussianNoise>`` (default 0): added to every component, the orientation
  quaternion's included (not renormalised), and squared on the covariance
  diagonals, as the plugin does;
* ``<rpyOffset>``: rotates the reported orientation (``offset * orientation``);
  ``<xyzOffset>`` is read and unused, as in Gazebo;
* ``<initialOrientationAsReference>``: only false (REP 145, the default) is
  simulated: the orientation is relative to the world.

Values come from :class:`workbench.sim.sensors.Imu` (with the sensor's own
``<imu>`` noise), stamped with simulated time. As the original, it computes and
publishes only while the topic has subscribers (``getNumSubscribers() > 0``); an
idle IMU does not cut the physics into its 5 ms periods either, and its first
reading after a subscriber arrives has no previous velocity to difference
(acceleration 0, the specific force only gravity's reaction), as at start-up.
Without a bus it always updates (``latest`` holds the reading).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.plugins import PluginSetupError, SdfElement, UpdateInfo
from workbench.sim.sensors.base import RosSensorPlugin, parameter
from workbench.sim.sensors.imu import Imu, ImuReading
from workbench.sim.sensors.messages import imu_message, resolve_topic
from workbench.sim.sensors.spec import ImuSpec


class GazeboRosImuSensor(RosSensorPlugin):
    """Publishes ``sensor_msgs/Imu`` of an ``imu`` sensor."""

    sensor_types = ("imu",)
    label = "imu"
    publisher: Any = None

    def setup(self, sdf: SdfElement) -> None:
        assert isinstance(self.spec, ImuSpec)
        if not sdf.has("frameName"):
            raise PluginSetupError(
                f"model '{self.model.name}', link '{self.spec.link}', sensor '{self.spec.name}': "
                f"imu plugin '{sdf.name}' needs <frameName> (gazebo_ros_imu_sensor's requirement)"
            )
        self.imu = Imu(self.spec, seed=self.seed)
        self.frame = parameter(sdf, "frameName", "")
        namespace = parameter(sdf, "robotNamespace", "") or self.model.name
        self.topic = resolve_topic(namespace, parameter(sdf, "topicName", "imu_data"))
        self.gaussian_noise = float(sdf.get("gaussianNoise", 0.0))
        rate = float(sdf.get("updateRateHZ", 1.0))
        if rate > 0 and (self.update_rate <= 0 or rate < self.update_rate):
            self.update_rate = rate
        self.offset = np.array([0.0, 0.0, 0.0, 1.0])
        if sdf.has("rpyOffset"):
            from pydrake.math import RollPitchYaw

            values = [float(v) for v in str(sdf.get("rpyOffset", "0 0 0")).split()]
            q = RollPitchYaw(*values[:3]).ToQuaternion()
            self.offset = np.array([q.x(), q.y(), q.z(), q.w()])
        self._rng = np.random.default_rng(self.seed + 1)
        #: The last reading (before the plugin's gaussianNoise), or None.
        self.latest: ImuReading | None = None
        self.latest_message: Any = None
        self.publisher = None
        self._X_BS = self.spec.pose()
        if self.node is not None:
            from workbench.msgs.sensor_msgs import Imu as ImuMessage

            self.publisher = self.node.create_publisher(self.topic, ImuMessage, queue_size=1)

    def active(self) -> bool:
        if self.publisher is None or self.listeners(self.publisher) > 0:
            return True
        self.imu.forget()
        return False

    def update(self, info: UpdateInfo) -> None:
        body = self.world.body(f"{self.model.name}::{self.spec.link}")
        reading = self.imu.measure(self.world, body, self._X_BS)
        self.latest = reading
        noise = self.gaussian_noise
        orientation = _multiply(self.offset, reading.orientation)
        angular = reading.angular_velocity
        linear = reading.linear_acceleration
        if noise > 0:
            orientation = orientation + self._rng.normal(0.0, noise, 4)
            angular = angular + self._rng.normal(0.0, noise, 3)
            linear = linear + self._rng.normal(0.0, noise, 3)
        self.latest_message = imu_message(
            orientation, angular, linear, noise, self.frame, info.sim_time
        )
        if self.publisher is not None:
            self.publisher.publish(self.latest_message)

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None


def _multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Quaternion product ``a * b`` of (x, y, z, w) quaternions."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array(
        [
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz,
        ]
    )
