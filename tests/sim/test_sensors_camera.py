"""Cameras rendered by Drake: depth against analytic geometry, point clouds, the OpenNI topics.

What is matched (gazebo_plugins noetic-devel):

* gazebo_ros_camera_utils.cpp: topics under ``<cameraName>`` (``image_raw``,
  ``camera_info`` by default); CameraInfo with ``f = W / (2 tan(hfov / 2))``,
  ``cx = (W + 1) / 2``, ``cy = (H + 1) / 2``, plumb_bob, ``P[3] = -f * hackBaseline``;
* gazebo_ros_openni_kinect.cpp: defaults ``ir/image_raw``, ``ir/camera_info``,
  ``depth/image_raw`` (32FC1), ``depth/camera_info``, ``points``; depths outside
  ``(pointCloudCutoff = 0.4, pointCloudCutoffMax = 5)`` are NaN in the depth
  image and the cloud; cloud points ``x = z tan(atan2(i - (W - 1) / 2, f))``,
  fields x, y, z, rgb (offsets 0, 4, 8, 16; 32 bytes a point).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from sensor_helpers import sdf_model, sensor_robot_sdf

from workbench.bus import Bus, Node
from workbench.sim import World
from workbench.sim.sensors import Camera, parse_sensor, sensor_plugin
from workbench.sim.server import SERVER_PHYSICS, SimServer
from workbench.spatial import rigid_transform

W, H, FOV = 80, 60, 1.2


def camera_xml(kind: str = "depth", plugin: str = "", fmt: str = "R8G8B8", rate: float = 10) -> str:
    """A camera 0.1 m in front of its link's origin (Gazebo cameras see their own link too)."""
    return f"""<sensor type="{kind}" name="cam"><update_rate>{rate}</update_rate>
  <pose>0.1 0 0 0 0 0</pose>
  <camera><horizontal_fov>{FOV}</horizontal_fov>
    <image><width>{W}</width><height>{H}</height><format>{fmt}</format></image>
    <clip><near>0.05</near><far>20</far></clip></camera>{plugin}</sensor>"""


# a wall tilted in yaw and pitch: the plane n . x = d, with n its x axis
WALL_RPY = (0.0, 0.3, 0.4)
WALL_CENTRE = np.array([3.0, 0.2, 1.0])
WALL_THICKNESS = 0.2


def _wall_world(**options) -> World:
    world = World(ground=False, **options)
    world.add_box(
        "wall",
        size=(WALL_THICKNESS, 30.0, 30.0),
        X_WB=rigid_transform(list(WALL_CENTRE), rpy=list(WALL_RPY)),
        rgba=(1.0, 0.0, 0.0, 1.0),
    )
    return world


def _wall_plane() -> tuple[np.ndarray, float]:
    R = rigid_transform([0, 0, 0], rpy=list(WALL_RPY)).rotation().matrix()
    n = R[:, 0]
    return n, float(n @ (WALL_CENTRE - n * WALL_THICKNESS / 2))


def _analytic_depth(X_WS) -> np.ndarray:
    """Depth along the optical axis of each pixel centre (Gazebo's pixel angles)."""
    n, d = _wall_plane()
    f = W / (2 * math.tan(FOV / 2))
    u = (np.arange(W) - (W - 1) / 2) / f
    v = (np.arange(H) - (H - 1) / 2) / f
    R = X_WS.rotation().matrix()
    o = X_WS.translation()
    # optical ray (u, v, 1) is S's (1, -u, -v): x forward, y left, z up
    rays = np.stack(
        [np.ones((H, W)), -np.broadcast_to(u, (H, W)), -np.broadcast_to(v[:, None], (H, W))], -1
    )
    rays_W = rays @ R.T
    return (d - n @ o) / (rays_W @ n)


def test_depth_pixels_are_within_a_centimetre_of_the_analytic_depth_and_colour_is_the_walls():
    world = _wall_world()
    world.build()
    camera = Camera(parse_sensor(camera_xml(), model="m", link="l"))
    X_WS = rigid_transform([0.2, -0.1, 1.1], rpy=[0.05, -0.1, 0.2])
    frame = camera.capture(world, X_WS)
    assert frame.depth is not None and frame.color is not None
    assert frame.depth.shape == (H, W) and frame.color.shape == (H, W, 3)
    error = np.abs(frame.depth - _analytic_depth(X_WS))
    assert error.max() < 0.01
    assert error.max() < 1e-3  # no half-pixel shift: the pixel centres are where Gazebo has them
    red, green, blue = (frame.color[..., k].astype(int) for k in range(3))
    assert np.all(red > 2 * green) and np.all(red > 2 * blue)


def test_point_cloud_points_lie_on_the_wall():
    world = _wall_world()
    world.build()
    camera = Camera(parse_sensor(camera_xml(), model="m", link="l"))
    X_WS = rigid_transform([0.0, 0.0, 1.0])
    frame = camera.capture(world, X_WS)
    assert frame.depth is not None
    points = camera.points(frame.depth).reshape(-1, 3)  # optical frame C
    X_WC = X_WS.multiply(rigid_transform([0, 0, 0], rpy=[-math.pi / 2, 0, -math.pi / 2]))
    points_W = points @ X_WC.rotation().matrix().T + X_WC.translation()
    n, d = _wall_plane()
    assert np.abs(points_W @ n - d).max() < 0.01


def test_the_image_is_not_mirrored_a_box_to_the_left_is_on_the_left():
    world = World(ground=False)
    world.add_box("left", size=(0.5, 0.5, 0.5), X_WB=[3.0, 1.0, 0.0], rgba=(0, 1, 0, 1))
    world.add_box("up", size=(0.5, 0.5, 0.5), X_WB=[3.0, 0.0, 1.0], rgba=(0, 0, 1, 1))
    world.build()
    camera = Camera(parse_sensor(camera_xml(kind="camera"), model="m", link="l"))
    frame = camera.capture(world, rigid_transform([0, 0, 0]), depth=False)
    assert frame.color is not None
    r, g, b = (frame.color[..., k].astype(int) for k in range(3))
    green = np.argwhere((g > 100) & (r < 60) & (b < 60))
    blue = np.argwhere((b > 100) & (r < 60) & (g < 60))
    assert len(green) > 50 and len(blue) > 50
    assert green[:, 1].mean() < W / 2 - 10 and abs(green[:, 0].mean() - (H - 1) / 2) < 2
    assert blue[:, 0].mean() < H / 2 - 10 and abs(blue[:, 1].mean() - (W - 1) / 2) < 2


KINECT = """<plugin name="kinect" filename="libgazebo_ros_openni_kinect.so">
  <cameraName>kinect</cameraName><frameName>kinect_optical</frameName>
  <pointCloudCutoff>0.5</pointCloudCutoff><pointCloudCutoffMax>4.0</pointCloudCutoffMax>
</plugin>"""


def test_the_openni_plugin_publishes_images_depth_cloud_and_camera_info():
    bus = Bus(threaded=False)
    received: dict[str, list] = {}
    listener = Node("listener", bus=bus)
    topics = {
        "/kinect/ir/image_raw": "sensor_msgs/Image",
        "/kinect/ir/camera_info": "sensor_msgs/CameraInfo",
        "/kinect/depth/image_raw": "sensor_msgs/Image",
        "/kinect/depth/camera_info": "sensor_msgs/CameraInfo",
        "/kinect/points": "sensor_msgs/PointCloud2",
    }
    for topic, kind in topics.items():
        received[topic] = []
        listener.create_subscription(topic, kind, received[topic].append, queue_size=100)
    world = _wall_world(**SERVER_PHYSICS)
    world.add_box("near", size=(0.2, 0.2, 0.2), X_WB=[0.45, 0.0, 1.0])  # closer than the cutoff
    server = SimServer(world, bus=bus, real_time_factor=0)
    server.spawn(sdf_model(sensor_robot_sdf("bot", camera_xml(plugin=KINECT), size=0.1)), [0, 0, 1])
    server.run(until=0.25)
    while bus.spin_once(0.0):
        pass
    assert {t: len(m) for t, m in received.items()} == {t: 3 for t in topics}  # 10 Hz: 0, .1, .2
    image = received["/kinect/ir/image_raw"][-1]
    assert (image.encoding, image.width, image.height, image.step) == ("rgb8", W, H, 3 * W)
    assert image.header.frame_id == "kinect_optical"
    assert image.header.stamp.to_sec() == pytest.approx(0.2)
    depth_msg = received["/kinect/depth/image_raw"][-1]
    assert (depth_msg.encoding, depth_msg.step) == ("32FC1", 4 * W)
    depth = np.frombuffer(bytes(depth_msg.data), "<f4").reshape(H, W)
    centre = depth[H // 2 - 2 : H // 2 + 2, W // 2 - 2 : W // 2 + 2]
    assert np.all(np.isnan(centre))  # the near box, inside the 0.5 m cutoff
    X_WS = rigid_transform([0.1, 0, 1])
    expected = _analytic_depth(X_WS)
    seen = np.isfinite(depth)
    assert seen.sum() > 0.3 * W * H
    assert np.abs(depth[seen] - expected[seen]).max() < 0.01
    assert np.all(np.isnan(depth[expected > 4.01]))  # beyond pointCloudCutoffMax
    assert np.any(expected > 4.01)
    info = received["/kinect/depth/camera_info"][-1]
    f = W / (2 * math.tan(FOV / 2))
    assert list(info.K) == pytest.approx([f, 0, (W + 1) / 2, 0, f, (H + 1) / 2, 0, 0, 1])
    assert info.distortion_model == "plumb_bob" and list(info.D) == [0.0] * 5
    cloud = received["/kinect/points"][-1]
    assert [(fl.name, fl.offset, fl.datatype) for fl in cloud.fields] == [
        ("x", 0, 7),
        ("y", 4, 7),
        ("z", 8, 7),
        ("rgb", 16, 7),
    ]
    assert (cloud.width, cloud.height, cloud.point_step, cloud.is_dense) == (W, H, 32, False)
    rows = np.frombuffer(bytes(cloud.data), np.uint8).reshape(H * W, 32)
    xyz = rows[:, :12].copy().view("<f4").reshape(H, W, 3)
    assert np.allclose(xyz[..., 2][seen], depth[seen])
    pixels = np.frombuffer(bytes(image.data), np.uint8).reshape(H * W, 3)
    assert np.array_equal(rows[:, 16:19], pixels)  # the image's bytes, in image order
    server.stop()


def test_a_camera_renders_only_for_subscribers_and_on_demand():
    plugin = (
        '<plugin name="c" filename="libgazebo_ros_camera.so"><cameraName>cam</cameraName></plugin>'
    )
    world = _wall_world(**SERVER_PHYSICS)
    server = SimServer(world, bus=Bus(threaded=False), real_time_factor=0)
    server.spawn(
        sdf_model(sensor_robot_sdf("bot", camera_xml(kind="camera", plugin=plugin), size=0.1)),
        [0, 0, 1],
    )
    server.run(until=0.15)
    camera = sensor_plugin(server, "cam")
    assert camera.latest is None  # nobody listened
    frame = camera.capture()
    assert frame.color is not None and frame.color.shape == (H, W, 3) and frame.depth is None
    assert camera.latest is frame
    server.stop()
