"""Experiment 6 steps 23-30: simpledoifffbot follows a box with libFollowerPlugin.so.

What is matched (Gazebo 11, plugins/FollowerPlugin.cc): the first depth sensor
of the model; left and right wheels are ``<left_joint>``/``<right_joint>`` or
the first two revolute joints; separation = the joints' anchors' distance,
radius = half the left wheel's largest bounding-box edge; per depth frame the
nearest depth in (0.1, 5) m of the middle row steers
``turn = 1 - idx / (W / 2)``, rim speeds ``-0.1 -+ 0.1 turn b / 2`` m/s, and
nothing in range or nearer than 0.4 m stops the wheels.
"""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from follower_helpers import ROBOT, FollowRig, counting, follower_model

from workbench.sim import World
from workbench.sim.gazebo_plugins.follower import (
    MAX_RANGE,
    STOP_DISTANCE,
    nearest_in_middle_row,
    wheel_velocities,
)
from workbench.sim.loading import load_sim_model
from workbench.sim.model_spec import PluginSpec
from workbench.sim.plugins import BUILTIN_PLUGINS
from workbench.sim.server import SERVER_PHYSICS, SimServer


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    return follower_model(tmp_path_factory.mktemp("follower"))


@pytest.fixture
def rig_factory():
    rigs: list[FollowRig] = []

    def make(model, box_xy):
        rigs.append(FollowRig(model, box_xy))
        return rigs[-1]

    yield make
    for rig in rigs:
        rig.close()


# --- the steering, one depth image at a time ---------------------------------------------


def _image(width: int = 8, height: int = 5, fill: float = np.inf) -> np.ndarray:
    return np.full((height, width), fill, dtype=np.float32)


def test_the_nearest_pixel_of_the_middle_row_in_range_is_the_target():
    depth = _image()
    depth[2, 5] = 2.0
    depth[2, 6] = 1.0
    depth[1, 1] = 0.5  # not in the middle row (row H // 2 = 2)
    depth[2, 0] = 0.05  # nearer than 0.1 m: not a reading (Drake's 0 too)
    depth[2, 7] = np.nan
    assert nearest_in_middle_row(depth) == (6, 1.0)
    depth[2, 2] = 1.0
    assert nearest_in_middle_row(depth) == (2, 1.0)  # the leftmost of equals
    depth[2, :] = MAX_RANGE  # 5 m is out of range (exclusive)
    assert nearest_in_middle_row(depth) is None


@pytest.mark.parametrize(
    ("column", "left", "right"),
    [
        # W = 8: turn = 1 - idx / 4; yaw rate 0.1 turn; b = 1.25, r = 0.3
        (0, (-0.1 + 0.1 * 1.0 * 0.625) / 0.3, (-0.1 - 0.1 * 1.0 * 0.625) / 0.3),
        (4, -0.1 / 0.3, -0.1 / 0.3),
        (6, (-0.1 - 0.05 * 0.625) / 0.3, (-0.1 + 0.05 * 0.625) / 0.3),
    ],
)
def test_wheel_velocities_are_gazebos(column, left, right):
    depth = _image()
    depth[2, column] = 2.0
    assert wheel_velocities(depth, 1.25, 0.3) == pytest.approx((left, right))


def test_nothing_in_range_or_too_close_stops_the_wheels():
    assert wheel_velocities(_image(), 1.25, 0.3) == (0.0, 0.0)
    depth = _image()
    depth[2, 3] = STOP_DISTANCE - 0.01
    assert wheel_velocities(depth, 1.25, 0.3) == (0.0, 0.0)
    depth[2, 3] = STOP_DISTANCE + 0.01
    assert wheel_velocities(depth, 1.25, 0.3)[0] < 0.0


def test_the_library_name_maps_to_the_python_plugin():
    assert BUILTIN_PLUGINS["libFollowerPlugin.so"].endswith("follower:FollowerPlugin")


# --- the robot in the simulator ------------------------------------------------------------


def test_it_finds_its_camera_and_wheels_and_renders_only_at_the_sensor_rate(robot, rig_factory):
    rig = rig_factory(robot, None)
    plugin = rig.plugin
    assert plugin.wheels == ("wheel_1_joint", "wheel_2_joint")  # the first: y = max, the left
    assert plugin.separation == pytest.approx(1.25)  # 2 x (0.5 + 0.25 / 2)
    assert plugin.radius == pytest.approx(0.3)
    assert (plugin.spec.name, plugin.spec.type, plugin.update_rate) == ("camera", "depth", 30.0)
    times = counting(plugin.camera)
    start = rig.world.time
    rig.run(1.0)
    assert 29 <= len(times) <= 31  # not the 1000 physics steps
    assert np.diff(times) == pytest.approx(1.0 / 30.0, abs=1.5e-3)
    assert times[0] >= start


@pytest.mark.parametrize("side", [1.0, -1.0], ids=["box-left", "box-right"])
def test_it_turns_towards_a_box_and_stops_short_of_it(robot, rig_factory, side):
    rig = rig_factory(robot, None)
    rig.run(0.5)  # settle on the ground
    rig.place_box(*rig.ahead(1.5 + 0.2, 0.5 * side))  # its near side 1.5 m ahead, 0.5 m aside
    start_x, start_gap, start_bearing = rig.camera()[0], rig.gap(), rig.bearing()
    assert start_gap == pytest.approx(math.hypot(1.5, 0.3), abs=0.01)  # to its near corner
    assert side * start_bearing > 0.25
    taken = rig.run_until_stopped(40.0)
    assert taken < 30.0, "it never stopped"
    assert side * rig.heading() > 0.1  # turned towards the box
    assert abs(rig.bearing()) < 0.5  # the box is well inside its 60 degree view
    assert rig.camera()[0] - start_x > 0.8  # drove up to it ...
    assert 0.3 < rig.gap() < 0.5  # ... and stopped short: 0.4 m of depth, as Gazebo's
    assert rig.plugin.nearest is not None and rig.plugin.nearest[1] < STOP_DISTANCE
    assert rig.speed() < 0.01
    held = rig.camera().copy()
    rig.run(2.0)
    assert np.linalg.norm(rig.camera() - held) < 0.005  # and stays stopped


def test_it_follows_the_box_when_the_box_is_moved(robot, rig_factory):
    rig = rig_factory(robot, None)
    rig.run(0.5)
    rig.place_box(*rig.ahead(1.2, 0.3))
    rig.run_until_stopped(30.0)
    first = rig.camera().copy()
    heading = rig.heading()
    assert 0.3 < rig.gap() < 0.5
    # the box jumps ahead and to the right: the robot turns right and catches up
    rig.place_box(*rig.ahead(1.5, -0.6))
    rig.run(2.0)
    # wheels turn negatively to roll forward: the left one faster (more negative) turns right
    assert rig.speed() > 0.05 and rig.plugin.command[0] < rig.plugin.command[1] < 0.0
    rig.run_until_stopped(40.0)
    assert rig.heading() < heading - 0.1
    assert np.linalg.norm(rig.camera() - first) > 0.8
    assert 0.3 < rig.gap() < 0.5
    # and once more, to the left
    heading = rig.heading()
    rig.place_box(*rig.ahead(1.4, 0.6))
    rig.run_until_stopped(40.0)
    assert rig.heading() > heading + 0.1
    assert 0.3 < rig.gap() < 0.5


def test_with_nothing_in_view_it_stops(robot, rig_factory):
    rig = rig_factory(robot, None)  # the box is far away (50, 50)
    rig.run(0.5)
    still = rig.camera().copy()
    rig.run(3.0)
    assert rig.plugin.nearest is None and rig.plugin.command == (0.0, 0.0)
    assert np.linalg.norm(rig.camera() - still) < 0.005
    # beyond 5 m it sees nothing either; inside 5 m it drives
    rig.place_box(*rig.ahead(5.5, 0.0))
    rig.run(2.0)
    assert rig.plugin.command == (0.0, 0.0) and rig.speed() < 0.005
    rig.place_box(*rig.ahead(3.0, 0.0))
    rig.run(3.0)
    assert rig.speed() > 0.05
    # the box vanishes (behind the robot) while it drives: it brakes at once
    rig.place_box(*rig.ahead(-3.0, 0.0))
    rig.run(0.5)
    assert rig.plugin.nearest is None and rig.speed() < 0.01
    braked = rig.camera().copy()
    rig.run(2.0)
    assert np.linalg.norm(rig.camera() - braked) < 0.005


def test_named_joints_are_used_swapped_wheels_turn_away(tmp_path, rig_factory):
    model = follower_model(tmp_path, left_joint="wheel_2_joint", right_joint="wheel_1_joint")
    rig = rig_factory(model, None)
    assert rig.plugin.wheels == ("wheel_2_joint", "wheel_1_joint")
    rig.run(0.5)
    rig.place_box(*rig.ahead(2.0, 0.8))
    rig.run(6.0)
    assert rig.heading() < -0.05  # the box is on the left; the swapped wheels turn right


def test_after_a_world_reset_it_starts_over(robot, rig_factory):
    rig = rig_factory(robot, None)
    rig.run(0.5)
    rig.place_box(*rig.ahead(1.5, 0.0))
    rig.run(3.0)
    moved = rig.camera()[0]
    rig.server.reset(time_too=False)
    assert rig.plugin.command == (0.0, 0.0) and rig.plugin.depth is None
    assert rig.camera()[0] < moved - 0.2
    rig.run(1.0)  # the box went back to where it was spawned, out of sight
    assert rig.plugin.depth is not None and rig.plugin.nearest is None
    assert rig.speed() < 0.01
    rig.place_box(*rig.ahead(1.5, 0.0))
    rig.run(2.0)
    assert rig.speed() > 0.05


def _spawn_with_follower(model_name: str, caplog) -> SimServer:
    model = load_sim_model(model_name)
    model.plugins = [
        PluginSpec(
            "follower",
            "libFollowerPlugin.so",
            '<plugin name="follower" filename="libFollowerPlugin.so"/>',
            "model",
        )
    ]
    server = SimServer(World(**SERVER_PHYSICS), real_time_factor=0)
    with caplog.at_level(logging.ERROR):
        server.spawn(model, [0.0, 0.0, 0.0])
    return server


def test_without_a_depth_camera_the_plugin_is_not_loaded(caplog):
    server = _spawn_with_follower("two_wheeled_robot", caplog)
    try:
        assert server.plugins == []
        assert "follower' not loaded" in caplog.text and "depth sensor not found" in caplog.text
    finally:
        server.stop()


def test_the_shipped_model_has_the_database_camera():
    from workbench.sim.sensors import parse_sensor

    model = load_sim_model(ROBOT)
    [(link, xml)] = model.sensors
    spec = parse_sensor(xml, model=ROBOT, link=link)
    assert (link, spec.type, spec.width, spec.height) == ("depth_camera", "depth", 320, 240)
    assert (spec.horizontal_fov, spec.near, spec.far) == (1.047, 0.1, 100.0)
    assert (spec.update_rate, spec.always_on) == (30.0, True)
    assert [(p.name, p.filename) for p in model.plugins] == [("follower", "libFollowerPlugin.so")]
    server = SimServer(World(**SERVER_PHYSICS), real_time_factor=0)
    try:
        server.spawn(model, [0.0, 0.0, 0.0])
        [plugin] = server.plugins
        server.run(until=0.1)
        assert plugin.depth.shape == (240, 320) and plugin.nearest is None
    finally:
        server.stop()


def test_in_the_follower_world_the_shipped_robot_drives_up_to_the_box():
    from workbench.sim.gzserver import ServerOptions, build_server
    from workbench.sim.world_file import shipped_worlds

    assert "follower" in shipped_worlds()
    world, server, _ = build_server(ServerOptions(world="follower", view=False, fast=True))
    try:
        server.spawn(load_sim_model(ROBOT), [0.0, 0.0, 0.0])  # step 29, at the origin
        [plugin] = server.plugins
        server.run(until=20.0)  # step 30
        assert plugin.command == (0.0, 0.0) and plugin.nearest is not None
        assert 0.3 < plugin.nearest[1] < STOP_DISTANCE
        X = world.get_model_pose(ROBOT)
        assert X.translation()[0] > 0.8 and X.rotation().ToRollPitchYaw().yaw_angle() > 0.1
        assert world.get_model_pose("obstacle").translation()[:2] == pytest.approx([2.65, 0.5])
    finally:
        server.stop()
