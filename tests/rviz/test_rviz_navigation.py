"""RViz for navigation: the Map display's colour schemes, Polygon, Path and PoseArray as RViz
draws them, and the "2D Pose Estimate" / "2D Nav Goal" tools.

Palette values are read from RViz's src/rviz/default_plugin/map_display.cpp (noetic):
``makeMapPalette``, ``makeCostmapPalette``, ``makeRawPalette``; costmap_2d's
costmap_2d_publisher.cpp translates costs 0, 253, 254, 255 to 0, 99, 100, -1 and
1..252 to ``1 + 97 * (cost - 1) / 251``. The tools' messages follow RViz's
initial_pose_tool.cpp (covariance [0] = 0.5², [7] = 0.5², [35] = (pi/12)²) and
goal_tool.cpp; pose_array_display.cpp draws "Arrow (Flat)" as three lines per pose,
to the tip at 0.3 m and back to (0.75, +-0.2) * 0.3 m.
"""

from __future__ import annotations

import base64
import io
import json
import math
import time
from pathlib import Path as Path_

import numpy as np
import pytest
from rviz_helpers import click, recording_meshcat

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import (
    Point32,
    PolygonStamped,
    Pose,
    PoseArray,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
)
from workbench.msgs.nav_msgs import OccupancyGrid, Path
from workbench.rviz import RViz
from workbench.rviz.map_palette import PALETTES, colour_cells, shrink
from workbench.tf import StaticTransformBroadcaster

# (scheme, byte) -> RGBA, evaluated by hand from map_display.cpp's loops
RVIZ_VALUES = {
    ("map", 0): (255, 255, 255, 255),
    ("map", 50): (128, 128, 128, 255),  # 255 - (255 * 50) / 100 = 255 - 127
    ("map", 99): (3, 3, 3, 255),  # 255 - 25245 / 100 = 255 - 252
    ("map", 100): (0, 0, 0, 255),
    ("map", 101): (0, 255, 0, 255),  # illegal positive: green
    ("map", 127): (0, 255, 0, 255),
    ("map", 128): (255, 0, 0, 255),  # illegal negative: red ...
    ("map", 191): (255, 127, 0, 255),  # (255 * 63) / 126
    ("map", 254): (255, 255, 0, 255),  # ... to yellow
    ("map", 255): (0x70, 0x89, 0x86, 255),  # -1: unknown
    ("costmap", 0): (0, 0, 0, 0),  # free: transparent
    ("costmap", 1): (2, 0, 253, 255),  # (255 * 1) / 100 = 2
    ("costmap", 50): (127, 0, 128, 255),
    ("costmap", 98): (249, 0, 6, 255),
    ("costmap", 99): (0, 255, 255, 255),  # inscribed: cyan
    ("costmap", 100): (255, 0, 255, 255),  # lethal: purple
    ("costmap", 101): (0, 255, 0, 255),
    ("costmap", 200): (255, 145, 0, 255),  # (255 * 72) / 126
    ("costmap", 255): (0x70, 0x89, 0x86, 255),
    ("raw", 0): (0, 0, 0, 255),
    ("raw", 100): (100, 100, 100, 255),
    ("raw", 255): (255, 255, 255, 255),
}


def _translate(cost: int) -> int:
    """costmap_2d's cost -> OccupancyGrid value."""
    special = {0: 0, 253: 99, 254: 100, 255: -1}
    return special.get(cost, 1 + (97 * (cost - 1)) // 251)


@pytest.mark.parametrize(("key", "rgba"), sorted(RVIZ_VALUES.items()))
def test_palettes_match_rviz(key, rgba):
    scheme, byte = key
    assert tuple(int(v) for v in PALETTES[scheme][byte]) == rgba


def test_costmap_costs_take_rviz_colours_and_the_display_alpha():
    costs = np.array([[0, 1, 128, 252, 253, 254, 255]])
    cells = np.array([[_translate(c) for c in row] for row in costs], np.int8).view(np.uint8)
    rgba = colour_cells(cells, "costmap", 0.7)
    assert tuple(rgba[0, 0]) == (0, 0, 0, 0)  # free stays see-through
    assert tuple(rgba[0, 4]) == (0, 255, 255, 178)  # INSCRIBED 253 -> 99: cyan, 255 * 0.7
    assert tuple(rgba[0, 5]) == (255, 0, 255, 178)  # LETHAL 254 -> 100: purple
    assert tuple(rgba[0, 6]) == (0x70, 0x89, 0x86, 178)  # NO_INFORMATION 255 -> -1
    assert rgba[0, 1, 2] > rgba[0, 2, 2] > rgba[0, 3, 2]  # blue fades as the cost rises
    assert rgba[0, 1, 0] < rgba[0, 2, 0] < rgba[0, 3, 0]  # ... and red grows
    # the map scheme is opaque from RViz's 0.9998 and blends under it
    grey = np.array([[0, 100]], np.uint8)
    assert list(colour_cells(grey, "map", 1.0)[0, :, 3]) == [255, 255]
    assert list(colour_cells(grey, "map", 0.5)[0, :, 3]) == [128, 128]


def test_a_shrunk_map_keeps_walls_and_a_shrunk_costmap_its_highest_cost():
    cells = np.zeros((4, 4), np.uint8)
    cells[0, 1] = 100
    cells[3, 3] = 255  # unknown
    cells[2, 2] = 40
    assert shrink(cells, 2, "map").tolist() == [[100, 0], [0, 40]]
    assert shrink(cells, 2, "costmap").tolist() == [[100, 0], [0, 40]]
    cells[2, 2] = 0
    assert shrink(cells, 2, "map").tolist() == [[100, 0], [0, 255]]  # unknown over free


@pytest.fixture
def scene():
    bus = Bus()
    meshcat = recording_meshcat()
    node = Node("publisher", bus=bus)
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = "map", "base_link"
    t.transform.translation.x = 2.0
    t.transform.rotation.z, t.transform.rotation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)
    StaticTransformBroadcaster(node).sendTransform(t)
    yield bus, node, meshcat
    bus.shutdown()


def _wait_drawn(rviz, display, count=1, seconds=10.0):
    deadline = time.monotonic() + seconds
    while display.drawn < count and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.01)
    assert display.drawn >= count, display.status


def _texture(meshcat, path):
    """(alphaMode, RGBA image rows top first) of the glTF quad drawn at ``path``."""
    from PIL import Image

    document = json.loads(Path_(meshcat.objects[path].source().path()).read_text(encoding="utf-8"))
    uri = document["images"][0]["uri"].split(",", 1)[1]
    image = Image.open(io.BytesIO(base64.b64decode(uri))).convert("RGBA")
    return document["materials"][0]["alphaMode"], np.asarray(image)


def _grid(data, width, height, resolution=0.5, frame="map", x=-1.0, y=0.0):
    grid = OccupancyGrid()
    grid.header.frame_id = frame
    grid.info.width, grid.info.height, grid.info.resolution = width, height, resolution
    grid.info.origin.position.x, grid.info.origin.position.y = x, y
    grid.info.origin.orientation.w = 1.0
    grid.data = list(data)
    return grid


def test_map_and_costmap_displays_draw_rviz_colours(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=[], meshcat=meshcat)
    plain = rviz.add_display("Map", alpha=1.0)
    costs = rviz.add_display(
        "Map", topic="/move_base/global_costmap/costmap", color_scheme="costmap", alpha=0.7
    )
    assert (plain.layer, costs.layer) == (0, 1)
    node.create_publisher("map", OccupancyGrid, latch=True).publish(
        _grid([0, 100, -1, 50, 0, 0], 3, 2)
    )
    node.create_publisher("/move_base/global_costmap/costmap", OccupancyGrid).publish(
        _grid([0, 99, 100, -1, 1, 98], 3, 2)
    )
    _wait_drawn(rviz, plain)
    _wait_drawn(rviz, costs)
    mode, image = _texture(meshcat, "/rviz/Map/image")
    assert mode == "OPAQUE"
    # row 0 of the grid is the image's bottom row
    assert image[1].tolist() == [[255, 255, 255, 255], [0, 0, 0, 255], [112, 137, 134, 255]]
    assert image[0, 0].tolist() == [128, 128, 128, 255]
    mode, image = _texture(meshcat, "/rviz/Map_(2)/image")
    assert mode == "BLEND"
    assert image[1].tolist() == [[0, 0, 0, 0], [0, 255, 255, 178], [255, 0, 255, 178]]
    assert image[0].tolist()[0] == [112, 137, 134, 178]
    # the costmap lies 2 mm above the map; the map's extent is known in the fixed frame
    assert meshcat.transforms["/rviz/Map_(2)/image"][2, 3] == pytest.approx(0.002)
    assert rviz.map_extent() == pytest.approx((-1.0, 0.5, 0.0, 1.0))
    rviz.close()


def test_a_map_whose_data_does_not_fit_is_reported_as_rviz_does(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=["Map"], meshcat=meshcat)
    node.create_publisher("map", OccupancyGrid).publish(_grid([0, 0, 0], 2, 2))
    deadline = time.monotonic() + 10
    while "Map" not in rviz.displays[0].status and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.01)
    assert rviz.displays[0].status["Map"] == (
        "Data size doesn't match width*height: width = 2, height = 2, data size = 3"
    )
    from workbench.errors import ViewerError

    with pytest.raises(ViewerError, match="unknown Color Scheme 'heat'"):
        rviz.add_display("Map", color_scheme="heat")
    rviz.close()


def test_polygon_is_a_closed_line_in_its_frame(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=[], meshcat=meshcat)
    display = rviz.add_display("Polygon", topic="/move_base/local_costmap/footprint")
    footprint = PolygonStamped()
    footprint.header.frame_id = "base_link"
    corners = [(-0.105, -0.105), (-0.105, 0.105), (0.041, 0.105), (0.041, -0.105)]
    footprint.polygon.points = [Point32(x=x, y=y, z=0.0) for x, y in corners]
    publisher = node.create_publisher("/move_base/local_costmap/footprint", PolygonStamped)
    publisher.publish(footprint)
    _wait_drawn(rviz, display)
    vertices, ends, rgba = meshcat.lines["/rviz/Polygon"]
    assert ends is None and vertices.shape == (3, 5)
    np.testing.assert_allclose(vertices[:2, :4].T, corners, atol=1e-6)
    np.testing.assert_allclose(vertices[:, 4], vertices[:, 0])  # back to the first point
    assert rgba == pytest.approx((25 / 255, 1.0, 0.0, 1.0))  # RViz's default colour
    np.testing.assert_allclose(meshcat.transforms["/rviz/Polygon"][:3, 3], [2.0, 0.0, 0.0])
    footprint.polygon.points[1].x = float("nan")
    publisher.publish(footprint)
    deadline = time.monotonic() + 10
    while display.status.get("Topic") == "OK" and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.01)
    assert display.status["Topic"] == (
        "Message contained invalid floating point values (nans or infs)"
    )
    rviz.close()


def test_path_and_particle_cloud_are_drawn_as_rviz_draws_them(scene):
    bus, node, meshcat = scene
    rviz = RViz(bus, fixed_frame="map", displays=[], meshcat=meshcat)
    plan = rviz.add_display("Path", topic="/move_base/NavfnROS/plan", color=(1.0, 0.0, 0.0))
    cloud = rviz.add_display("PoseArray")
    assert cloud.topic == "particlecloud"
    path = Path()
    path.header.frame_id = "map"
    for k in range(4):
        pose = PoseStamped()
        pose.header.frame_id = "map"
        pose.pose.position.x, pose.pose.position.y = 0.5 * k, 0.1 * k
        path.poses.append(pose)
    node.create_publisher("/move_base/NavfnROS/plan", Path).publish(path)
    particles = PoseArray()
    particles.header.frame_id = "base_link"
    for yaw in (0.0, math.pi / 2):
        pose = Pose()
        pose.position.x = 1.0
        pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        particles.poses.append(pose)
    particles.poses.append(Pose())  # an all-zero quaternion: the identity, as RViz's
    node.create_publisher("particlecloud", PoseArray).publish(particles)
    _wait_drawn(rviz, plan)
    _wait_drawn(rviz, cloud)
    vertices, _, rgba = meshcat.lines["/rviz/Path"]
    np.testing.assert_allclose(vertices[:2].T, [[0.5 * k, 0.1 * k] for k in range(4)])
    assert rgba == (1.0, 0.0, 0.0, 1.0)
    starts, ends, rgba = meshcat.lines["/rviz/PoseArray"]
    assert starts.shape == ends.shape == (3, 9)  # three strokes per pose
    assert rgba == pytest.approx((1.0, 25 / 255, 0.0, 1.0))
    np.testing.assert_allclose(starts[:, 0], [1.0, 0.0, 0.0])  # shaft of the first
    np.testing.assert_allclose(ends[:, 0], [1.3, 0.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(ends[:, 1], [1.225, 0.06, 0.0], atol=1e-9)
    np.testing.assert_allclose(ends[:, 2], [1.225, -0.06, 0.0], atol=1e-9)
    np.testing.assert_allclose(ends[:, 3], [1.0, 0.3, 0.0], atol=1e-9)  # the turned one
    np.testing.assert_allclose(meshcat.transforms["/rviz/PoseArray"][:3, 3], [2.0, 0.0, 0.0])
    path.poses = []
    node.create_publisher("/move_base/NavfnROS/plan", Path).publish(path)
    _wait_drawn(rviz, plan, 2)
    assert not meshcat.HasPath("/rviz/Path")  # an empty plan clears the line
    rviz.close()


def _heard(node, topic, kind):
    heard = []
    node.create_subscription(topic, kind, heard.append)
    return heard


def _wait(predicate, seconds=10.0):
    deadline = time.monotonic() + seconds
    while not predicate() and time.monotonic() < deadline:
        time.sleep(0.01)
    return predicate()


def test_tool_buttons_publish_the_slider_pose_in_the_fixed_frame(scene):
    bus, node, meshcat = scene
    poses = _heard(node, "/initialpose", PoseWithCovarianceStamped)
    goals = _heard(node, "/move_base_simple/goal", PoseStamped)
    rviz = RViz(bus, fixed_frame="map", displays=["Map"], meshcat=meshcat)
    rviz.update()
    assert {"2D Pose Estimate", "2D Nav Goal"} <= set(meshcat.GetButtonNames())
    assert {"Pose x (m)", "Pose y (m)", "Pose yaw (deg)"} <= set(meshcat.GetSliderNames())
    assert meshcat.SetSliderValue("Pose x (m)", 50.0) == 10.0  # no map yet: +-10 m
    # a 4 x 3 m map from (-1, -1): the sliders now span it
    node.create_publisher("map", OccupancyGrid).publish(
        _grid([0] * 12, 4, 3, resolution=1.0, x=-1.0, y=-1.0)
    )
    _wait_drawn(rviz, rviz.displays[0])
    rviz.update()
    assert meshcat.GetSliderValue("Pose x (m)") == 3.0  # kept, clamped into the map
    assert meshcat.SetSliderValue("Pose x (m)", -5.0) == -1.0
    assert meshcat.SetSliderValue("Pose y (m)", 5.0) == 2.0
    meshcat.SetSliderValue("Pose x (m)", 1.5)
    meshcat.SetSliderValue("Pose y (m)", -0.5)
    meshcat.SetSliderValue("Pose yaw (deg)", 90.0)
    rviz.update()
    arrow = meshcat.transforms["/rviz/Tools/pose"]
    np.testing.assert_allclose(arrow[:3, 3], [1.5, -0.5, 0.0])
    np.testing.assert_allclose(arrow[:3, 0], [0.0, 1.0, 0.0], atol=1e-9)  # facing +y
    click(meshcat, "2D Pose Estimate")
    rviz.update()
    assert _wait(lambda: len(poses) == 1)
    pose = poses[0]
    assert pose.header.frame_id == "map"
    assert (pose.pose.pose.position.x, pose.pose.pose.position.y) == (1.5, -0.5)
    q = pose.pose.pose.orientation
    assert (q.z, q.w) == pytest.approx((math.sin(math.pi / 4), math.cos(math.pi / 4)))
    covariance = np.asarray(pose.pose.covariance).reshape(6, 6)
    expected = np.zeros((6, 6))
    expected[0, 0] = expected[1, 1] = 0.25
    expected[5, 5] = (math.pi / 12) ** 2
    np.testing.assert_allclose(covariance, expected)
    click(meshcat, "2D Nav Goal")
    click(meshcat, "2D Nav Goal")
    rviz.update()
    assert _wait(lambda: len(goals) == 1)
    goal = goals[0]
    assert goal.header.frame_id == "map"
    assert (goal.pose.position.x, goal.pose.position.y, goal.pose.position.z) == (1.5, -0.5, 0)
    assert len(poses) == 1  # one click, one message
    rviz.close()
    assert not {"2D Pose Estimate", "2D Nav Goal"} & set(meshcat.GetButtonNames())
    assert "Pose x (m)" not in meshcat.GetSliderNames()


def test_send_goal_and_set_pose_estimate_from_python(scene):
    from workbench.errors import ViewerError
    from workbench.rviz.pose_tools import ToolSettings

    bus, node, meshcat = scene
    poses = _heard(node, "/amcl/initialpose", PoseWithCovarianceStamped)
    goals = _heard(node, "/goal", PoseStamped)
    settings = ToolSettings(
        initial_pose_topic="/amcl/initialpose", goal_topic="goal", std_dev_x=0.1, tools=()
    )
    rviz = RViz(bus, fixed_frame="odom", displays=[], meshcat=meshcat, tools=settings)
    rviz.update()
    assert "2D Nav Goal" not in meshcat.GetButtonNames()  # no tools: no controls
    sent = rviz.send_goal(2.0, -1.0, math.pi)
    rviz.set_pose_estimate(0.5, 0.25, -math.pi / 2)
    assert _wait(lambda: goals and poses)
    assert goals[0].header.frame_id == "odom" and goals[0].pose.position.x == 2.0
    assert goals[0].pose.orientation.z == pytest.approx(1.0) == sent.pose.orientation.z
    assert np.asarray(poses[0].pose.covariance)[0] == pytest.approx(0.01)
    assert poses[0].pose.pose.orientation.z == pytest.approx(-math.sqrt(0.5))
    with pytest.raises(ViewerError, match=r"2D Nav Goal: x, y and yaw must be finite"):
        rviz.send_goal(float("nan"), 0.0, 0.0)
    rviz.close()


def test_the_tools_section_of_an_rviz_config_sets_topics_and_deviations(tmp_path):
    from workbench.rviz.config import load_config

    config = tmp_path / "nav.rviz"
    config.write_text(
        """Visualization Manager:
  Global Options: {Fixed Frame: map}
  Displays:
    - {Class: rviz/Map, Name: Costmap, Topic: /move_base/local_costmap/costmap,
       Color Scheme: costmap, Alpha: 0.5}
    - {Class: rviz/Polygon, Name: Footprint, Topic: /move_base/local_costmap/footprint,
       Color: 0; 0; 0}
    - {Class: rviz/Path, Name: Plan, Topic: /move_base/NavfnROS/plan, Color: 255; 0; 0}
  Tools:
    - Class: rviz/Interact
    - Class: rviz/SetInitialPose
      Theta std deviation: 0.5
      Topic: /robot/initialpose
      X std deviation: 0.2
    - Class: rviz/SetGoal
      Topic: /robot/goal
""",
        encoding="utf-8",
    )
    loaded = load_config(config)
    assert [d.options for d in loaded.displays] == [
        {"topic": "/move_base/local_costmap/costmap", "color_scheme": "costmap", "alpha": 0.5},
        {"topic": "/move_base/local_costmap/footprint", "color": (0.0, 0.0, 0.0), "alpha": 1.0},
        {"topic": "/move_base/NavfnROS/plan", "color": (1.0, 0.0, 0.0), "alpha": 1.0},
    ]
    tools = loaded.tools
    assert tools.tools == ("SetInitialPose", "SetGoal")
    assert (tools.initial_pose_topic, tools.goal_topic) == ("/robot/initialpose", "/robot/goal")
    assert (tools.std_dev_x, tools.std_dev_y, tools.std_dev_theta) == (0.2, 0.5, 0.5)
    config.write_text(
        config.read_text().replace("X std deviation: 0.2", "X std deviation: wide"), "utf-8"
    )
    from workbench.errors import ViewerError

    with pytest.raises(ViewerError, match="Tools: SetInitialPose: X std deviation is not a number"):
        load_config(config)


def test_the_turtlebot3_navigation_view_builds_with_its_tools(scene):
    from types import SimpleNamespace

    from workbench.bus.launch import find_package
    from workbench.rviz.node import build

    bus, node, meshcat = scene
    view = find_package("turtlebot3_navigation") / "rviz" / "turtlebot3_navigation.rviz"
    rviz = build(
        SimpleNamespace(display_config=str(view), fixed_frame=None, port=None), bus, meshcat
    )
    assert [d.name for d in rviz.displays][-5:] == [
        "Polygon", "Costmap (2)", "Planner (2)", "Amcl Particles", "Goal",
    ]  # fmt: skip
    costmaps = [d for d in rviz.displays if getattr(d, "color_scheme", None) == "costmap"]
    assert [d.topic for d in costmaps] == [
        "/move_base/global_costmap/costmap",
        "/move_base/local_costmap/costmap",
    ]
    assert [d.layer for d in costmaps] == [1, 2]  # above the map
    goals = _heard(node, "/move_base_simple/goal", PoseStamped)
    rviz.update()
    assert {"2D Pose Estimate", "2D Nav Goal"} <= set(meshcat.GetButtonNames())
    click(meshcat, "2D Nav Goal")
    rviz.update()
    assert _wait(lambda: goals) and goals[0].header.frame_id == "map"
    rviz.close()


def test_two_rviz_on_one_meshcat_keep_their_controls_when_one_closes(scene):
    bus, node, meshcat = scene
    goals = _heard(node, "/move_base_simple/goal", PoseStamped)
    first = RViz(bus, fixed_frame="map", displays=[], meshcat=meshcat)
    second = RViz(bus, fixed_frame="map", displays=[], meshcat=meshcat)
    first.update()
    second.update()
    first.close()  # removes the panel's controls
    second.update()  # puts them back
    assert "2D Nav Goal" in meshcat.GetButtonNames()
    meshcat.SetSliderValue("Pose x (m)", 2.0)
    click(meshcat, "2D Nav Goal")
    second.update()
    assert _wait(lambda: goals) and goals[0].pose.position.x == 2.0
    second.close()
