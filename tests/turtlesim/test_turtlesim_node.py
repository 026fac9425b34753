"""The turtlesim node on an in-process bus: its names, services, parameters and errors.

Matched to ROS Noetic's turtlesim_node (turtle_frame.cpp, turtle.cpp): global
services clear/reset/spawn/kill; per-turtle cmd_vel, pose, color_sensor,
set_pen, teleport_absolute, teleport_relative; private background_r/g/b
parameters set only when absent (``if (!private_nh_.hasParam(...))``) and
re-read by clear; spawn with an empty name answers turtleN; spawning a taken
name and killing a missing turtle fail with the original's error lines.
"""

from __future__ import annotations

import pytest

from workbench.bus import Bus, Node, ServiceError
from workbench.msgs.geometry_msgs import Twist, Vector3
from workbench.msgs.std_srvs import Empty, Trigger
from workbench.msgs.turtlesim import Color, Kill, Pose, SetPen, Spawn, TeleportAbsolute
from workbench.turtlesim.node import TurtlesimNode


@pytest.fixture
def world():
    bus = Bus(threaded=False)
    node = Node("turtlesim", bus=bus, disable_rosout=True)
    sim = TurtlesimNode(node, start_timer=False)
    user = Node("user", bus=bus, disable_rosout=True)
    yield bus, sim, user
    bus.shutdown()


def _drain(bus):
    while bus.spin_once(0.0):
        pass


def test_graph_names_and_types(world):
    bus, _, _ = world
    graph = bus.graph()
    node = graph.nodes["/turtlesim"]
    assert sorted(node.publications) == ["/turtle1/color_sensor", "/turtle1/pose"]
    assert node.subscriptions == ["/turtle1/cmd_vel"]
    assert {"/clear", "/kill", "/reset", "/spawn", "/turtle1/set_pen"} <= set(node.services)
    assert graph.topics["/turtle1/pose"].type == "turtlesim/Pose"
    assert graph.topics["/turtle1/color_sensor"].type == "turtlesim/Color"
    assert graph.topics["/turtle1/cmd_vel"].type == "geometry_msgs/Twist"
    assert graph.services["/clear"].type == "std_srvs/Empty"
    assert graph.services["/spawn"].type == "turtlesim/Spawn"
    assert bus.params.get("/turtlesim/background_b") == 255


def test_cmd_vel_moves_and_pose_is_published(world):
    bus, sim, user = world
    poses, colours = [], []
    user.create_subscription("/turtle1/pose", Pose, poses.append)
    user.create_subscription("/turtle1/color_sensor", Color, colours.append)
    user.create_publisher("/turtle1/cmd_vel", Twist).publish(
        Twist(linear=Vector3(x=2.0), angular=Vector3(z=1.8))
    )
    _drain(bus)
    for _ in range(10):
        sim.step()
    _drain(bus)
    assert len(poses) == 10 and len(colours) == 10
    assert poses[-1].linear_velocity == pytest.approx(2.0)
    assert poses[-1].theta == pytest.approx(1.8 * 0.16, abs=1e-5)
    assert poses[-1].x > 5.6


def test_spawn_kill_and_their_errors(world):
    bus, sim, user = world
    spawn = user.create_client("/spawn", Spawn)
    assert spawn.call(Spawn.Request(x=2, y=2, theta=0.2, name="")).name == "turtle2"
    assert "/turtle2/pose" in bus.graph().topics
    with pytest.raises(ServiceError, match="already exists"):
        spawn.call(Spawn.Request(x=1, y=1, theta=0, name="turtle2"))
    kill = user.create_client("/kill", Kill)
    kill.call(Kill.Request(name="turtle2"))
    assert "turtle2" not in sim.sim.turtles
    assert "/turtle2/pose" not in bus.graph().topics
    with pytest.raises(ServiceError, match="no turtle named 'turtle2'"):
        kill.call(Kill.Request(name="turtle2"))


def test_background_parameter_then_clear(world):
    bus, sim, user = world
    user.set_param("/turtlesim/background_r", 150)
    assert sim.sim.path_image.getpixel((5, 5)) == (0x45, 0x56, 0xFF)
    user.create_client("/clear", Empty).call(Empty.Request())
    assert sim.sim.path_image.getpixel((5, 5)) == (150, 0x56, 0xFF)


def test_existing_background_parameters_are_kept():
    bus = Bus(threaded=False)
    bus.params.set("/turtlesim/background_g", 0)
    sim = TurtlesimNode(Node("turtlesim", bus=bus, disable_rosout=True), start_timer=False)
    assert sim.sim.background == (0x45, 0, 0xFF)
    bus.shutdown()


def test_pen_teleport_reset_and_snapshot(world, tmp_path):
    bus, sim, user = world
    user.create_client("/turtle1/set_pen", SetPen).call(
        SetPen.Request(r=255, g=0, b=255, width=3, off=0)
    )
    user.create_client("/turtle1/teleport_absolute", TeleportAbsolute).call(
        TeleportAbsolute.Request(x=1, y=1, theta=0)
    )
    sim.step()
    pose = sim.sim.turtle("turtle1").pose
    assert (pose.x, pose.y) == pytest.approx((1.0, 1.0))
    user.create_client("/spawn", Spawn).call(Spawn.Request(x=3, y=3, theta=0, name="t2"))
    user.create_client("/reset", Empty).call(Empty.Request())
    assert list(sim.sim.turtles) == ["turtle1"]
    assert "/t2/pose" not in bus.graph().topics
    response = user.create_client("/turtlesim/save_png", Trigger).call(Trigger.Request())
    assert not response.success
    path = sim.save_png(tmp_path / "canvas.png")
    assert path.read_bytes()[:4] == b"\x89PNG"
