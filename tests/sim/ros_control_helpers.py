"""A two-link arm with ros_control in a running SimServer, as ur_gazebo's launch files set it up.

tests/data/ros_control/two_link_arm.urdf has effort transmissions and the
gazebo_ros_control block; controllers.yaml is in the shape of ur5_controllers.yaml. The
rig puts the URDF on ``/robot_description``, the YAML at the top level (``<rosparam
command="load">``), spawns the model as spawn_model does (``robot_namespace`` ``/``) and
runs the server in the background as fast as it computes.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from workbench.bus import Bus, Node
from workbench.limits import load_yaml_file
from workbench.sim import World
from workbench.sim.gazebo_ros_plugins.robot_namespace import with_robot_namespace
from workbench.sim.loading import sim_model_from_xml
from workbench.sim.ros_control.nodes import Spawner, _spawner_parser
from workbench.sim.server import SERVER_PHYSICS, SimServer

DATA = Path(__file__).resolve().parents[1] / "data" / "ros_control"
ARM = DATA / "two_link_arm.urdf"
CONTROLLERS = DATA / "controllers.yaml"
JOINTS = ["shoulder_joint", "elbow_joint"]
EFFORT = "hardware_interface/EffortJointInterface"


def arm_urdf(interface: str = EFFORT, plugin: str = "") -> str:
    """The arm's URDF with every transmission on ``interface`` and the plugin's parameters."""
    text = ARM.read_text(encoding="utf-8").replace(EFFORT, interface)
    return text.replace(
        '<plugin name="ros_control" filename="libgazebo_ros_control.so">',
        f'<plugin name="ros_control" filename="libgazebo_ros_control.so">{plugin}',
    )


def wait_for(predicate: Callable[[], Any], timeout: float = 60.0) -> Any:
    """Poll ``predicate`` until it is truthy (wall ``timeout`` s); its value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.005)
    raise AssertionError(f"condition not met within {timeout} s")


class ArmRig:
    """The arm spawned with ros_control, its parameters, a tester node."""

    def __init__(
        self,
        urdf: str | None = None,
        params: dict[str, Any] | None = None,
        description: bool = True,
        start: bool = True,
    ) -> None:
        self.bus = Bus()
        for key, value in load_yaml_file(CONTROLLERS, "controllers").items():
            self.bus.params.set("/" + key, value)
        for key, value in (params or {}).items():
            self.bus.params.set(key, value)
        text = urdf if urdf is not None else arm_urdf()
        if description:
            self.bus.params.set("/robot_description", text)
        self.world = World(**SERVER_PHYSICS)
        self.server = SimServer(self.world, bus=self.bus, real_time_factor=0)
        model = sim_model_from_xml(text, name="robot", source="two_link_arm.urdf")
        self.server.spawn(with_robot_namespace(model, "/"), [0.0, 0.0, 0.0])
        self.node = Node("tester", bus=self.bus)
        self.spawners: list[Spawner] = []
        if start:
            self.server.start()

    def spawn(self, *args: str) -> Spawner:
        """Run a spawner with ``args`` (its command line) and return it once it loaded and started."""
        spawner = Spawner(
            Node("spawner", bus=self.bus, anonymous=True), _spawner_parser().parse_args(list(args))
        )
        spawner.run(spin=False)
        self.spawners.append(spawner)
        return spawner

    def call(self, service: str, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        kinds = {
            "list_controllers": cm.ListControllers,
            "load_controller": cm.LoadController,
            "unload_controller": cm.UnloadController,
            "switch_controller": cm.SwitchController,
            "list_controller_types": cm.ListControllerTypes,
        }
        client = self.node.create_client(f"/controller_manager/{service}", kinds[service])
        client.wait_for_service(timeout=30)
        return client.call(request, timeout=30)

    def states(self) -> dict[str, str]:
        from workbench.msgs.controller_manager_msgs import ListControllers

        reply = self.call("list_controllers", ListControllers.Request())
        return {c.name: c.state for c in reply.controller}

    def positions(self) -> list[float]:
        plant = self.world.plant
        context = plant.GetMyContextFromRoot(self.world.context)
        return [
            float(plant.GetPositions(context)[plant.GetJointByName(j).position_start()])
            for j in JOINTS
        ]

    def record(self, topic: str, kind: str) -> list[Any]:
        log: list[Any] = []
        self.node.create_subscription(topic, kind, log.append, inline=True)
        return log

    def close(self) -> None:
        self.server.stop()
        self.bus.shutdown()
