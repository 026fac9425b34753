"""The laser: exact distances against analytic geometry, Gazebo's out-of-range readings, the bus.

What is matched (gazebo_plugins noetic-devel, gazebo 11):

* gazebo_ros_laser.cpp / gazebo_ros_gpu_laser.cpp: ``<topicName>`` and
  ``<frameName>`` default to ``/world``; the message copies the sensor's angles,
  ``angle_increment = (max - min) / (count - 1)``, ``time_increment = scan_time = 0``,
  range limits, ranges and intensities, stamped with the scan's simulated time;
* gazebo's RaySensor / GpuRaySensor: a reading at or beyond ``<range><max>`` is
  ``+inf`` (REP 117), noise only on readings in range, clamped to [min, max];
* MultiRayShape: beam i points at ``min_angle + i (max - min) / (samples - 1)``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from sensor_helpers import (
    SENSOR_Z,
    analytic_distance,
    build_world,
    laser_xml,
    sdf_model,
    sensor_robot_sdf,
)
from sim_helpers import box_model

from workbench.bus import Bus, Node
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.sensors import Lidar, parse_sensor, sensor_plugin
from workbench.sim.sensors.raycast import (
    CAPSULE,
    CONVEX,
    ELLIPSOID,
    HALFSPACE,
    SPHERE,
    ShapeTable,
    cast_rays,
)
from workbench.sim.server import SERVER_PHYSICS, SimServer
from workbench.spatial import rigid_transform

LASER_PLUGIN = (
    '<plugin name="laser_plugin" filename="libgazebo_ros_laser.so">'
    "<topicName>/scan</topicName><frameName>base_laser</frameName></plugin>"
)


@pytest.fixture(scope="module")
def world() -> World:
    w = World(ground=True)
    build_world(w)
    w.build()
    return w


def _spec(**options):
    return parse_sensor(laser_xml(**options), model="test", link="base")


@pytest.mark.parametrize(("x", "y", "yaw"), [(0.0, 0.0, 0.0), (0.7, -0.4, 0.3), (-1.2, 0.9, -2.0)])
def test_every_beam_is_within_a_centimetre_of_the_analytic_distance(world, x, y, yaw):
    spec = _spec(range_max=20.0)
    lidar = Lidar(spec)
    X_WS = rigid_transform([x, y, SENSOR_Z], rpy=[0, 0, yaw])
    ranges = lidar.scan(world, X_WS, noise=False)
    angles = spec.horizontal.angles() + yaw
    expected = np.array(
        [analytic_distance(np.array([x, y]), np.array([math.cos(a), math.sin(a)])) for a in angles]
    )
    expected[expected >= spec.range_max] = np.inf
    assert ranges.shape == (720,)
    hit = np.isfinite(expected)
    assert hit.sum() > 300  # the walls and obstacles cover much of the view
    assert np.array_equal(np.isfinite(ranges), hit)
    assert np.max(np.abs(ranges[hit] - expected[hit])) < 0.01
    assert np.max(np.abs(ranges[hit] - expected[hit])) < 1e-6  # in fact exact


def test_beams_that_hit_nothing_read_plus_inf_and_hits_beyond_max_too(world):
    spec = _spec(range_max=3.0)
    ranges = Lidar(spec).scan(world, rigid_transform([0, 0, SENSOR_Z]), noise=False)
    angles = spec.horizontal.angles()
    east = np.argmin(np.abs(angles))  # the east wall is 3.9 m away: beyond max
    south = np.argmin(np.abs(angles + math.pi / 2))  # nothing at all to the south
    assert ranges[east] == math.inf and ranges[south] == math.inf
    assert np.all(np.isfinite(ranges) | (ranges == math.inf))  # never -inf, never NaN
    finite = ranges[np.isfinite(ranges)]
    assert finite.size and finite.max() < 3.0 and finite.min() > 0.1


def test_above_the_obstacles_only_the_ground_is_seen_by_downward_beams(world):
    vertical = (
        "<vertical><samples>3</samples><resolution>1</resolution>"
        "<min_angle>-0.5</min_angle><max_angle>0.5</max_angle></vertical>"
    )
    spec = _spec(samples=8, range_max=30.0, vertical=vertical)
    ranges = Lidar(spec).scan(world, rigid_transform([0, 0, 5.0]), noise=False)
    rows = ranges.reshape(3, 8)
    assert np.allclose(rows[0], 5.0 / math.sin(0.5), atol=1e-9)  # pitch -0.5: down to z = 0
    assert np.all(rows[1:] == math.inf)  # level and up: nothing


def test_gaussian_noise_is_seeded_and_clamped_to_the_limits(world):
    noise = "<noise><type>gaussian</type><mean>0.0</mean><stddev>0.05</stddev></noise>"
    spec = _spec(noise=noise, range_max=20.0)
    X = rigid_transform([0, 0, SENSOR_Z])
    clean = Lidar(spec).scan(world, X, noise=False)
    a, b = Lidar(spec, seed=3).scan(world, X), Lidar(spec, seed=3).scan(world, X)
    assert np.array_equal(a, b)
    hit = np.isfinite(clean)
    error = a[hit] - clean[hit]
    assert 0.03 < error.std() < 0.07 and abs(error.mean()) < 0.01
    assert np.array_equal(np.isfinite(a), hit)  # noise never turns a reading into inf


def test_shapes_of_every_other_kind_against_their_analytic_distances():
    eye = np.repeat(np.eye(3)[None], 5, axis=0)
    c, s = math.cos(0.4), math.sin(0.4)
    tilted = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    R = eye.copy()
    R[1] = tilted
    cube = np.array(
        [
            [1, 0, 0, 0.5],
            [-1, 0, 0, 0.5],
            [0, 1, 0, 0.5],
            [0, -1, 0, 0.5],
            [0, 0, 1, 0.5],
            [0, 0, -1, 0.5],
        ],
        dtype=float,
    )
    table = ShapeTable(
        kind=np.array([SPHERE, CAPSULE, ELLIPSOID, HALFSPACE, CONVEX]),
        params=np.array([[0.5, 0, 0], [0.3, 0.5, 0], [0.2, 0.4, 0.6], [0, 0, 0], [0, 0, 0]]),
        R_WG=R,
        p_WG=np.array([[5, 0, 0], [0, 5, 0], [-5, 0, 0], [0, 0, -2], [0, -5, 0]], dtype=float),
        center_G=np.zeros((5, 3)),
        radius=np.array([0.5, 0.8, 0.6, np.inf, math.sqrt(0.75)]),
        planes={4: cube},
    )
    directions = np.array(
        [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, 0, -1], [0, -1, 0], [0, 0, 1]], dtype=float
    )
    t = cast_rays(table, np.zeros(3), directions, 0.0, 100.0)
    # capsule: tilted 0.4 rad about y; along +y the beam meets its side at radius 0.3
    assert t == pytest.approx([4.5, 4.7, 4.8, 2.0, 4.5, math.inf], abs=1e-9)
    # from inside the sphere the beam crosses its surface on the way out
    inside = cast_rays(table, np.array([5.0, 0, 0]), directions[:1], 0.0, 100.0)
    assert inside[0] == pytest.approx(0.5)


def test_broad_phase_finds_what_testing_every_pair_finds():
    rng = np.random.default_rng(7)
    n = 300
    table = ShapeTable(
        kind=np.full(n, SPHERE),
        params=np.c_[rng.uniform(0.05, 0.4, n), np.zeros((n, 2))],
        R_WG=np.repeat(np.eye(3)[None], n, axis=0),
        p_WG=rng.uniform(-10, 10, (n, 3)),
        center_G=np.zeros((n, 3)),
        radius=np.zeros(n),
    )
    table.radius = table.params[:, 0].copy()
    directions = rng.normal(size=(2000, 3))
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    directions[:2] = [[0, 0, 1], [0, 0, -1]]  # no azimuth
    origin = np.array([0.3, -0.2, 0.1])
    t = cast_rays(table, origin, directions, 0.0, 8.0)
    rel = table.p_WG - origin
    along = directions @ rel.T
    miss2 = (rel**2).sum(axis=1)[None, :] - along**2
    root = np.sqrt(np.maximum(table.radius[None, :] ** 2 - miss2, 0.0))
    brute = np.where((miss2 <= table.radius**2) & (along - root > 0), along - root, np.inf).min(
        axis=1
    )
    brute[brute > 8.0] = np.inf
    assert np.isfinite(t).sum() > 50
    assert np.allclose(t, brute, atol=1e-9, equal_nan=False)


def _server(bus=None, *, walls=True):
    world = World(**SERVER_PHYSICS)
    if walls:
        build_world(world)
    return SimServer(world, bus=bus, real_time_factor=0)


def test_scans_are_published_at_the_sensor_rate_with_sim_time_stamps_and_the_frame():
    bus = Bus(threaded=False)
    scans: list = []
    Node("listener", bus=bus).create_subscription(
        "/scan", "sensor_msgs/LaserScan", scans.append, queue_size=1000
    )
    server = _server(bus)
    robot = sensor_robot_sdf("bot", laser_xml(rate=20.0, range_max=20.0, plugin=LASER_PLUGIN))
    server.spawn(sdf_model(robot), [0.0, 0.0, SENSOR_Z - 0.1])
    server.run(until=0.5)
    while bus.spin_once(0.0):
        pass
    stamps = [s.header.stamp.to_sec() for s in scans]
    assert stamps == pytest.approx([0.05 * k for k in range(10)], abs=1e-9)
    last = scans[-1]
    assert last.header.frame_id == "base_laser"
    assert last.angle_min == pytest.approx(-math.pi) and last.angle_max == pytest.approx(math.pi)
    assert last.angle_increment == pytest.approx(2 * math.pi / 719)
    assert (last.time_increment, last.scan_time) == (0.0, 0.0)
    assert (last.range_min, last.range_max) == pytest.approx((0.1, 20.0))
    assert len(last.ranges) == len(last.intensities) == 720
    east = int(np.argmin(np.abs(np.linspace(-math.pi, math.pi, 720))))
    assert last.ranges[east] == pytest.approx(3.9, abs=0.01)  # the wall; the box itself unseen
    server.stop()


def test_the_sensors_own_link_is_not_seen_and_a_spawned_box_appears_in_the_next_scan():
    server = _server(walls=False)
    robot = sensor_robot_sdf("bot", laser_xml(rate=10.0, plugin=LASER_PLUGIN), size=0.6)
    server.spawn(sdf_model(robot), [0.0, 0.0, 0.3])
    server.run(until=0.05)
    laser = sensor_plugin(server, "laser")
    assert laser.latest is not None
    assert np.all(laser.latest == math.inf)  # the 0.6 m box around the sensor is its own link
    # the beams leave from z = 0.4 (the pose is 0.1 above the link's centre)
    server.spawn(box_model("obstacle", size=0.8, static=True), [2.0, 0.0, 0.4])
    server.run(until=0.15)
    ahead = int(np.argmin(np.abs(np.linspace(-math.pi, math.pi, 720))))
    assert laser.latest[ahead] == pytest.approx(1.6, abs=0.005)
    assert laser.latest_message.header.stamp.to_sec() == pytest.approx(0.1)
    server.stop()


def test_the_lab_robot_gives_720_beam_scans_on_scan():
    from workbench.sim.loading import load_sim_model

    bus = Bus(threaded=False)
    scans: list = []
    Node("listener", bus=bus).create_subscription(
        "/scan", "sensor_msgs/LaserScan", scans.append, queue_size=100
    )
    server = _server(bus)
    server.spawn(load_sim_model(str(urdf_dir() / "custom_bot.urdf")), [0.0, 0.0, 0.1])
    server.run(until=0.1)
    while bus.spin_once(0.0):
        pass
    assert len(scans) == 4  # <update_rate>40</update_rate>: t = 0, 0.025, 0.05, 0.075
    assert {len(s.ranges) for s in scans} == {720}
    assert scans[-1].header.frame_id == "laser_scanner"
    assert (scans[-1].range_min, scans[-1].range_max) == pytest.approx((0.1, 30.0))
    assert np.isfinite(np.asarray(scans[-1].ranges)).sum() > 100  # the walls are seen
    server.stop()
