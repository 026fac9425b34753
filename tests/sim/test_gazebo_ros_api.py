"""The Gazebo ROS API of the server over the bus: Gazebo's services, topics and status messages.

The status strings are gazebo_ros_api_plugin.cpp's (gazebo_ros_pkgs, Noetic).
"""

from __future__ import annotations

import re
import time

import numpy as np
import pytest

from workbench.bus import Bus, Node
from workbench.msgs import gazebo_msgs as gm
from workbench.msgs import std_srvs
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.server import SERVER_PHYSICS, SimServer

BOX = """<robot name="box"><link name="body">
  <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  <visual><geometry><box size="0.2 0.2 0.2"/></geometry></visual></link></robot>"""


@pytest.fixture
def gazebo():
    bus = Bus()
    world = World(**SERVER_PHYSICS)
    server = SimServer(world, bus=bus, real_time_factor=0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    client = Node("client", bus=bus)
    server.start()
    yield server, client, bus
    api.close()
    server.stop()
    bus.shutdown()


def call(client, name, kind, **fields):
    return client.create_client(f"/gazebo/{name}", kind).call(kind.Request(**fields), timeout=30)


def spawn(client, name, xml=BOX, z=1.0, service="spawn_urdf_model", **extra):
    request = gm.SpawnModel.Request(model_name=name, model_xml=xml, **extra)
    request.initial_pose.position.z = z
    request.initial_pose.orientation.w = 1.0
    return client.create_client(f"/gazebo/{service}", gm.SpawnModel).call(request, timeout=30)


def wait_until(server, t):
    deadline = time.monotonic() + 60
    while server.call(lambda: server.world.time) < t and time.monotonic() < deadline:
        time.sleep(0.01)


def test_spawn_fall_rest_and_report_the_state(gazebo):
    server, client, _ = gazebo
    reply = spawn(client, "my_object", (urdf_dir() / "simple_box.urdf").read_text())
    assert (reply.success, reply.status_message) == (
        True,
        "SpawnModel: Successfully spawned entity",
    )
    wait_until(server, server.world.time + 2.0)
    state = call(client, "get_model_state", gm.GetModelState, model_name="my_object")
    assert state.success and state.status_message == "GetModelState: got properties"
    # simple_box's link frame is at the bottom of its 2 m box: it rests at z = 0
    assert state.pose.position.z == pytest.approx(0.0, abs=3e-3)
    assert abs(state.twist.linear.z) < 1e-2
    world = call(client, "get_world_properties", gm.GetWorldProperties)
    assert world.model_names == ["ground_plane", "my_object"] and world.sim_time > 2.0


def test_a_name_in_use_gets_gazebos_refusal_and_nothing_changes(gazebo):
    server, client, _ = gazebo
    assert spawn(client, "box").success
    again = spawn(client, "box", z=3.0)
    assert (again.success, again.status_message) == (
        False,
        "SpawnModel: Failure - model already exists.",
    )
    wrong = spawn(client, "sdf_as_urdf", xml="<sdf version='1.6'><model name='m'/></sdf>")
    assert (wrong.success, wrong.status_message) == (
        False,
        "SpawnModel: Failure - model format is not URDF.",
    )
    assert call(client, "get_world_properties", gm.GetWorldProperties).model_names == [
        "ground_plane",
        "box",
    ]


def test_bad_spawn_requests_fail_with_a_status_and_the_server_keeps_running(gazebo):
    server, client, _ = gazebo
    nan = spawn(client, "nan_box", z=float("nan"))
    assert not nan.success and "not finite" in nan.status_message
    empty = spawn(client, "no_links", xml='<robot name="empty"></robot>')
    assert not empty.success and "SpawnModel: Failure" in empty.status_message
    garbage = spawn(client, "junk", xml="definitely not a model", service="spawn_sdf_model")
    assert not garbage.success and "neither URDF" in garbage.status_message
    t = server.call(lambda: server.world.time)
    wait_until(server, t + 0.1)
    assert server.call(lambda: server.world.time) >= t + 0.1


def test_unknown_models_get_gazebos_does_not_exist(gazebo):
    _, client, _ = gazebo
    get = call(client, "get_model_state", gm.GetModelState, model_name="ghost")
    assert (get.success, get.status_message) == (False, "GetModelState: model does not exist")
    delete = call(client, "delete_model", gm.DeleteModel, model_name="ghost")
    assert (delete.success, delete.status_message) == (False, "DeleteModel: model does not exist")
    state = gm.ModelState(model_name="ghost")
    state.pose.orientation.w = 1.0
    put = call(client, "set_model_state", gm.SetModelState, model_state=state)
    assert (put.success, put.status_message) == (False, "SetModelState: model does not exist")
    props = call(client, "get_model_properties", gm.GetModelProperties, model_name="ghost")
    assert props.status_message == "GetModelProperties: model does not exist"


def test_set_state_then_delete_and_properties(gazebo):
    server, client, _ = gazebo
    spawn(client, "box", z=0.1)
    state = gm.ModelState(model_name="box")
    state.pose.position.x, state.pose.position.z = 2.0, 3.0
    state.pose.orientation.w = 1.0
    state.twist.angular.z = 1.5
    reply = call(client, "set_model_state", gm.SetModelState, model_state=state)
    assert (reply.success, reply.status_message) == (True, "SetModelState: set model state done")
    got = call(client, "get_model_state", gm.GetModelState, model_name="box")
    assert got.pose.position.x == pytest.approx(2.0, abs=1e-6)
    assert got.twist.angular.z == pytest.approx(1.5, abs=0.05)
    props = call(client, "get_model_properties", gm.GetModelProperties, model_name="box")
    assert props.success and props.body_names == ["body"] and not props.is_static
    assert props.canonical_body_name == "body"
    deleted = call(client, "delete_model", gm.DeleteModel, model_name="box")
    assert (deleted.success, deleted.status_message) == (
        True,
        "DeleteModel: successfully deleted model",
    )
    assert call(client, "get_world_properties", gm.GetWorldProperties).model_names == [
        "ground_plane"
    ]


def test_spawn_and_delete_while_running_keep_the_other_models_moving(gazebo):
    server, client, _ = gazebo
    spawn(client, "slider", z=0.1)
    state = gm.ModelState(model_name="slider")
    state.pose.position.z = 0.1
    state.pose.orientation.w = 1.0
    state.twist.linear.x = 1.0
    server.paused = True
    call(client, "set_model_state", gm.SetModelState, model_state=state)
    before = server.call(
        lambda: (
            server.world.get_model_pose("slider").translation().copy(),
            server.world.get_model_twist("slider"),
        )
    )
    rebuilds = server.world.rebuilds
    assert spawn(client, "newcomer", z=2.0).success
    assert call(client, "delete_model", gm.DeleteModel, model_name="newcomer").success
    after = server.call(
        lambda: (
            server.world.get_model_pose("slider").translation().copy(),
            server.world.get_model_twist("slider"),
        )
    )
    np.testing.assert_array_equal(before[0], after[0])
    np.testing.assert_array_equal(before[1][0], after[1][0])
    assert server.world.rebuilds == rebuilds + 2


def test_pause_unpause_and_reset(gazebo):
    server, client, _ = gazebo
    spawn(client, "box", z=1.0)
    call(client, "pause_physics", std_srvs.Empty)
    t = server.call(lambda: server.world.time)
    time.sleep(0.2)
    assert server.call(lambda: server.world.time) == t
    call(client, "unpause_physics", std_srvs.Empty)
    wait_until(server, t + 0.5)
    call(client, "pause_physics", std_srvs.Empty)  # so the box cannot fall again before we look
    call(client, "reset_world", std_srvs.Empty)
    z = server.call(lambda: server.world.get_model_pose("box").translation()[2])
    assert z == pytest.approx(1.0, abs=1e-6)  # back at the spawn pose
    assert server.call(lambda: server.world.time) > t  # reset_world keeps the clock
    call(client, "reset_simulation", std_srvs.Empty)
    assert server.call(lambda: server.world.time) == 0.0


def test_wrenches_and_efforts_for_a_while(gazebo):
    server, client, _ = gazebo
    # velodyne.urdf without its velocity controller plugin (which would hold the top at 0)
    spinner = re.sub(
        r"<gazebo>\s*<plugin.*?</gazebo>",
        "",
        (urdf_dir() / "velodyne.urdf").read_text(),
        flags=re.S,
    )
    assert "velocity_controller" not in spinner
    assert spawn(client, "spinner", xml=spinner, z=0.0).success
    assert spawn(client, "box", z=0.1).success
    server.paused = True
    request = gm.ApplyBodyWrench.Request(body_name="box::body")
    request.wrench.force.z = 2.0 * 9.81  # twice its weight, for 0.3 s
    request.duration.sec, request.duration.nanosec = 0, 300_000_000
    assert call(
        client,
        "apply_body_wrench",
        gm.ApplyBodyWrench,
        **{f: getattr(request, f) for f in ("body_name", "wrench", "duration")},
    ).success
    forever = gm.ApplyJointEffort.Request().duration
    forever.sec = -1  # a negative duration: until cleared, as in Gazebo
    effort = call(
        client,
        "apply_joint_effort",
        gm.ApplyJointEffort,
        joint_name="top_joint",
        effort=0.001,
        duration=forever,
    )
    assert (effort.success, effort.status_message) == (True, "ApplyJointEffort: effort set")
    missing = call(client, "apply_joint_effort", gm.ApplyJointEffort, joint_name="nope", effort=1.0)
    assert (missing.success, missing.status_message) == (False, "ApplyJointEffort: joint not found")
    start = server.call(lambda: server.world.time)
    server.paused = False
    server.wake()
    wait_until(server, start + 0.3)
    server.paused = True
    z = server.call(lambda: server.world.get_model_pose("box").translation()[2])
    assert z > 0.1 + 0.5 * 9.81 * 0.3**2 * 0.8  # pushed up at g for 0.3 s
    spin = server.call(
        lambda: server.world.plant.GetVelocities(
            server.world.plant.GetMyContextFromRoot(server.world.context)
        )[server.world.joint("spinner", "top_joint").velocity_start()]
    )
    assert spin > 1.0  # 0.001 N m on 9.1e-5 kg m^2: ~11 rad/s^2


def test_model_states_reach_a_subscriber(gazebo):
    server, client, _ = gazebo
    spawn(client, "box", z=1.0)
    received = []
    client.create_subscription("/gazebo/model_states", gm.ModelStates, received.append)
    deadline = time.monotonic() + 30
    while not received and time.monotonic() < deadline:
        time.sleep(0.02)
    assert received and received[-1].name == ["ground_plane", "box"]
    assert received[-1].pose[1].orientation.w == pytest.approx(1.0, abs=0.1)
