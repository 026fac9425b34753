"""CostmapROS inside a real node on the in-process bus: the lab's pre-Hydro parameters,
a /map, laser scans and tf in, nav_msgs/OccupancyGrid and the footprint out."""

from __future__ import annotations

import math
import threading
import time

import numpy as np
import pytest
from costmap_world import (
    GLOBAL_PARAMS,
    ORIGIN,
    RESOLUTION,
    WALL_COLUMN,
    World,
    set_params,
)
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import PolygonStamped
from workbench.msgs.nav_msgs import OccupancyGrid
from workbench.navigation.costmap_errors import CostmapError
from workbench.navigation.costmap_ros import CostmapROS
from workbench.tf import Buffer, TransformListener

NS = "/move_base/global_costmap"


@pytest.fixture
def bus():
    bus = Bus()
    yield bus
    bus.shutdown()


class Setup:
    """move_base's node with a tf listener, the world, and a watcher of the topics."""

    def __init__(self, bus, name: str = "global_costmap") -> None:
        self.bus = bus
        self.node = Node("move_base", bus=bus, disable_rosout=True)
        self.buffer = Buffer()
        TransformListener(self.buffer, self.node)
        self.world = World(bus)
        self.world.publish_static()
        self.world.publish_map()
        self.grids: list[OccupancyGrid] = []
        self.footprints: list[PolygonStamped] = []
        watcher = Node("watcher", bus=bus, disable_rosout=True)
        watcher.create_subscription(f"/move_base/{name}/costmap", OccupancyGrid, self.grids.append)
        watcher.create_subscription(
            f"/move_base/{name}/footprint", PolygonStamped, self.footprints.append
        )
        self.name = name
        self.costmap: CostmapROS | None = None

    def start(self) -> CostmapROS:
        self.place(0.0, 0.0, 0.0)
        self.costmap = CostmapROS(self.node, self.name, self.buffer, start_timers=False)
        return self.costmap

    def place(self, x: float, y: float, yaw: float):
        stamp = self.node.now()
        self.world.publish_pose(x, y, yaw, stamp)
        assert wait_for(lambda: self.buffer.can_transform("odom", "base_link", stamp))
        return stamp

    def scan(self, ranges, stamp) -> None:
        self.world.scan_pub.publish(self.world.scan(ranges, stamp))

    def cycle(self, x: float = 0.0, y: float = 0.0, yaw: float = 0.0, ranges=None):
        stamp = self.place(x, y, yaw)
        if ranges is not None:
            self.scan(ranges, stamp)
        n = len(self.grids)
        assert self.costmap is not None
        self.costmap.update()
        self.costmap.publish()
        assert wait_for(lambda: len(self.grids) > n)
        grid = self.grids[-1]
        return np.asarray(grid.data).reshape(grid.info.height, grid.info.width)


def cell(grid: OccupancyGrid, x: float, y: float) -> tuple[int, int]:
    """(row, column) of a world point in a published grid (of the costmap's resolution: the
    message's float32 resolution would truncate 62.0 cells to 61)."""
    origin = grid.info.origin.position
    return int((y - origin.y) / RESOLUTION), int((x - origin.x) / RESOLUTION)


def test_the_labs_pre_hydro_keys_become_costmap_2ds_layers(bus, capsys):
    set_params(bus, NS, {**GLOBAL_PARAMS, "track_unknown_space": True})
    set_params(bus, "/move_base/local_costmap", {**GLOBAL_PARAMS, "static_map": False})
    s = Setup(bus)
    s.start()
    p = bus.params
    assert p.get(f"{NS}/plugins") == [
        {"name": "static_layer", "type": "costmap_2d::StaticLayer"},
        {"name": "obstacle_layer", "type": "costmap_2d::ObstacleLayer"},
        {"name": "inflation_layer", "type": "costmap_2d::InflationLayer"},
    ]
    # moved (deleted at the top) as loadOldParameters moves them
    assert p.get(f"{NS}/obstacle_layer/obstacle_range") == 2.5
    assert p.get(f"{NS}/obstacle_layer/raytrace_range") == 3.0
    assert p.get(f"{NS}/obstacle_layer/observation_sources") == "laser_scan_sensor"
    assert p.get(f"{NS}/obstacle_layer/laser_scan_sensor/topic") == "scan"
    assert p.get(f"{NS}/inflation_layer/inflation_radius") == 0.55
    for key in (
        "obstacle_range",
        "raytrace_range",
        "observation_sources",
        "laser_scan_sensor",
        "inflation_radius",
    ):
        assert not p.has(f"{NS}/{key}"), key
    # track_unknown_space: kept at the top for the static layer, moved for the obstacles
    assert p.get(f"{NS}/static_layer/track_unknown_space") is True
    assert p.get(f"{NS}/obstacle_layer/track_unknown_space") is True
    # the footprint is written back as costmap_2d writes it
    assert p.get(f"{NS}/footprint") == "[[0.2,0.2],[-0.2,0.2],[-0.2,-0.2],[0.2,-0.2]]"
    out = capsys.readouterr()
    assert 'global_costmap: Parameter "plugins" not provided, loading pre-Hydro parameters' in (
        out.out + out.err
    )
    assert 'global_costmap: Using plugin "static_layer"' in out.out
    data = s.cycle()
    assert (data[0:10, 0:10] == -1).all() and data[10, 10] == 0  # unknown tracked throughout
    local = CostmapROS(s.node, "local_costmap", s.buffer, start_timers=False)
    assert [layer.name for layer in local.layered.layers] == ["obstacle_layer", "inflation_layer"]


def test_a_plugins_list_is_used_and_pre_hydro_keys_beside_it_are_named(bus, capsys):
    set_params(
        bus,
        NS,
        {
            "plugins": [{"name": "inflater", "type": "costmap_2d::InflationLayer"}],
            "static_map": True,
            "inflation_radius": 0.3,
        },
    )
    costmap = Setup(bus).start()
    assert [layer.name for layer in costmap.layered.layers] == ["inflater"]
    assert costmap.layer("inflater").inflation_radius == 0.3  # copyParentParameters
    assert bus.params.get(f"{NS}/inflation_radius") == 0.3  # copied, not moved
    out = capsys.readouterr()
    assert (
        'global_costmap: Pre-Hydro parameter "static_map" unused since "plugins" is provided'
        in (out.err + out.out)
    )


def test_map_scan_and_tf_give_costmap_2ds_published_costs(bus):
    set_params(bus, NS, {**GLOBAL_PARAMS, "publish_frequency": 1.0})
    s = Setup(bus)
    costmap = s.start()
    assert costmap.inscribed_radius == pytest.approx(0.21)  # 0.2 + footprint_padding 0.01
    assert costmap.circumscribed_radius == pytest.approx(0.21 * math.sqrt(2))
    ranges = [1.025] + [math.inf] * 359  # beam 0 hits 1.025 m ahead of the laser: x = 1.125
    data = s.cycle(ranges=ranges)
    msg = s.grids[-1]
    assert msg.header.frame_id == "map"
    assert (msg.info.width, msg.info.height) == (80, 80)
    assert (msg.info.origin.position.x, msg.info.origin.position.y) == pytest.approx(ORIGIN)
    row = data[40]  # y = 0.0 .. 0.05
    wall = WALL_COLUMN
    assert row[wall] == 100 and (data[:, wall] == 100).all()
    hit = cell(msg, 1.125, 0.0)
    assert hit == (40, 62)
    assert data[hit] == 100

    # left of the hit: 4 cells within the inscribed radius (4 * 0.05 <= 0.21), then decay
    def translated(d):
        c = int(252 * math.exp(-10.0 * (d * RESOLUTION - 0.21)))
        return 0 if c == 0 else 1 + 97 * (c - 1) // 251

    assert row[hit[1] - 4 : hit[1]].tolist() == [99] * 4
    assert row[hit[1] - 8 : hit[1] - 4].tolist() == [translated(d) for d in (8, 7, 6, 5)]
    # ceil(0.55 / 0.05) = 11 cells are inflated, no further
    assert row[hit[1] - 11] == translated(11) > 0 and row[hit[1] - 12] == 0
    # the unknown block of the map: the static layer has it unknown, but the obstacle layer
    # (track_unknown_space false: free cells) raises unknown master cells to its free cost
    assert (data[0:10, 0:10] == 0).all()
    assert data[cell(msg, 0.0, -1.0)] == 0
    # the footprint, padded, at the robot in the map frame
    assert wait_for(lambda: len(s.footprints) >= 1)
    fp = s.footprints[-1]
    assert fp.header.frame_id == "map"
    points = sorted((round(p.x, 6), round(p.y, 6)) for p in fp.polygon.points)
    assert points == [(-0.21, -0.21), (-0.21, 0.21), (0.21, -0.21), (0.21, 0.21)]

    # The obstacle moves away: the ray clears its old cell, the new one is marked.
    data = s.cycle(ranges=[1.325] + [math.inf] * 359)  # x = 1.425: cell 68
    assert data[hit] == translated(6)  # only the new hit 6 cells away inflates it now
    assert data[40, 68] == 100
    # Max-range readings do not clear (laser_geometry drops them): the new hit stays.
    data = s.cycle(ranges=[3.5] * 360)
    assert data[40, 68] == 100


def test_the_rolling_window_follows_the_robot_and_keeps_what_it_saw(bus):
    ns = "/move_base/local_costmap"
    set_params(
        bus,
        ns,
        {
            **GLOBAL_PARAMS,
            "global_frame": "odom",
            "static_map": False,
            "rolling_window": True,
            "width": 2.0,
            "height": 2,
            "resolution": 0.05,
        },
    )
    s = Setup(bus, "local_costmap")
    costmap = s.start()
    data = s.cycle(0.0, 0.0, 0.0, ranges=[0.625] + [math.inf] * 359)  # obstacle at x = 0.725
    msg = s.grids[-1]
    assert msg.header.frame_id == "odom" and (msg.info.width, msg.info.height) == (40, 40)
    # origin: robot - (40 - 0.5) * 0.05 / 2, moved in whole cells from 0: -19 cells
    assert (msg.info.origin.position.x, msg.info.origin.position.y) == pytest.approx((-0.95, -0.95))
    assert data[cell(msg, 0.725, 0.0)] == 100
    data = s.cycle(0.4, 0.5, 0.0)  # no new scan: the obstacle stays where it was in odom
    msg = s.grids[-1]
    # x: int((0.4 - 0.9875 + 0.95) / 0.05) = 7 cells; y: int((0.5 - 0.9875 + 0.95) / 0.05) = 9
    assert (msg.info.origin.position.x, msg.info.origin.position.y) == pytest.approx((-0.6, -0.5))
    assert data[cell(msg, 0.725, 0.0)] == 100
    assert costmap.costmap().origin_x == pytest.approx(-0.6)
    data = s.cycle(3.0, 0.5, 0.0)  # far away: the obstacle left the window
    assert (data == 100).sum() == 0


def test_reset_and_clearing_outside_a_square(bus):
    set_params(bus, NS, GLOBAL_PARAMS)
    s = Setup(bus)
    costmap = s.start()
    ranges = [math.inf] * 360
    ranges[0], ranges[90], ranges[180] = 0.525, 1.225, 0.925  # x 0.625; y 1.225; x -0.825
    s.cycle(ranges=ranges)
    obstacles = costmap.layer("obstacle_layer").grid.costs
    assert (obstacles == 254).sum() == 3
    costmap.clear_outside(0.75)  # keeps cells strictly inside the 1.5 m square
    kept = np.argwhere(obstacles == 254).tolist()
    assert kept == [[40, 52]]  # (0.6, 0.0)
    assert obstacles[0, 0] == 255  # the rest is unknown now
    costmap.reset_layers()
    assert (costmap.layer("obstacle_layer").grid.costs == 254).sum() == 0
    data = s.cycle()
    assert (data[:, WALL_COLUMN] == 100).all() and (data == 100).sum() == 80  # the map stays


def test_a_silent_source_makes_the_costmap_not_current(bus, capsys):
    params = {**GLOBAL_PARAMS}
    params["laser_scan_sensor"] = {**params["laser_scan_sensor"], "expected_update_rate": 0.05}
    set_params(bus, NS, params)
    s = Setup(bus)
    costmap = s.start()
    stamp = s.place(0, 0, 0)
    s.scan([1.0] * 360, stamp)
    costmap.update()
    assert costmap.is_current()
    assert wait_for(lambda: s.node.now().to_sec() - stamp.to_sec() > 0.2)
    s.place(0, 0, 0)
    costmap.update()
    assert not costmap.is_current()
    assert "The scan observation buffer has not been updated for" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("key", "value", "message"),
    [
        (
            "inflation_radius",
            "wide",
            f"parameter {NS}/inflation_layer/inflation_radius must be a number, got 'wide'",
        ),
        ("width", "ten", f"parameter {NS}/width must be an integer, got 'ten'"),
        ("update_frequency", True, f"parameter {NS}/update_frequency must be a number, got True"),
        (
            "rolling_window",
            "yes",
            f"parameter {NS}/rolling_window must be true or false, got 'yes'",
        ),
        ("global_frame", 3, f"parameter {NS}/global_frame must be a string, got 3"),
        ("footprint", [[0.2, 0.2], [0.1]], f"parameter {NS}/footprint is not a polygon"),
        ("footprint", "[[1, 2], [3, 4]]", f"parameter {NS}/footprint is not a polygon"),
        ("observation_sources", 5, f"parameter {NS}/observation_sources must be a string, got 5"),
        (
            "laser_scan_sensor",
            {"data_type": "Sonar"},
            f"parameter {NS}/obstacle_layer/laser_scan_sensor/data_type is 'Sonar'",
        ),
        (
            "laser_scan_sensor",
            {"marking": "on"},
            f"parameter {NS}/obstacle_layer/laser_scan_sensor/marking must be true or false",
        ),
        ("plugins", "static", f"parameter {NS}/plugins must be a list"),
        (
            "plugins",
            [{"name": "x", "type": "rtabmap_ros::StaticLayer"}],
            "names the layer type 'rtabmap_ros::StaticLayer'",
        ),
        ("robot_radius", "big", None),  # a footprint is given: robot_radius is not read
    ],
)
def test_wrong_parameters_are_one_line_errors_naming_them(bus, key, value, message):
    set_params(bus, NS, {**GLOBAL_PARAMS, key: value})
    s = Setup(bus)
    if message is None:
        s.start()
        return
    with pytest.raises(CostmapError) as error:
        s.start()
    text = str(error.value)
    assert "\n" not in text and message in text, text


def test_robot_radius_is_searched_upwards_and_padded(bus):
    params = {k: v for k, v in GLOBAL_PARAMS.items() if k != "footprint"}
    set_params(bus, NS, params)
    bus.params.set("/move_base/robot_radius", 0.105)
    costmap = Setup(bus).start()
    assert len(costmap.footprint) == 16
    assert costmap.footprint[0] == pytest.approx((0.115, 0.0))
    # the diagonal vertices move 0.01 along x and y: 0.105 + 0.01 * sqrt(2)
    assert costmap.circumscribed_radius == pytest.approx(0.105 + 0.01 * math.sqrt(2))
    bus.params.set("/move_base/robot_radius", "big")
    with pytest.raises(CostmapError, match="parameter /move_base/robot_radius must be a number"):
        CostmapROS(costmap.node, "global_costmap", costmap.tf_buffer, start_timers=False)


def test_the_timers_update_and_publish_on_the_bus_clock(bus):
    set_params(bus, NS, {**GLOBAL_PARAMS, "update_frequency": 20.0, "publish_frequency": 5.0})
    s = Setup(bus)
    s.place(0.0, 0.0, 0.0)
    costmap = CostmapROS(s.node, "global_costmap", s.buffer)  # timers on
    try:
        stop = []

        def keep_placing():
            while not stop:
                s.world.publish_pose(0.0, 0.0, 0.0, s.node.now())
                time.sleep(0.02)

        thread = threading.Thread(target=keep_placing, daemon=True)
        thread.start()
        assert wait_for(lambda: len(s.grids) >= 3, timeout=10.0)
        assert wait_for(lambda: len(s.footprints) >= 3 * len(s.grids) // 2, timeout=10.0)
        stamps = [g.header.stamp.to_sec() for g in s.grids[:3]]
        assert all(b - a >= 0.19 for a, b in zip(stamps[:-1], stamps[1:], strict=True))
        assert (np.asarray(s.grids[-1].data).reshape(80, 80)[:, WALL_COLUMN] == 100).all()
    finally:
        stop.append(True)
        costmap.shutdown()


def test_a_rolling_window_samples_the_static_map_through_tf(bus):
    ns = "/move_base/local_costmap"
    set_params(
        bus,
        ns,
        {
            "global_frame": "odom",
            "robot_base_frame": "base_link",
            "rolling_window": True,
            "width": 1,
            "height": 1,
            "resolution": 0.05,
            "plugins": [{"name": "static", "type": "costmap_2d::StaticLayer"}],
        },
    )
    s = Setup(bus, "local_costmap")
    s.start()
    data = s.cycle(1.2, 0.0, 0.0)  # the wall (x 1.5 .. 1.55) is 0.3 m ahead
    msg = s.grids[-1]
    assert (msg.info.width, msg.info.height) == (20, 20)
    column = cell(msg, 1.525, 0.0)[1]
    assert (data[:, column] == 100).all() and (data == 100).sum() == 20
    data = s.cycle(0.0, 0.0, 0.0)  # the wall left the window
    assert (data == 100).sum() == 0


def test_a_scan_waits_for_its_transform_and_keeps_only_the_newest(bus):
    set_params(bus, NS, GLOBAL_PARAMS)
    s = Setup(bus)
    costmap = s.start()
    first = s.place(0.0, 0.0, 0.0)
    later = Time.from_sec(first.to_sec() + 0.05)
    ranges = [math.inf] * 360
    ranges[90] = 0.725  # y = 0.725 from where the robot will be at `later`
    s.scan(ranges, later)
    costmap.update()
    obstacles = costmap.layer("obstacle_layer")
    assert (obstacles.grid.costs == 254).sum() == 0  # no transform at that stamp yet
    s.world.publish_pose(0.5, 0.0, 0.0, later)
    assert wait_for(lambda: s.buffer.can_transform("odom", "base_link", later))
    costmap.update()
    assert np.argwhere(obstacles.grid.costs == 254).tolist() == [[54, 52]]  # (0.6, 0.725)


def test_a_scan_waits_for_its_transform_under_a_moving_parent_of_the_global_frame(bus, capsys):
    # amcl's map -> odom above a local costmap in odom: tf2 explains the scan that came before
    # its odometry by that link ("only time ... is in the buffer"); the scan still waits
    from costmap_world import transform

    from workbench.msgs.tf2_msgs import TFMessage

    set_params(bus, NS, GLOBAL_PARAMS)
    s = Setup(bus)
    costmap = s.start()
    first = s.place(0.0, 0.0, 0.0)
    above = transform("earth", "map", (0, 0, 0), 0.0, first)
    s.world.tf_pub.publish(TFMessage(transforms=[above]))
    assert wait_for(lambda: s.buffer.can_transform("earth", "base_link", first))
    later = Time.from_sec(first.to_sec() + 0.05)
    ranges = [math.inf] * 360
    ranges[90] = 0.725
    s.scan(ranges, later)
    costmap.update()
    obstacles = costmap.layer("obstacle_layer")
    assert (obstacles.grid.costs == 254).sum() == 0
    s.world.publish_pose(0.5, 0.0, 0.0, later)
    assert wait_for(lambda: s.buffer.can_transform("odom", "base_link", later))
    costmap.update()
    assert np.argwhere(obstacles.grid.costs == 254).tolist() == [[54, 52]]
    assert "Message dropped" not in capsys.readouterr().err


def test_a_scan_arriving_during_an_update_does_not_wait_for_it(bus):
    # the scan callback runs on the thread that delivers messages (Zenoh's, for another
    # process): waiting there for a long update would hold up /tf and /clock as well
    set_params(bus, NS, GLOBAL_PARAMS)
    s = Setup(bus)
    costmap = s.start()
    stamp = s.place(0.5, 0.0, 0.0)
    ranges = [math.inf] * 360
    ranges[90] = 0.725
    update_running, update_done = threading.Event(), threading.Event()

    def long_update() -> None:
        with costmap._lock:
            update_running.set()
            update_done.wait(60.0)

    updater = threading.Thread(target=long_update)
    updater.start()
    try:
        assert update_running.wait(10.0)
        publisher = threading.Thread(target=s.scan, args=(ranges, stamp))
        publisher.start()
        assert wait_for(lambda: not publisher.is_alive(), 10.0)
    finally:
        update_done.set()
        updater.join()
    costmap.update()  # the next update places the scan
    obstacles = costmap.layer("obstacle_layer")
    assert np.argwhere(obstacles.grid.costs == 254).tolist() == [[54, 52]]


def test_map_type_voxel_becomes_a_voxel_layer_read_as_obstacles(bus, capsys):
    set_params(bus, NS, {**GLOBAL_PARAMS, "map_type": "voxel", "z_voxels": 10})
    costmap = Setup(bus).start()
    assert bus.params.get(f"{NS}/plugins")[1] == {
        "name": "obstacle_layer",
        "type": "costmap_2d::VoxelLayer",
    }
    assert bus.params.get(f"{NS}/obstacle_layer/z_voxels") == 10
    assert costmap.layer("obstacle_layer").buffers[0].topic == "scan"
    assert "obstacle_layer is read as a costmap_2d::ObstacleLayer" in capsys.readouterr().err


def test_a_map_whose_data_does_not_fit_its_size_is_refused_with_one_line(bus, capsys):
    from costmap_world import map_message

    set_params(bus, NS, GLOBAL_PARAMS)
    s = Setup(bus)
    costmap = s.start()
    bad = map_message(s.node.now())
    bad.info.width = 81
    s.world.map_pub.publish(bad)
    assert wait_for(lambda: "the map on map has 6400 cells" in capsys.readouterr().err)
    data = s.cycle()
    assert data.shape == (80, 80) and (data[:, WALL_COLUMN] == 100).all()  # the old map stays
    assert costmap.costmap().size_x == 80
