"""Costmap2D's geometry, rolling-window moves, Bresenham ray tracing and polygon fill,
checked against costmap_2d's definitions (costmap_2d.cpp / costmap_2d.h, Noetic)."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_raytrace import convex_fill_cells, raytrace_cells


def grid(size_x: int = 10, size_y: int = 5, res: float = 0.5) -> Costmap2D:
    return Costmap2D(np.zeros((size_y, size_x), np.uint8), res, -1.0, 2.0, "odom")


def test_world_to_map_truncates_and_refuses_points_outside():
    g = grid()
    assert (g.size_x, g.size_y) == (10, 5)
    assert g.world_to_map(-1.0, 2.0) == (0, 0)
    assert g.world_to_map(-0.51, 2.49) == (0, 0)
    assert g.world_to_map(-0.5, 2.5) == (1, 1)
    assert g.world_to_map(3.99, 4.49) == (9, 4)
    assert g.world_to_map(4.0, 3.0) is None  # x end is outside
    assert g.world_to_map(-1.01, 3.0) is None
    assert g.world_to_map(0.0, 4.5) is None
    assert g.world_to_map(float("nan"), 3.0) is None
    assert g.map_to_world(0, 0) == (-0.75, 2.25)
    assert g.map_to_world(9, 4) == (3.75, 4.25)


def test_world_to_map_array_matches_the_scalar_version():
    g = grid()
    rng = np.random.default_rng(1)
    xy = rng.uniform([-2, 1], [5, 6], size=(500, 2))
    mx, my, inside = g.world_to_map_array(xy)
    for (x, y), a, b, i in zip(xy, mx, my, inside, strict=True):
        cell = g.world_to_map(float(x), float(y))
        assert (cell is not None) == bool(i)
        if cell is not None:
            assert cell == (a, b)


def test_copy_is_independent():
    g = grid()
    c = g.copy()
    c.costs[0, 0] = 254
    assert g.costs[0, 0] == 0 and c.frame == "odom" and c.resolution == g.resolution


def test_size_in_meters_is_costmap_2ds_cells_less_a_half():
    # getSizeInMetersX: (size_x - 1 + 0.5) * resolution
    assert grid().size_in_meters() == (4.75, 2.25)


def test_update_origin_moves_by_whole_cells_and_keeps_the_overlap():
    g = Costmap2D(np.arange(20, dtype=np.uint8).reshape(4, 5), 1.0, 0.0, 0.0)
    g.update_origin(2.7, -1.2, 255)  # int(2.7) = 2 cells right, int(-1.2) = -1 cell down
    assert (g.origin_x, g.origin_y) == (2.0, -1.0)
    expected = np.full((4, 5), 255, np.uint8)
    expected[1:4, 0:3] = np.arange(20).reshape(4, 5)[0:3, 2:5]
    np.testing.assert_array_equal(g.costs, expected)
    g.update_origin(2.9, -0.5, 255)  # less than a cell: nothing moves
    assert (g.origin_x, g.origin_y) == (2.0, -1.0)
    g.update_origin(100.0, 0.0, 7)  # no overlap at all
    assert (g.costs == 7).all() and g.origin_x == 100.0


def reference_line(x0: int, y0: int, x1: int, y1: int, max_length: float) -> list[tuple[int, int]]:
    """raytraceLine + bresenham2D of costmap_2d.h, step by step."""
    dx, dy = x1 - x0, y1 - y0
    adx, ady = abs(dx), abs(dy)
    ox = 1 if dx > 0 else -1
    oy = 1 if dy > 0 else -1
    dist = float(np.hypot(dx, dy))
    scale = 1.0 if dist == 0.0 else min(1.0, max_length / dist)
    if adx >= ady:
        da, db, ea, eb, error = adx, ady, (ox, 0), (0, oy), adx // 2
    else:
        da, db, ea, eb, error = ady, adx, (0, oy), (ox, 0), ady // 2
    end = min(int(scale * da), da)
    x, y = x0, y0
    cells = []
    for _ in range(end):
        cells.append((x, y))
        x, y = x + ea[0], y + ea[1]
        error += db
        if error >= da:
            x, y = x + eb[0], y + eb[1]
            error -= da
    cells.append((x, y))
    return cells


@pytest.mark.parametrize("max_length", [np.inf, 7, 3, 0])
def test_raytrace_cells_match_costmap_2ds_bresenham(max_length):
    rng = np.random.default_rng(2)
    x0, y0 = 20, 25
    ends = rng.integers(0, 50, size=(200, 2))
    ends[:4] = [[20, 25], [40, 25], [20, 0], [45, 24]]  # a point, axis-aligned, near-flat
    xs, ys = raytrace_cells(x0, y0, ends[:, 0], ends[:, 1], max_length)
    expected = [c for e in ends for c in reference_line(x0, y0, int(e[0]), int(e[1]), max_length)]
    assert list(zip(xs.tolist(), ys.tolist(), strict=True)) == expected


def test_convex_fill_covers_the_polygon_columns():
    xs, ys = convex_fill_cells(np.array([2, 6, 6, 2]), np.array([1, 1, 4, 4]))
    cells = set(zip(xs.tolist(), ys.tolist(), strict=True))
    assert cells == {(x, y) for x in range(2, 7) for y in range(1, 5)}
    xs, ys = convex_fill_cells(np.array([0, 4, 0]), np.array([0, 0, 4]))
    cells = set(zip(xs.tolist(), ys.tolist(), strict=True))
    assert (0, 0) in cells and (0, 4) in cells and (4, 0) in cells and (2, 2) in cells
    assert (3, 3) not in cells and (4, 1) not in cells
    assert convex_fill_cells(np.array([1, 2]), np.array([1, 2]))[0].size == 0
