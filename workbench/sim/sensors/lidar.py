"""A laser scanner (Gazebo's ``ray`` and ``gpu_ray`` sensors) by exact ray casting.

Usable without a server::

    from workbench.sim.sensors import Lidar, parse_sensor
    lidar = Lidar(parse_sensor(xml, model="bot", link="laser"))
    ranges = lidar.scan(world, X_WS)          # (vertical x horizontal,) metres

Beams leave the sensor frame S's origin; beam (i, j) points along
``Rz(yaw_i) Ry(-pitch_j) x`` of S (Gazebo's MultiRayShape: yaw from
``<horizontal>``, pitch from ``<vertical>``, positive pitch up). Readings are
ordered row by row of the vertical angle, each row from ``min_angle`` to
``max_angle``. Geometry of the link the sensor is on is not seen.

Readings follow Gazebo 11's RaySensor and GpuRaySensor (REP 117): the first
surface a beam crosses beyond ``<range><min>`` gives its distance; a beam that
reaches ``<range><max>`` without crossing one reads ``+inf``, a distance at or
below ``<min>`` reads ``-inf``, and only the readings in between get the
``<noise>`` (Gaussian, from a seeded generator), clamped to ``[min, max]``.
``gazebo_ros_laser`` and ``gazebo_ros_gpu_laser`` publish these values as
they are. ``<range><resolution>`` is read but not applied (Gazebo does not
quantise either). With ``<resolution>`` other than 1, Gazebo interpolates
between ``samples`` rays; here every reading is a ray of its own.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.sensors.collision import collision_scene
from workbench.sim.sensors.raycast import cast_rays
from workbench.sim.sensors.spec import LaserSpec


class Lidar:
    """Scans of one ``ray``/``gpu_ray`` sensor.

    Args:
        spec: The sensor (see :func:`workbench.sim.sensors.parse_sensor`).
        seed: Seed of the noise generator (each Lidar draws its own sequence).
    """

    def __init__(self, spec: LaserSpec, seed: int = 0) -> None:
        self.spec = spec
        yaw = spec.horizontal.angles()
        pitch = spec.vertical.angles()
        P, Y = np.meshgrid(pitch, yaw, indexing="ij")
        #: (N, 3) beam directions in S, vertical-major.
        self.directions_S = np.stack(
            [np.cos(P) * np.cos(Y), np.cos(P) * np.sin(Y), np.sin(P)], axis=-1
        ).reshape(-1, 3)
        self._rng = np.random.default_rng(seed)

    @property
    def angle_increment(self) -> float:
        """Horizontal angle between readings, rad (0 for one reading)."""
        n = self.spec.horizontal.count
        h = self.spec.horizontal
        return 0.0 if n < 2 else (h.max_angle - h.min_angle) / (n - 1)

    def distances(self, world: Any, X_WS: Any, *, exclude_body: int | None = None) -> np.ndarray:
        """Noise-free distances to the first surface per beam (inf: nothing within max range), m."""
        scene = collision_scene(world)
        R_WS = np.asarray(X_WS.rotation().matrix())
        origin = np.asarray(X_WS.translation())
        return cast_rays(
            scene.table,
            origin,
            self.directions_S @ R_WS.T,
            self.spec.range_min,
            self.spec.range_max,
            R_WS=R_WS,
            active=scene.mask_without(exclude_body),
        )

    def scan(
        self, world: Any, X_WS: Any, *, exclude_body: int | None = None, noise: bool = True
    ) -> np.ndarray:
        """One scan as Gazebo reports it (see the module docstring), float64, m.

        Args:
            world: A built :class:`workbench.sim.World`.
            X_WS: The sensor's pose in W (a RigidTransform).
            exclude_body: Index of a body whose geometry the beams pass through
                (the sensor's own link).
            noise: Apply the spec's Gaussian noise.
        """
        return self.readings(self.distances(world, X_WS, exclude_body=exclude_body), noise=noise)

    def readings(self, distances: np.ndarray, *, noise: bool = True) -> np.ndarray:
        """Gazebo's readings from distances: the +-inf masks, then noise in range."""
        low, high = self.spec.range_min, self.spec.range_max
        ranges = np.array(distances, dtype=float)
        beyond = ranges >= high
        below = ranges <= low
        inside = ~(beyond | below)
        spec_noise = self.spec.noise
        if noise and spec_noise is not None and inside.any():
            drawn = self._rng.normal(spec_noise.mean, spec_noise.stddev or 0.0, inside.sum())
            ranges[inside] = np.clip(ranges[inside] + drawn, low, high)
        ranges[beyond] = np.inf
        ranges[below] = -np.inf
        return ranges
