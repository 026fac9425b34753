"""What the ROS sensor plugins share: their sensor, its pose, its seed, its rate."""

from __future__ import annotations

import zlib
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.listener_count import ListenerCount
from workbench.sim.plugins import PluginSetupError, SdfElement, SensorPlugin
from workbench.sim.sensors.spec import SensorSpec, parse_sensor


class RosSensorPlugin(SensorPlugin):
    """A Gazebo ROS sensor plugin: reads its ``<sensor>``, updates at the sensor's rate.

    Subclasses set ``sensor_types`` and implement :meth:`setup` and ``update``.
    After ``load``: ``spec`` (the parsed sensor), ``model`` (the ModelHandle),
    ``node`` (the bus node, or None without a bus), ``seed``.
    """

    sensor_types: tuple[str, ...] = ()
    label = "sensor"

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        if sdf.sensor is None:
            raise PluginSetupError(
                f"{self.label} plugin '{sdf.name}' must be inside a <sensor> of type "
                + " or ".join(self.sensor_types)
            )
        link = sdf.reference or ""
        try:
            spec = parse_sensor(sdf.sensor, model=model.name, link=link)
        except SimulationError as error:
            raise PluginSetupError(error.message) from None
        if spec.type not in self.sensor_types:
            raise PluginSetupError(
                f"model '{model.name}', link '{link}', sensor '{spec.name}': {self.label} plugin "
                f"'{sdf.name}' needs a sensor of type {' or '.join(self.sensor_types)}, "
                f"not '{spec.type}'"
            )
        self.spec: SensorSpec = spec
        self.model = model
        self.node = node
        self.sdf = sdf
        self.seed = zlib.crc32(f"{model.name}::{link}::{spec.name}".encode())
        self.update_rate = spec.update_rate
        #: Subscribers of a publisher's topic, looked up at most 5 times a wall second.
        self.listeners = ListenerCount()
        self.setup(sdf)

    def setup(self, sdf: SdfElement) -> None:
        """Read the plugin's parameters and advertise its topics."""

    @property
    def world(self) -> Any:
        """The World the sensor is in."""
        return self.model.server.world

    def sensor_pose(self) -> tuple[Any, Any]:
        """``(X_WS, body)``: the sensor frame in W now, and the plant body of its link."""
        world = self.world
        body = world.body(f"{self.model.name}::{self.spec.link}")
        plant = world.plant
        X_WL = plant.EvalBodyPoseInWorld(plant.GetMyContextFromRoot(world.context), body)
        return X_WL.multiply(self.spec.pose()), body


def parameter(sdf: SdfElement, key: str, default: str) -> str:
    """A text parameter of the ``<plugin>`` (``default`` when absent or empty)."""
    value = sdf.get(key, default)
    return str(value).strip() if value is not None and str(value).strip() else default


def robot_namespace(sdf: SdfElement) -> str:
    """``<robotNamespace>`` (gazebo_plugins' GetRobotNamespace; empty when absent)."""
    return parameter(sdf, "robotNamespace", "")
