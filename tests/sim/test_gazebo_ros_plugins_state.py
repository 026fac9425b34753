"""``libgazebo_ros_joint_state_publisher.so``, ``libgazebo_ros_planar_move.so`` and the
namespace rules of Gazebo's ROS plugins.

Matched against gazebo_ros_pkgs noetic-devel: ``gazebo_ros_joint_state_publisher.cpp``
(``jointName`` split on commas with spaces removed, ``updateRate`` 100, names,
positions and velocities on ``joint_states``, namespace defaulting to the model's
name), ``gazebo_ros_planar_move.cpp`` (velocity set from ``linear.x/y`` turned by
the yaw and ``angular.z`` before every step, ``odometryRate`` 20, empty default
namespace, ``cmdTimeout``), ``gazebo_ros_utils.h`` (``GazeboRos``: namespace =
``robotNamespace`` or the model's name) and gazebo_ros_api_plugin.cpp
(``walkChildAddRobotNamespace``: a spawn request's ``robot_namespace`` goes into
every plugin that has none).
"""

from __future__ import annotations

import logging
import math
import time

import numpy as np
import pytest
from drive_helpers import Rig, custom_bot, with_params
from sim_helpers import box_model

from workbench.bus import Bus, Node
from workbench.msgs import gazebo_msgs as gm
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.gazebo_ros_plugins.ros_context import global_namespace, resolve_frame
from workbench.sim.model_spec import PluginSpec
from workbench.sim.server import SERVER_PHYSICS, SimServer

JSP = "libgazebo_ros_joint_state_publisher.so"


def test_joint_state_publisher_publishes_exactly_the_listed_joints():
    rig = Rig(custom_bot())
    try:
        states = rig.record("/joint_states", "sensor_msgs/JointState")
        rig.run(0.5)
        mine = [(t, m) for t, m in states if "front_wheel_joint" in m.name]
        assert {tuple(m.name) for _, m in mine} == {
            ("front_caster_of_wheel_joint", "front_wheel_joint")  # as listed, spaces dropped
        }
        assert len(mine) == pytest.approx(50, abs=1)  # <updateRate> default 100 Hz
        stamps = np.array([m.header.stamp.to_sec() for _, m in mine])
        assert np.allclose(np.diff(stamps), 0.01, atol=1e-6)
        assert all(m.header.stamp.to_sec() == pytest.approx(t, abs=1e-9) for t, m in mine)
        t, last = mine[-1]
        model = rig.plugin("GazeboRosJointStatePublisher").model
        assert list(last.position) == pytest.approx(
            [model.joint_position(j) for j in last.name], abs=1e-3
        )
        assert len(last.velocity) == 2 and len(last.effort) == 0
    finally:
        rig.close()


def test_joint_state_publisher_rate_and_a_missing_joint(caplog):
    model = with_params(custom_bot(), JSP, jointName="front_wheel_joint,no_such,left_wheel_joint")
    model = with_params(model, JSP, updateRate="20")
    with caplog.at_level(logging.WARNING):
        rig = Rig(model)
    try:
        errors = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
        assert len(errors) == 1 and "'custom_bot'" in errors[0] and "'no_such'" in errors[0]
        states = rig.record("/joint_states", "sensor_msgs/JointState")
        rig.run(1.0)
        mine = [m for _, m in states if "front_wheel_joint" in m.name]
        assert len(mine) == pytest.approx(20, abs=1)
        assert mine[-1].name == ["front_wheel_joint", "left_wheel_joint"]
    finally:
        rig.close()


def planar_box(**params: str) -> object:
    body = "".join(f"<{k}>{v}</{k}>" for k, v in params.items())
    spec = PluginSpec(
        name="object_controller",
        filename="libgazebo_ros_planar_move.so",
        element=f'<plugin name="object_controller" filename="libgazebo_ros_planar_move.so">'
        f"{body}</plugin>",
        kind="model",
        source="test",
    )
    return box_model("crate", size=(0.4, 0.3, 0.2), mass=20.0, plugins=[spec])


def test_planar_move_moves_a_box_kinematically_with_the_commanded_velocities():
    rig = Rig(planar_box(), z=0.1)
    try:
        odom = rig.record("/odom", "nav_msgs/Odometry")
        tf = rig.record("/tf", "tf2_msgs/TFMessage")
        rig.run(0.2)
        x0, y0, yaw0 = rig.pose()
        v, u, w, T = 0.4, 0.1, 0.5, 2.0  # forward, sideways (body frame), turn, duration
        rig.command(v, w, sideways=u)
        rig.run(T)
        x, y, yaw = rig.pose()
        # set before every step; friction slows it only within a step (mu g dt = 0.01 m/s)
        assert yaw - yaw0 == pytest.approx(w * T, rel=0.03)
        # body-frame velocity (v, u) at a constant turn rate, integrated exactly
        dx = (v * (math.sin(w * T)) - u * (1 - math.cos(w * T))) / w
        dy = (v * (1 - math.cos(w * T)) + u * math.sin(w * T)) / w
        assert math.hypot(x - x0 - dx, y - y0 - dy) < 0.03 * math.hypot(v, u) * T
        # odometry: the true pose at <odometryRate> 20 Hz, twist in the base frame
        stamps = np.array([m.header.stamp.to_sec() for _, m in odom])
        assert len(stamps) == pytest.approx(2.2 / 0.051, abs=3)  # strictly more than 1/20 s apart
        assert np.all(np.diff(stamps) > 0.05 - 1e-6)
        t, last = odom[-1]
        assert (last.header.frame_id, last.child_frame_id) == ("odom", "base_footprint")
        assert last.twist.twist.linear.x == pytest.approx(v, abs=0.012)  # mu g dt again
        assert last.twist.twist.linear.y == pytest.approx(u, abs=0.012)
        assert last.twist.twist.angular.z == pytest.approx(w, rel=0.03)
        assert any(
            x.child_frame_id == "base_footprint" and x.header.stamp == last.header.stamp
            for _, m in tf
            for x in m.transforms
        )
        rig.command(0.0)
        rig.run(0.2)
        before = rig.pose()
        rig.run(0.5)
        assert rig.pose() == pytest.approx(before, abs=1e-3)
    finally:
        rig.close()


def test_planar_move_stops_after_cmd_timeout_and_can_skip_the_transform():
    rig = Rig(planar_box(cmdTimeout="0.3", publishOdometryTf="false"), z=0.1)
    try:
        tf = rig.record("/tf", "tf2_msgs/TFMessage")
        rig.command(0.5)
        rig.run(1.0)
        x = rig.pose()[0]
        assert x == pytest.approx(0.5 * 0.3, abs=0.03)  # moved only until the timeout
        assert tf == []
    finally:
        rig.close()


def test_a_drive_without_robot_namespace_listens_under_the_model_name():
    """GazeboRos: no <robotNamespace> -> the model's name (world-file models)."""
    model = custom_bot(namespace="")
    rig = Rig(model)
    try:
        odom = rig.record("/custom_bot/odom", "nav_msgs/Odometry")
        x0 = rig.pose()[0]
        rig.command(0.5)  # /cmd_vel: nobody listens
        rig.run(0.5)
        assert abs(rig.pose()[0] - x0) < 0.01
        rig.command(0.5, topic="/custom_bot/cmd_vel")
        rig.run(0.5)
        assert rig.pose()[0] - x0 > 0.15
        assert odom and odom[-1][1].child_frame_id == "base_link"
    finally:
        rig.close()


def test_tf_prefix_and_global_frames_resolve_as_tf():
    assert resolve_frame("", "odom") == "odom"
    assert resolve_frame("robot1", "odom") == "robot1/odom"
    assert resolve_frame("/robot1", "odom") == "robot1/odom"
    assert resolve_frame("robot1", "/odom") == "odom"
    assert global_namespace("/") == "/" and global_namespace("//") == "/"
    assert global_namespace("bot") == "/bot" and global_namespace("/a//b/") == "/a/b"
    rig = Rig(custom_bot(namespace="/robot1"))
    try:
        rig.bus.params.set("/robot1/tf_prefix", "robot1")
        rig.server.delete("custom_bot")
        rig.server.spawn(custom_bot(namespace="/robot1"), [0.0, 0.0, 0.1])
        odom = rig.record("/robot1/odom", "nav_msgs/Odometry")
        rig.run(0.05)
        assert (odom[-1][1].header.frame_id, odom[-1][1].child_frame_id) == (
            "robot1/odom",
            "robot1/base_link",
        )
    finally:
        rig.close()


def test_spawn_service_gives_plugins_the_request_robot_namespace():
    """spawn_model sends its namespace ('/'): the spawned robot's drive is on /cmd_vel."""
    bus = Bus()
    server = SimServer(World(**SERVER_PHYSICS), bus=bus, real_time_factor=0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    client = Node("client", bus=bus)
    server.start()
    try:
        xml = (urdf_dir() / "custom_bot.urdf").read_text()
        request = gm.SpawnModel.Request(model_name="bot", model_xml=xml, robot_namespace="/")
        request.initial_pose.position.z = 0.1
        request.initial_pose.orientation.w = 1.0
        reply = client.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel).call(
            request, timeout=60
        )
        assert reply.success, reply.status_message
        odom: list = []
        client.create_subscription("/odom", "nav_msgs/Odometry", odom.append, inline=True)
        command = client.create_publisher("/cmd_vel", "geometry_msgs/Twist")
        message = command.data_class()
        message.linear.x = 0.5
        command.publish(message)
        x0 = server.call(lambda: server.world.get_model_pose("bot").translation()[0])
        t0 = server.call(lambda: server.world.time)
        deadline = time.monotonic() + 60
        while server.call(lambda: server.world.time) < t0 + 0.5 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert odom and odom[-1].child_frame_id == "base_link"
        x = server.call(lambda: server.world.get_model_pose("bot").translation()[0])
        assert x - x0 > 0.15
    finally:
        api.close()
        server.stop()
        bus.shutdown()
