"""An inertial measurement unit (Gazebo's ``imu`` sensor) read from the plant's state.

Usable without a server::

    imu = Imu(parse_sensor(xml, model="bot", link="imu_link"))
    reading = imu.measure(world, body, X_BS)

What Gazebo 11's ImuSensor reports, with its orientation reference the world
(REP 145, what gazebo_ros_imu_sensor sets):

* ``orientation``: the sensor frame S in W, a quaternion (x, y, z, w);
* ``angular_velocity``: S's angular velocity in W, expressed in S, rad/s;
* ``linear_acceleration``: the specific force, the acceleration of S's origin
  minus gravity, expressed in S, m/s^2: at rest on the ground it reads +9.81
  along the axis that points up (Gazebo subtracts the world's gravity too).

The acceleration is, as in Gazebo, the change of S's origin's velocity since the
previous reading divided by the time between them (0 at the first reading). Asking
the plant for its accelerations instead would solve the contact problem again at
every reading, which cost a robot in the house half its speed. ``<imu>`` noise (per axis, or the older
``<noise><rate>``/``<accel>`` form) is Gaussian with a bias drawn once per axis,
from a seeded generator.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.sim.sensors.spec import ImuSpec, NoiseSpec


@dataclass
class ImuReading:
    """One IMU measurement (see the module docstring); ``orientation`` is (x, y, z, w)."""

    orientation: np.ndarray
    angular_velocity: np.ndarray
    linear_acceleration: np.ndarray
    time: float = 0.0


class Imu:
    """Measurements of one ``imu`` sensor.

    Args:
        spec: The sensor (see :func:`workbench.sim.sensors.parse_sensor`).
        seed: Seed of the noise generator.
    """

    def __init__(self, spec: ImuSpec, seed: int = 0) -> None:
        self.spec = spec
        self._rng = np.random.default_rng(seed)
        self._rate_bias = self._biases(spec.angular_velocity_noise)
        self._accel_bias = self._biases(spec.linear_acceleration_noise)
        self._last: tuple[float, np.ndarray] | None = None

    def _biases(self, noises: tuple[NoiseSpec | None, ...]) -> np.ndarray:
        bias = np.zeros(3)
        for i, noise in enumerate(noises):
            if noise is not None and (noise.bias_mean or noise.bias_stddev):
                value = self._rng.normal(noise.bias_mean, noise.bias_stddev)
                bias[i] = value if self._rng.uniform() < 0.5 else -value  # Gazebo flips the sign
        return bias

    def measure(self, world: Any, body: Any, X_BS: Any, *, noise: bool = True) -> ImuReading:
        """The IMU on ``body`` (a plant body) at ``X_BS`` (a RigidTransform), now."""
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        X_WB = plant.EvalBodyPoseInWorld(context, body)
        V_WB = plant.EvalBodySpatialVelocityInWorld(context, body)
        R_WB = X_WB.rotation().matrix()
        R_WS = R_WB @ X_BS.rotation().matrix()
        r = R_WB @ np.asarray(X_BS.translation())
        w = np.asarray(V_WB.rotational())
        v_point = np.asarray(V_WB.translational()) + np.cross(w, r)
        now = float(world.time)
        a_point = np.zeros(3)
        if self._last is not None and now > self._last[0]:
            a_point = (v_point - self._last[1]) / (now - self._last[0])
        self._last = (now, v_point)
        gravity = np.asarray(plant.gravity_field().gravity_vector())  # the world's, as Gazebo
        angular = R_WS.T @ w
        specific = R_WS.T @ (a_point - gravity)
        if noise:
            angular = angular + self._draw(self.spec.angular_velocity_noise) + self._rate_bias
            specific = specific + self._draw(self.spec.linear_acceleration_noise) + self._accel_bias
        from pydrake.math import RotationMatrix

        q = RotationMatrix(R_WS).ToQuaternion()
        return ImuReading(
            orientation=np.array([q.x(), q.y(), q.z(), q.w()]),
            angular_velocity=angular,
            linear_acceleration=specific,
            time=float(world.time),
        )

    def forget(self) -> None:
        """Drop the previous reading: the next one reports no acceleration (a restart)."""
        self._last = None

    def _draw(self, noises: tuple[NoiseSpec | None, ...]) -> np.ndarray:
        values = np.zeros(3)
        for i, noise in enumerate(noises):
            if noise is not None:
                values[i] = self._rng.normal(noise.mean, noise.stddev)
        return values
