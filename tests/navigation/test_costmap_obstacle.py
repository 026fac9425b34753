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
