"""A lab robot (urdf/custom_bot.urdf) on flat ground in a SimServer with an in-process bus."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from lxml import etree

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist
from workbench.sim import World
from workbench.sim.gazebo_ros_plugins.robot_namespace import with_robot_namespace
from workbench.sim.loading import load_sim_model
from workbench.sim.model_spec import SimModel
from workbench.sim.server import SERVER_PHYSICS, SimServer

CUSTOM_BOT_DRIVE_JOINTS = ("left_wheel_joint", "right_wheel_joint")
RADIUS = 0.035  # custom_bot's <wheelDiameter> 0.07 / 2
SEPARATION = 0.25  # custom_bot's <wheelSeparation>


def with_params(model: SimModel, library: str, **params: str) -> SimModel:
    """``model`` with the plugin of ``library`` given (or re-given) ``<tag>value</tag>``."""
    plugins = []
    for spec in model.plugins:
        if spec.filename == library:
            element = etree.fromstring(spec.element.encode())
            for tag, value in params.items():
                child = element.find(tag)
                if child is None:
                    child = etree.SubElement(element, tag)
                child.text = value
            spec = dataclasses.replace(spec, element=etree.tostring(element, encoding="unicode"))
        plugins.append(spec)
    return dataclasses.replace(model, plugins=plugins)


def custom_bot(namespace: str = "/", **drive: str) -> SimModel:
    """custom_bot with its drive and joint state plugins (the laser's left out), spawned as
    spawn_model does (``robot_namespace`` ``/``), drive parameters overridden by ``drive``."""
    model = load_sim_model("custom_bot", name="custom_bot")
    model.plugins = [p for p in model.plugins if p.kind == "model"]
    return with_params(
        with_robot_namespace(model, namespace), "libgazebo_ros_diff_drive.so", **drive
    )


class Rig:
    """A server with one model, a command publisher and topic recorders (callbacks run inline,
    in the simulation's thread, so each message is seen at the simulated time it was sent)."""

    def __init__(self, model: SimModel, z: float = 0.1, **spawn: Any) -> None:
        self.bus = Bus()
        self.world = World(**SERVER_PHYSICS)
        self.server = SimServer(self.world, bus=self.bus, real_time_factor=0)
        self.server.spawn(model, [0.0, 0.0, z], **spawn)
        self.name = model.name
        self.node = Node("tester", bus=self.bus)
        self.publishers: dict[str, Any] = {}
        self.received: dict[str, list[tuple[float, Any]]] = {}

    def record(self, topic: str, kind: str) -> list[tuple[float, Any]]:
        """``(sim time when received, message)`` of every message on ``topic`` from now on."""
        log: list[tuple[float, Any]] = []
        self.received[topic] = log
        self.node.create_subscription(
            topic, kind, lambda m: log.append((self.world.time, m)), inline=True
        )
        return log

    def command(
        self, forward: float, turn: float = 0.0, sideways: float = 0.0, topic: str = "/cmd_vel"
    ) -> None:
        if topic not in self.publishers:
            self.publishers[topic] = self.node.create_publisher(topic, Twist)
        message = Twist()
        message.linear.x, message.linear.y, message.angular.z = forward, sideways, turn
        self.publishers[topic].publish(message)

    def run(self, seconds: float) -> None:
        self.server.run(until=self.world.time + seconds)

    def plugin(self, cls_name: str) -> Any:
        return next(p for p in self.server.plugins if type(p).__name__ == cls_name)

    def pose(self) -> tuple[float, float, float]:
        """``(x, y, yaw)`` of the model."""
        X = self.world.get_model_pose(self.name)
        return (X.translation()[0], X.translation()[1], X.rotation().ToRollPitchYaw().yaw_angle())

    def close(self) -> None:
        self.server.stop()
        self.bus.shutdown()


def yaw_of(q: Any) -> float:
    """Yaw of a geometry_msgs/Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
