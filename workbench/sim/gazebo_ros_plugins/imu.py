"""``libgazebo_ros_imu.so``: the model plugin IMU (``GazeboRosIMU``), as TurtleBot3's URDF uses it.

Parameters, as gazebo_plugins' gazebo_ros_imu.cpp (noetic-devel) reads them::

    <plugin name="imu_plugin" filename="libgazebo_ros_imu.so">
      <bodyName>imu_link</bodyName>        <!-- required: the link measured -->
      <topicName>imu</topicName>           <!-- default /default_imu -->
      <serviceName>imu_service</serviceName> <!-- std_srvs/Empty, default /default_imu -->
      <frameName>imu_link</frameName>      <!-- header.frame_id, default <bodyName> -->
      <gaussianNoise>0.0</gaussianNoise>   <!-- stddev on rates and accelerations -->
      <updateRate>0</updateRate>           <!-- Hz; 0: every physics step -->
      <rpyOffset>0 0 0</rpyOffset>         <!-- rotates the reported orientation -->
    </plugin>

Names are relative to ``<robotNamespace>`` (none: the global namespace; a spawned
robot's is ``/``), so TurtleBot3's IMU publishes ``/imu``. Only while ``topicName`` has
subscribers, every ``1 / updateRate`` s, it publishes ``sensor_msgs/Imu`` stamped with
simulated time, with what this plugin (unlike the ``imu`` sensor's
``libgazebo_ros_imu_sensor.so``) reports:

* ``orientation``: ``rpyOffset * q_WL``, the link frame in the world;
* ``angular_velocity``: the link's angular velocity in the world, plus noise, turned by
  that orientation (``q.RotateVector``, as the plugin does);
* ``linear_acceleration``: the change of the link origin's world velocity since the
  last message over the time between them, plus noise, turned the same way. Gravity
  is not in it: at rest the IMU reads 0, not 9.81 (the plugin's convention).

The covariance diagonals are ``gaussianNoise``^2. The ``<imu><noise>`` block that
TurtleBot3 puts in the element, ``<xyzOffset>`` and ``<alwaysOn>`` are not read, as in
Gazebo. The service answers at once: the IMU is always calibrated. A missing
``<bodyName>`` or a link the model lacks is one error line; the model runs without it.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.gazebo_ros_plugins.links import find_link, link_state, noise_seed, vector
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos, ros_stamp
from workbench.sim.listener_count import ListenerCount
from workbench.sim.plugins import ModelPlugin, PluginSetupError, SdfElement, UpdateInfo


class GazeboRosImu(ModelPlugin):
    """Publishes ``sensor_msgs/Imu`` of a link (see the module docstring)."""

    publisher: Any = None

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("GazeboRosIMU", sdf, model.name, node, default_namespace="")
        body = ros.text("bodyName")
        if not body:
            raise PluginSetupError(
                f"model '{model.name}': imu plugin '{sdf.name}' needs <bodyName> (the link it "
                "measures)"
            )
        self.model = model
        self.link = find_link(model, body, sdf.name, "bodyName", other_models=True)
        self.frame = ros.string("frameName", body)
        self.noise = ros.number("gaussianNoise", 0.0)
        self.update_rate = max(ros.number("updateRate", 0.0), 0.0)
        from pydrake.math import RollPitchYaw

        self.offset = RollPitchYaw(*vector(ros.text("rpyOffset"))).ToRotationMatrix()
        self.rng = np.random.default_rng(noise_seed(model.name, sdf.name))
        X_WL, v_W, _ = link_state(model.server.world, self.link)
        self.last = (model.sim_time, v_W)
        self.acceleration = np.zeros(3)
        #: The last message, or None.
        self.latest_message: Any = None
        self._listeners = ListenerCount()
        topic = ros.string("topicName", "/default_imu")
        self.publisher = None
        self.service = None
        if node is not None and topic:
            self.publisher = node.create_publisher(
                ros.topic(topic), "sensor_msgs/Imu", queue_size=1
            )
            from workbench.msgs.std_srvs import Empty

            self.service = node.create_service(
                ros.topic(ros.string("serviceName", "/default_imu")),
                Empty,
                lambda request: Empty.Response(),
            )

    def active(self) -> bool:
        return self.publisher is None or self._listeners(self.publisher) > 0

    def update(self, info: UpdateInfo) -> None:
        X_WL, v_W, w_W = link_state(self.model.server.world, self.link)
        then, v_before = self.last
        if info.sim_time != then:  # else the last acceleration again, as Gazebo
            self.acceleration = (v_W - v_before) / (info.sim_time - then)
            self.last = (info.sim_time, v_W)
        acceleration = self.acceleration
        rotation = self.offset.multiply(X_WL.rotation())
        R = rotation.matrix()
        noise = self.noise
        angular = R @ (w_W + self.rng.normal(0.0, noise, 3) if noise > 0 else w_W)
        linear = R @ (acceleration + self.rng.normal(0.0, noise, 3) if noise > 0 else acceleration)
        self.latest_message = _message(
            rotation.ToQuaternion(), angular, linear, noise, self.frame, info.sim_time
        )
        if self.publisher is not None:
            self.publisher.publish(self.latest_message)

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None
        if self.service is not None:
            self.service.shutdown()
            self.service = None


def _message(
    q: Any, angular: np.ndarray, linear: np.ndarray, noise: float, frame: str, seconds: float
) -> Any:
    from workbench.msgs.sensor_msgs import Imu

    message = Imu()
    message.header.frame_id = frame
    message.header.stamp = ros_stamp(seconds)
    o = message.orientation
    o.x, o.y, o.z, o.w = float(q.x()), float(q.y()), float(q.z()), float(q.w())
    a, b = message.angular_velocity, message.linear_acceleration
    a.x, a.y, a.z = (float(v) for v in angular)
    b.x, b.y, b.z = (float(v) for v in linear)
    variance = noise * noise
    for field in (
        "orientation_covariance",
        "angular_velocity_covariance",
        "linear_acceleration_covariance",
    ):
        values = [0.0] * 9
        values[0] = values[4] = values[8] = variance
        setattr(message, field, values)
    return message
