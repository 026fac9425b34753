"""A running simulator with the Gazebo ROS API on an in-process bus, for hostile-request tests.

:func:`running_gazebo` starts one server (models ``box`` and ``spinner``) and yields a
:class:`Gazebo` that sends requests and checks that the simulation still steps.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from sim_helpers import box_model, spinner_model

from workbench.bus import Bus, Node
from workbench.msgs import gazebo_msgs as gm
from workbench.msgs import std_srvs
from workbench.sim import World
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.server import SERVER_PHYSICS, SimServer

#: The service types of ``/gazebo/<name>``.
SERVICES: dict[str, Any] = {
    "spawn_urdf_model": gm.SpawnModel,
    "spawn_sdf_model": gm.SpawnModel,
    "delete_model": gm.DeleteModel,
    "get_model_state": gm.GetModelState,
    "set_model_state": gm.SetModelState,
    "get_world_properties": gm.GetWorldProperties,
    "get_model_properties": gm.GetModelProperties,
    "set_model_configuration": gm.SetModelConfiguration,
    "apply_body_wrench": gm.ApplyBodyWrench,
    "apply_joint_effort": gm.ApplyJointEffort,
    "clear_body_wrenches": gm.BodyRequest,
    "clear_joint_forces": gm.JointRequest,
    "reset_world": std_srvs.Empty,
    "unpause_physics": std_srvs.Empty,
}

#: Seconds a request or a check may take before the test calls it a hang.
PATIENCE = 60.0


@dataclass
class Gazebo:
    server: SimServer
    client: Any

    def call(self, service: str, request: Any) -> Any:
        """Send ``request`` to ``/gazebo/<service>`` and return the reply."""
        kind = SERVICES[service]
        return self.client.create_client(f"/gazebo/{service}", kind).call(request, timeout=PATIENCE)

    def sim_time(self) -> float:
        reply = self.call("get_world_properties", gm.GetWorldProperties.Request())
        assert reply.success, reply.status_message
        return float(reply.sim_time)

    def model_names(self) -> list[str]:
        reply = self.call("get_world_properties", gm.GetWorldProperties.Request())
        return list(reply.model_names)

    def clean_up(self) -> None:
        """Wrenches and efforts off, models back where they were spawned, physics running."""
        self.call("clear_body_wrenches", gm.BodyRequest.Request(body_name="box::body"))
        self.call("clear_body_wrenches", gm.BodyRequest.Request(body_name="spinner::base"))
        self.call("clear_joint_forces", gm.JointRequest.Request(joint_name="spin"))
        self.call("reset_world", std_srvs.Empty.Request())
        self.call("unpause_physics", std_srvs.Empty.Request())

    def assert_steps(self, what: str, seconds: float = 0.05) -> None:
        """The simulated time advances ``seconds`` and get_world_properties answers."""
        start = self.sim_time()
        deadline = time.monotonic() + PATIENCE
        while self.sim_time() < start + seconds:
            assert self.server.error is None, f"after {what}: {self.server.error}"
            assert time.monotonic() < deadline, f"after {what}: the simulation stopped stepping"
            time.sleep(0.01)


@contextlib.contextmanager
def running_gazebo() -> Iterator[Gazebo]:
    """A server with ``box`` (resting at the origin) and ``spinner`` (at x = 1 m), stepping."""
    bus = Bus()
    world = World(**SERVER_PHYSICS)
    server = SimServer(world, bus=bus, real_time_factor=1.0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    client = Node("client", bus=bus)
    server.start()
    try:
        gazebo = Gazebo(server, client)
        for model, x in (
            (box_model("box", size=0.2, mass=1.0), 0.0),
            (spinner_model("spinner"), 1.0),
        ):
            request = gm.SpawnModel.Request(model_name=model.name, model_xml=model.text)
            request.initial_pose.position.x = x
            request.initial_pose.position.z = 0.1 if model.name == "box" else 0.0
            request.initial_pose.orientation.w = 1.0
            reply = gazebo.call("spawn_urdf_model", request)
            assert reply.success, reply.status_message
        yield gazebo
    finally:
        api.close()
        server.stop()
        bus.shutdown()
