"""Occupancy grid: log-odds ray updates and the nav_msgs/OccupancyGrid layout."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import MappingError
from workbench.mapping import GridMap, OccupancyGrid
from workbench.mapping.simulate import box_segments, raycast


def _room_scan(pose, max_range=10.0):
    """A 360-beam scan of a 4 m x 4 m room with corners (0, 0) and (4, 4)."""
    angles = np.linspace(-np.pi, np.pi, 720, endpoint=False)
    return raycast(box_segments(0.0, 0.0, 4.0, 4.0), np.asarray(pose), angles, max_range), angles


def test_room_scan_marks_walls_occupied_inside_free_outside_unknown():
    grid = OccupancyGrid(100, 100, 0.05, (-0.5, -0.5, 0.0))
    ranges, angles = _room_scan([2.0, 2.0, 0.3])
    for _ in range(3):
        grid.integrate_scan(np.array([2.0, 2.0, 0.3]), ranges, angles)
    msg = grid.to_map()
    cell = msg.world_to_cell(np.array([[2.0, 1.0], [3.9, 2.0], [4.02, 2.0], [4.3, 2.0]]))
    inside, near_wall, wall, outside = (int(msg.data[iy, ix]) for ix, iy in cell)
    assert inside <= 25  # free after three misses (log-odds -1.2, 23 %)
    assert near_wall <= 25
    assert wall >= 65
    assert outside == -1  # beyond the wall: never observed
    # Every wall cell along x = 4 between y = 0.5 and 3.5 is occupied.
    ys = np.arange(0.5, 3.5, 0.05)
    cells = msg.world_to_cell(np.column_stack([np.full_like(ys, 4.01), ys]))
    assert np.all(msg.data[cells[:, 1], cells[:, 0]] >= 65)


def test_invalid_readings_mark_nothing():
    grid = OccupancyGrid(40, 40, 0.1, (-2.0, -2.0, 0.0))
    ranges = np.array([np.nan, np.inf, -np.inf, 0.0, 5.0, 1.0])
    angles = np.array([0.0, 0.5, 1.0, 1.5, 2.0, -1.0])
    grid.integrate_scan(np.zeros(3), ranges, angles, max_range=5.0, min_range=0.0)
    # Only the last beam (1 m at -1 rad) is real: its end cell and its path are observed.
    assert grid.observed.sum() == pytest.approx(11, abs=2)
    end = np.array([[np.cos(-1.0), np.sin(-1.0)]]) * 0.99
    ix, iy = grid.to_map().world_to_cell(end)[0]
    assert grid.observed[iy, ix]
    # Nothing along the max-range beam at 2 rad.
    ix, iy = grid.to_map().world_to_cell(np.array([[np.cos(2.0), np.sin(2.0)]]))[0]
    assert not grid.observed[iy, ix]


def test_origin_is_the_corner_of_cell_zero_and_data_is_row_major():
    grid = GridMap(np.arange(12, dtype=np.int8).reshape(3, 4), 0.5, (1.0, 2.0, 0.0))
    assert grid.width == 4 and grid.height == 3
    # Cell (ix=1, iy=2) holds data[2 * width + 1] in the flat message.
    assert grid.flat()[2 * 4 + 1] == grid.data[2, 1] == 9
    np.testing.assert_allclose(grid.cell_to_world(np.array([[0, 0]])), [[1.25, 2.25]])
    np.testing.assert_array_equal(
        grid.world_to_cell(np.array([[1.01, 2.01], [2.9, 3.4]])), [[0, 0], [3, 2]]
    )
    again = GridMap.from_flat(grid.flat(), 4, 3, 0.5, grid.origin)
    np.testing.assert_array_equal(again.data, grid.data)


def test_rotated_origin_converts_points_consistently():
    grid = GridMap(np.zeros((10, 10), dtype=np.int8), 0.1, (1.0, 1.0, np.pi / 2))
    # With a 90 degree yaw, +x of the grid points along +y of the map frame.
    np.testing.assert_array_equal(grid.world_to_cell(np.array([[0.95, 1.35]])), [[3, 0]])
    centre = grid.cell_to_world(np.array([[3, 0]]))
    np.testing.assert_allclose(centre, [[0.95, 1.35]])


def test_bad_grid_arguments_raise_mapping_errors():
    with pytest.raises(MappingError, match="positive"):
        OccupancyGrid(0, 10, 0.05)
    with pytest.raises(MappingError, match="resolution"):
        OccupancyGrid(10, 10, -1.0)
    with pytest.raises(MappingError, match="width\\*height"):
        GridMap.from_flat([0, 1, 2], 2, 2, 0.1)


def test_a_grid_too_large_to_allocate_is_refused():
    with pytest.raises(MappingError, match="coarser resolution"):
        OccupancyGrid.covering(np.array([[0.0, 0.0], [1e6, 1e6]]), 0.05)
