"""The obstacle layer's marking and ray-trace clearing (ObstacleLayer::updateBounds and
raytraceFreespace, costmap_2d Noetic) and laser scans as points (laser_geometry)."""

from __future__ import annotations

import math

import numpy as np

from workbench.msgs.sensor_msgs import LaserScan
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_observation import Observation, scan_points
from workbench.navigation.costmap_obstacle import clear_rays, fill_polygon, mark_points


def lethal_grid() -> Costmap2D:
    """20 x 10 cells of 0.1 m, all lethal, origin (0, 0)."""
    return Costmap2D(np.full((10, 20), 254, np.uint8), 0.1, 0.0, 0.0, "odom")


def obs(points, origin=(0.05, 0.55, 0.2), obstacle_range=2.5, raytrace_range=3.0) -> Observation:
    return Observation(
        np.array(origin, float),
        np.array(points, float).reshape(-1, 3),
        obstacle_range,
        raytrace_range,
        0.0,
    )


def test_marking_respects_obstacle_range_and_height():
    g = Costmap2D(np.zeros((10, 20), np.uint8), 0.1, 0.0, 0.0)
    o = obs(
        [[1.05, 0.55, 0.2], [0.55, 0.15, 0.2], [1.75, 0.55, 2.5], [5.0, 0.5, 0.2]],
        obstacle_range=1.0,
    )
    # (1.05, 0.55) is 1.0 m away: not nearer than obstacle_range, not marked
    mark_points(g, o, max_obstacle_height=2.0)
    assert np.argwhere(g.costs == 254).tolist() == [[1, 5]]  # (0.55, 0.15) only
    o.obstacle_range = 2.5
    mark_points(g, o, max_obstacle_height=2.0)
    assert sorted(np.argwhere(g.costs == 254).tolist()) == [[1, 5], [5, 10]]  # 2.5 m high: no
    o.obstacle_range = 3.0  # the high point is 2.86 m away in 3-D
    mark_points(g, o, max_obstacle_height=3.0)
    assert [5, 17] in np.argwhere(g.costs == 254).tolist()


def test_a_ray_clears_its_cells_up_to_and_including_the_end_cell():
    g = lethal_grid()
    assert clear_rays(g, obs([[1.05, 0.55, 0.2]]))
    assert g.costs[5, 0:11].tolist() == [0] * 11 and g.costs[5, 11] == 254
    assert (g.costs[np.arange(10) != 5] == 254).all()


def test_raytrace_range_limits_the_cleared_cells():
    g = lethal_grid()
    clear_rays(g, obs([[1.95, 0.55, 0.2]], raytrace_range=0.42))  # ceil(4.2) = 5 cells
    assert g.costs[5].tolist() == [0] * 6 + [254] * 14


def test_rays_leaving_the_grid_are_cut_at_its_edge():
    g = lethal_grid()
    clear_rays(g, obs([[5.0, 0.55, 0.2], [0.05, -3.0, 0.2]]))
    assert (g.costs[5, :] == 0).all()  # up to the last cell (map end - 1 mm)
    assert (g.costs[0:6, 0] == 0).all()  # down to row 0


def test_a_sensor_outside_the_grid_clears_nothing():
    g = lethal_grid()
    assert not clear_rays(g, obs([[1.0, 0.5, 0.2]], origin=(-1.0, 0.5, 0.2)))
    assert (g.costs == 254).all()


def test_footprint_polygons_fill_and_refuse_to_leave_the_grid():
    g = lethal_grid()
    assert fill_polygon(g, np.array([[0.25, 0.25], [0.55, 0.25], [0.55, 0.45], [0.25, 0.45]]), 0)
    assert np.argwhere(g.costs == 0).min(axis=0).tolist() == [2, 2]
    assert np.argwhere(g.costs == 0).max(axis=0).tolist() == [4, 5]
    assert not fill_polygon(g, np.array([[-0.1, 0.1], [0.5, 0.1], [0.5, 0.5]]), 0)


def scan(ranges, range_max=3.5):
    msg = LaserScan()
    msg.angle_min, msg.angle_increment = 0.0, math.pi / 2
    msg.range_min, msg.range_max = 0.12, range_max
    msg.ranges = [float(r) for r in ranges]
    return msg


def test_scans_keep_readings_in_range_and_inf_only_when_valid():
    msg = scan([1.0, 3.5, float("inf"), 0.1])  # a hit, max range, no return, too close
    np.testing.assert_allclose(scan_points(msg), [[1.0, 0.0, 0.0]])
    points = scan_points(msg, inf_is_valid=True)
    assert points.shape == (2, 3)
    np.testing.assert_allclose(points[1], [-(3.5 - 0.0001), 0.0, 0.0], atol=1e-6)
    assert scan_points(scan([float("nan")] * 4)).shape == (0, 3)


def observation_buffer(params: dict):
    from workbench.bus import Bus, Node
    from workbench.navigation.costmap_observation import ObservationBuffer
    from workbench.navigation.costmap_params import Params

    bus = Bus()
    node = Node("move_base", bus=bus, disable_rosout=True)
    for key, value in params.items():
        bus.params.set(f"/move_base/c/obstacle_layer/{key}", value)
    source = Params(node, "/move_base/c/obstacle_layer/laser")
    return bus, ObservationBuffer("laser", source, "odom")


def tf_buffer():
    from costmap_world import transform

    from workbench.msgs import Time
    from workbench.tf import Buffer

    buffer = Buffer()
    for t in (0.0, 10.0):
        stamp = Time.from_sec(t)
        buffer.set_transform(transform("odom", "base_link", (1.0, 2.0, 0.0), math.pi / 2, stamp))
        buffer.set_transform(transform("base_link", "laser", (0.1, 0.0, 0.3), 0.0, stamp))
    return buffer


def test_observations_take_origin_heights_ranges_and_persistence_from_parameters():
    from workbench.msgs import Time

    bus, buffer = observation_buffer(
        {
            "obstacle_range": 1.5,  # searched upwards from the source
            "laser": {
                "sensor_frame": "base_link",
                "min_obstacle_height": 0.1,
                "max_obstacle_height": 0.25,
                "observation_persistence": 1.0,
            },
        }
    )
    try:
        assert (buffer.obstacle_range, buffer.raytrace_range) == (1.5, 3.0)
        msg = scan([1.0, 3.5, 2.0, 0.5])
        msg.header.frame_id = "laser"
        msg.header.stamp = Time.from_sec(1.0)
        buffer.buffer_scan(msg, tf_buffer(), now=1.0)
        (obs,) = buffer.get()
        np.testing.assert_allclose(obs.origin, [1.0, 2.0, 0.0], atol=1e-12)  # base_link
        assert obs.points.shape == (0, 3)  # the laser is 0.3 m up: above 0.25
        buffer.max_obstacle_height = 0.35
        msg.header.stamp = Time.from_sec(1.5)
        buffer.buffer_scan(msg, tf_buffer(), now=1.5)
        newest = buffer.get()[0]
        # beam 0 (1 m along the laser's x = odom's y) from the laser at (1, 2.1)
        np.testing.assert_allclose(newest.points[0], [1.0, 3.1, 0.3], atol=1e-9)
        assert len(buffer.get()) == 2  # both within observation_persistence
        msg.header.stamp = Time.from_sec(3.0)
        buffer.buffer_scan(msg, tf_buffer(), now=3.0)
        assert len(buffer.get()) == 1  # the others are more than 1 s older
    finally:
        bus.shutdown()
