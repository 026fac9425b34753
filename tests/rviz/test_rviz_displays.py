"""The displays on a real bus: markers in the fixed frame through tf, scans, maps, clouds, paths."""

from __future__ import annotations

import struct
import time

import numpy as np
import pytest
from rviz_helpers import marker, recording_meshcat

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Point, PoseStamped, TransformStamped
from workbench.msgs.visualization_msgs import Marker, MarkerArray
from workbench.rviz import RViz
from workbench.tf import StaticTransformBroadcaster


@pytest.fixture
def scene():
    bus = Bus()
    meshcat = recording_meshcat()
    node = Node("publisher", bus=bus)
    static = StaticTransformBroadcaster(node)
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = "map", "base_link"
    t.transform.translation.x = 2.0
    t.transform.rotation.z, t.transform.rotation.w = np.sin(np.pi / 4), np.cos(np.pi / 4)  # 90 deg
    static.sendTransform(t)
    yield bus, node, meshcat
    bus.shutdown()


def _settle(rviz, display, count=1, seconds=10.0):
    deadline = time.monotonic() + seconds
    while display.received < count and time.monotonic() < deadline:
        time.sleep(0.01)
    rviz.update()


def test_every_marker_type_is_drawn_in_the_fixed_frame_through_tf(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["Marker"], meshcat=meshcat)
    display = rviz.displays[0]
    publisher = node.create_publisher("visualization_marker", Marker)
    for kind in range(11):
        m = marker(kind, kind, frame="base_link", mesh_resource="") if kind != 10 else None
        if m is None:
            continue
        m.pose.position.x = 1.0  # 1 m along base_link's x = +y in map
        publisher.publish(m)
    _settle(rviz, display, 10)
    for kind in (0, 1, 2, 3, 4, 5, 6, 7, 8, 9):
        path = f"/rviz/Marker/test/{kind}"
        assert meshcat.HasPath(path), path
        np.testing.assert_allclose(meshcat.transforms[path][:3, 3], [2.0, 1.0, 0.0], atol=1e-9)
    assert "shown as a dot" in display.status["test/9"]
    rviz.close()


def test_replace_delete_and_status_lines_reach_the_view(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["MarkerArray"], meshcat=meshcat)
    display = rviz.displays[0]
    publisher = node.create_publisher("visualization_marker_array", MarkerArray)
    nan = marker(Marker.CUBE, 5)
    nan.pose.position.z = float("nan")
    lost = marker(Marker.CUBE, 6, frame="nowhere")
    mesh = marker(Marker.MESH_RESOURCE, 7, mesh_resource="package://workbench_urdf/meshes/gone.stl")
    publisher.publish(
        MarkerArray(markers=[marker(Marker.CUBE, 1), marker(Marker.SPHERE, 2), nan, lost, mesh])
    )
    _settle(rviz, display)
    assert meshcat.HasPath("/rviz/MarkerArray/test/1") and meshcat.HasPath(
        "/rviz/MarkerArray/test/2"
    )
    assert not meshcat.HasPath("/rviz/MarkerArray/test/5")
    assert display.status["test/5"].startswith("Position contains invalid floating point values")
    assert display.status.get("test/7", "").startswith(
        "cannot load mesh package://workbench_urdf/meshes/gone.stl"
    ), display.status
    publisher.publish(MarkerArray(markers=[marker(Marker.CUBE, 1, action=Marker.DELETE)]))
    _settle(rviz, display, 2)
    assert not meshcat.HasPath("/rviz/MarkerArray/test/1")
    time.sleep(1.1)  # a frame tf never knows: RViz's status after the filter gives up
    rviz.update()
    assert display.status["test/6"].startswith("No transform from [nowhere] to fixed frame [map]")
    publisher.publish(MarkerArray(markers=[marker(Marker.CUBE, 0, action=Marker.DELETEALL)]))
    _settle(rviz, display, 3)
    assert not meshcat.HasPath("/rviz/MarkerArray/test/2")
    rviz.close()


def test_a_million_points_are_drawn_decimated_with_a_warning(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["Marker"], meshcat=meshcat)
    m = marker(Marker.POINTS, 1)
    m.points = [Point(x=float(i % 1000), y=float(i // 1000), z=0.0) for i in range(1_000_000)]
    node.create_publisher("visualization_marker", Marker).publish(m)
    _settle(rviz, rviz.displays[0], seconds=60)
    assert "1000000 points drawn decimated (every 5th)" in rviz.displays[0].status["test/1"]
    rviz.close()


def test_laser_scan_map_cloud_path_and_pose_land_in_the_fixed_frame(scene):
    from workbench.msgs.nav_msgs import OccupancyGrid, Path
    from workbench.msgs.sensor_msgs import LaserScan, PointCloud2, PointField

    bus, node, meshcat = scene
    rviz = RViz(
        bus,
        fixed_frame="map",
        displays=["LaserScan", "Map", "PointCloud2", "Path", "Pose"],
        meshcat=meshcat,
    )
    scan = LaserScan(
        angle_min=-1.0, angle_max=1.0, angle_increment=0.5, range_min=0.1, range_max=10.0
    )
    scan.header.frame_id = "base_link"
    scan.ranges = [1.0, 2.0, float("inf"), 3.0, 0.05]
    node.create_publisher("scan", LaserScan).publish(scan)
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.info.width, grid.info.height, grid.info.resolution = 4, 3, 0.5
    grid.info.origin.position.x = -1.0
    grid.info.origin.orientation.w = 1.0
    grid.data = [0, 100, -1, 50] * 3
    node.create_publisher("map", OccupancyGrid).publish(grid)
    cloud = PointCloud2(height=1, width=2, point_step=16, row_step=32, is_dense=True)
    cloud.header.frame_id = "base_link"
    cloud.fields = [
        PointField(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")
    ]
    cloud.data = list(struct.pack("<4f4f", 1, 0, 0, 0, float("nan"), 0, 0, 0))
    node.create_publisher("points", PointCloud2).publish(cloud)
    path = Path()
    path.header.frame_id = "map"
    path.poses = [PoseStamped(), PoseStamped()]
    path.poses[1].pose.position.x = 1.0
    node.create_publisher("path", Path).publish(path)
    pose = PoseStamped()
    pose.header.frame_id = "base_link"
    pose.pose.orientation.w = 1.0
    node.create_publisher("pose", PoseStamped).publish(pose)
    deadline = time.monotonic() + 10
    while any(d.received < 1 for d in rviz.displays) and time.monotonic() < deadline:
        time.sleep(0.01)
    rviz.update()
    assert {d.name: d.drawn for d in rviz.displays} == {
        "LaserScan": 1, "Map": 1, "PointCloud2": 1, "Path": 1, "Pose": 1,
    }  # fmt: skip
    np.testing.assert_allclose(meshcat.transforms["/rviz/LaserScan"][:3, 3], [2.0, 0.0, 0.0])
    np.testing.assert_allclose(meshcat.transforms["/rviz/Map"][:3, 3], [-1.0, 0.0, 0.0])
    assert meshcat.objects["/rviz/LaserScan"].size() == 3  # inf and below range_min dropped
    assert meshcat.objects["/rviz/PointCloud2"].size() == 1  # the NaN point dropped
    rviz.close()


def test_robot_model_from_the_parameter_is_posed_by_tf(scene):
    bus, node, meshcat = scene
    from workbench.paths import urdf_dir

    rviz = RViz(bus, fixed_frame="map", displays=["RobotModel"], meshcat=meshcat)
    rviz.update()
    assert "Parameter [robot_description] does not exist" in rviz.displays[0].status["URDF"]
    node.set_param("robot_description", (urdf_dir() / "simple_box.urdf").read_text())
    rviz.update()
    assert (
        rviz.displays[0].status
        == {
            "my_box": '"my_box" passed to lookupTransform argument source_frame does not exist. '
            "(known frames: base_link, map)"
        }
        or "my_box" in rviz.displays[0].status
    )
    rviz.close()


def test_a_topic_of_another_type_and_an_unknown_display_are_reported(scene):
    from workbench.errors import ViewerError
    from workbench.msgs.std_msgs import String

    bus, node, meshcat = scene
    node.create_publisher("scan", String)
    rviz = RViz(bus, fixed_frame="map", displays=["LaserScan"], meshcat=meshcat)
    assert rviz.displays[0].status["Topic"].startswith("Error subscribing:")
    with pytest.raises(ViewerError, match="unknown display class 'Camera'"):
        rviz.add_display("Camera")
    rviz.close()


def test_tf_frames_and_their_parent_lines_are_drawn(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["TF"], meshcat=meshcat)
    deadline = time.monotonic() + 5
    while not meshcat.HasPath("/rviz/TF/arrows") and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.02)
    np.testing.assert_allclose(meshcat.transforms["/rviz/TF/frames/base_link"][:3, 3], [2.0, 0, 0])
    assert meshcat.HasPath("/rviz/TF/arrows")
    rviz.close()


def test_the_fixed_frame_defaults_to_map_else_the_tf_root(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, displays=[], meshcat=meshcat)
    deadline = time.monotonic() + 5
    while rviz.fixed_frame == "world" and time.monotonic() < deadline:
        time.sleep(0.01)
    assert rviz.fixed_frame == "map"
    rviz.close()


def test_an_rviz_config_gives_its_displays_and_the_robot_is_drawn_where_tf_says(scene):
    from types import SimpleNamespace

    from workbench.model import load_robot
    from workbench.msgs.sensor_msgs import JointState
    from workbench.paths import examples_dir, urdf_dir
    from workbench.robot_state.state_publisher import RobotStatePublisher
    from workbench.rviz.node import build

    bus, node, meshcat = scene
    node.set_param("robot_description", (urdf_dir() / "arm3.urdf").read_text())
    args = SimpleNamespace(
        display_config=str(examples_dir() / "rviz" / "lab.rviz"), fixed_frame=None, port=None
    )
    rviz = build(args, bus, meshcat)
    assert rviz.fixed_frame == "map"
    assert [d.name for d in rviz.displays] == [
        "Grid", "TF", "RobotModel", "LaserScan", "Map", "Marker", "MarkerArray",
        "InteractiveMarkers", "Path",
    ]  # fmt: skip
    assert (
        rviz.displays[3].topic == "/scan" and rviz.displays[8].topic == "/move_base/NavfnROS/plan"
    )
    robot = load_robot("arm3")
    publisher = RobotStatePublisher(robot, node=Node("robot_state_publisher", bus=bus))
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = "map", robot.root_link
    t.transform.translation.y = -3.0
    t.transform.rotation.w = 1.0
    StaticTransformBroadcaster(node).sendTransform(t)
    q = [0.3, -0.4, 0.5][: len(robot.joint_names)]
    joint_states = node.create_publisher("joint_states", JointState)
    deadline = time.monotonic() + 10
    drawn = rviz.displays[2]
    while time.monotonic() < deadline:
        joint_states.publish(JointState(name=robot.joint_names, position=q))
        rviz.update()
        if drawn.status == {} and drawn.drawn:
            break
        time.sleep(0.05)
    assert drawn.status == {}, drawn.status
    fk = robot.forward_kinematics(q)
    tip = robot.links[-1].name
    expected = fk[tip].translation() + np.array([0.0, -3.0, 0.0])
    drawn_at = [X[:3, 3] for path, X in meshcat.transforms.items() if path.endswith(f"/{tip}")]
    assert drawn_at, (tip, sorted(meshcat.transforms)[:12])
    np.testing.assert_allclose(drawn_at[-1], expected, atol=1e-6)
    del publisher
    rviz.close()


def test_scans_newer_than_tf_wait_silently_and_are_drawn_in_order_once_tf_catches_up(scene):
    """tf2's MessageFilter (RViz's LaserScan display) holds a message whose stamp tf has not
    reached yet, without an error status, and draws it when tf gets there."""
    from workbench.msgs import Time
    from workbench.msgs.sensor_msgs import LaserScan
    from workbench.tf import TransformBroadcaster

    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["LaserScan"], meshcat=meshcat)
    (display,) = rviz.displays
    display.draw_every = True
    moving = TransformBroadcaster(node)

    def odom(seconds: float, x: float) -> None:
        t = TransformStamped()
        t.header.stamp = Time(int(seconds), int(round(seconds % 1 * 1e9)))
        t.header.frame_id, t.child_frame_id = "map", "laser"
        t.transform.translation.x = x
        t.transform.rotation.w = 1.0
        moving.sendTransform(t)

    publisher = node.create_publisher("scan", LaserScan)

    def scan(seconds: float) -> None:
        message = LaserScan(angle_min=0.0, angle_max=0.0, angle_increment=0.1, range_max=5.0)
        message.header.frame_id = "laser"
        message.header.stamp = Time(int(seconds), int(round(seconds % 1 * 1e9)))
        message.ranges = [1.0]
        publisher.publish(message)

    odom(1.0, 0.0)
    odom(2.0, 1.0)
    scan(1.5)
    scan(2.5)  # newer than tf
    scan(2.7)
    _settle(rviz, display, count=3)
    assert display.drawn == 1 and display.status == {"Topic": "OK"}
    odom(3.0, 2.0)
    deadline = time.monotonic() + 10
    while display.drawn < 3 and time.monotonic() < deadline:
        time.sleep(0.01)
        rviz.update()
    assert display.drawn == 3 and display.status == {"Topic": "OK"}
    # the last one drawn is the newest: x = 1.7 m at 2.7 s
    np.testing.assert_allclose(meshcat.transforms["/rviz/LaserScan"][0, 3], 1.7, atol=1e-6)
    rviz.close()
