"""Simulated sensors: lasers, cameras, depth cameras and IMUs, and Gazebo's ROS plugins for them.

From Python, without a server::

    from workbench.sim.sensors import Lidar, Camera, Imu, parse_sensor
    spec = parse_sensor(xml, model="bot", link="laser")      # an SDF <sensor>
    ranges = Lidar(spec).scan(world, X_WS)                    # a built World, a pose in W

In a running :class:`~workbench.sim.server.SimServer`, a model's
``<sensor>`` with a ``libgazebo_ros_laser.so`` (``gpu_laser``, ``camera``,
``openni_kinect``, ``depth_camera``, ``imu_sensor``) plugin publishes on the
bus as Gazebo does, and :func:`sensor_plugin` finds it for a notebook::

    laser = sensor_plugin(server, "laser")
    laser.latest                      # the last scan's ranges
    sensor_plugin(server, "kinect").capture().depth

Modules: :mod:`.spec` (parsing), :mod:`.raycast` and :mod:`.collision` (exact
ray casting against the World's collision geometry), :mod:`.lidar`,
:mod:`.camera`, :mod:`.imu` (the sensors), :mod:`.messages` (sensor_msgs),
and one module per ROS plugin family.
"""

from __future__ import annotations

from typing import Any

from workbench.errors import SimulationError
from workbench.sim.sensors.camera import Camera, CameraFrame
from workbench.sim.sensors.imu import Imu, ImuReading
from workbench.sim.sensors.lidar import Lidar
from workbench.sim.sensors.spec import (
    CameraSpec,
    ImuSpec,
    LaserSpec,
    NoiseSpec,
    ScanAxis,
    SensorSpec,
    parse_sensor,
)

__all__ = [
    "Camera",
    "CameraFrame",
    "CameraSpec",
    "Imu",
    "ImuReading",
    "ImuSpec",
    "LaserSpec",
    "Lidar",
    "NoiseSpec",
    "ScanAxis",
    "SensorSpec",
    "model_sensors",
    "parse_sensor",
    "sensor_plugin",
]


def model_sensors(model: Any) -> list[SensorSpec]:
    """The specs of a SimModel's sensors (raises on the first bad one)."""
    return [parse_sensor(xml, model=model.name, link=link) for link, xml in model.sensors]


def sensor_plugin(server: Any, sensor: str, model: str | None = None) -> Any:
    """The running ROS plugin of the sensor named ``sensor`` (in ``model``, if given).

    Raises:
        SimulationError: No such sensor plugin runs, or the name is ambiguous.
    """
    from workbench.sim.sensors.base import RosSensorPlugin

    found = [
        plugin
        for plugin in server.plugins
        if isinstance(plugin, RosSensorPlugin)
        and plugin.spec.name == sensor
        and (model is None or plugin.model.name == model)
    ]
    if len(found) != 1:
        running = sorted(
            f"{p.model.name}/{p.spec.name}"
            for p in server.plugins
            if isinstance(p, RosSensorPlugin)
        )
        problem = "no" if not found else "more than one"
        raise SimulationError(
            f"{problem} sensor plugin for sensor '{sensor}'",
            hint="running: " + (", ".join(running) or "none") + "; pass model=...",
        )
    return found[0]
