"""navfn's planning on small grids: costs, obstacles, unknown space, the goal tolerance
search of NavfnROS::makePlan, and the baseline A* finding paths of the same cost."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.navigation.astar_baseline import astar
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.navfn import goal_window, navfn_plan, path_length
from workbench.navigation.navfn_grid import POT_HIGH, cell_costs, path_cells, potential


def free(size_x: int = 20, size_y: int = 10) -> Costmap2D:
    return Costmap2D(np.zeros((size_y, size_x), np.uint8), 0.1, 0.0, 0.0, "map")


def path_cost(cells, cost) -> float:
    return sum(
        math.hypot(b[0] - a[0], b[1] - a[1]) * cost[b[1], b[0]]
        for a, b in zip(cells[:-1], cells[1:], strict=True)
    )


def test_navfn_cell_costs():
    costs = np.array([[0, 1, 100, 252, 253, 254, 255]] * 3, np.uint8)
    costs = np.pad(costs, 1)  # the outer ring is always an obstacle
    c = cell_costs(costs, allow_unknown=True)
    # 50 + 0.8 c, truncated, at most 253; 253 and 254 obstacles; unknown 253 when allowed
    assert c[1, 1:8].tolist() == [50, 50, 130, 251, math.inf, math.inf, 253]
    assert cell_costs(costs, allow_unknown=False)[1, 7] == math.inf
    assert np.isinf(c[0]).all() and np.isinf(c[:, 0]).all() and np.isinf(c[:, -1]).all()


def test_a_straight_plan_runs_through_cell_centres_to_the_goal():
    path = navfn_plan(free(), (0.55, 0.55), (1.52, 0.57))
    assert path[0] == pytest.approx((0.55, 0.55))
    assert path[-2] == pytest.approx((1.55, 0.55))  # the goal's cell
    assert path[-1] == (1.52, 0.57)  # and the goal itself, as navfn appends it
    assert len(path) == 12
    assert all(y == pytest.approx(0.55) for _, y in path[:-1])


def test_plans_go_around_walls_through_the_gap_and_not_between_corners():
    cm = free(20, 20)
    cm.costs[:, 10] = 254
    cm.costs[15, 10] = 0  # a gap at y = 1.55
    path = navfn_plan(cm, (0.55, 0.55), (1.55, 0.55))
    cells = [cm.world_to_map(x, y) for x, y in path]
    assert (10, 15) in cells
    assert all(cm.costs[my, mx] == 0 for mx, my in cells)
    # two obstacles touching at a corner close the gap for an 8-connected step too
    cm.costs[15, 10] = 254
    cm.costs[14, 10] = 0
    cm.costs[15, 11] = 0
    cm.costs[14, 11] = 254
    assert navfn_plan(cm, (0.55, 0.55), (1.55, 0.55)) == []


def test_costs_push_the_path_away_from_expensive_cells():
    cm = free(30, 11)
    cm.costs[3:8, 10:20] = 200  # an expensive patch on the straight line
    path = navfn_plan(cm, (0.55, 0.55), (2.55, 0.55))
    assert not any(cm.costs[cm.world_to_map(x, y)[::-1]] for x, y in path)
    assert path_length(path) > 2.0


def test_a_goal_in_an_obstacle_or_off_the_map_has_no_plan_without_tolerance():
    cm = free()
    cm.costs[5, 15] = 253  # inscribed counts as an obstacle
    assert navfn_plan(cm, (0.55, 0.55), (1.55, 0.55)) == []
    assert navfn_plan(cm, (0.55, 0.55), (5.0, 0.5)) == []
    assert navfn_plan(cm, (-1.0, 0.5), (1.0, 0.5)) == []
    assert navfn_plan(cm, (0.55, 0.55), (1.95, 0.55)) == []  # the border ring


def test_the_tolerance_finds_the_nearest_reachable_point_of_the_goal_window():
    cm = free()
    cm.costs[3:8, 13:18] = 254  # the goal (1.52, 0.53) sits in a 5 x 5 block
    goal = (1.52, 0.53)
    path = navfn_plan(cm, (0.55, 0.55), goal, tolerance=0.3)
    end = path[-1]
    # navfn's window: x, y from goal - 0.3 in steps of 0.1 while <= goal + 0.3 (adding up
    # 0.1 six times to 1.22 overshoots 1.82 by a rounding error: six columns, seven rows)
    wx, wy = goal_window(goal, 0.3, 0.1)
    assert wx.shape == (7, 6)
    legal = [
        (x, y)
        for x, y in zip(wx.ravel(), wy.ravel(), strict=True)
        if cm.world_to_map(x, y) is not None
        and cm.costs[cm.world_to_map(x, y)[::-1]] == 0
        and 0 < cm.world_to_map(x, y)[1] < 9
    ]
    nearest = min(legal, key=lambda p: (p[0] - goal[0]) ** 2 + (p[1] - goal[1]) ** 2)
    assert end == pytest.approx(nearest)
    assert math.dist(end, goal) == pytest.approx(0.3)  # just outside the block
    assert navfn_plan(cm, (0.55, 0.55), goal, tolerance=0.1) == []  # too small a window


def test_unknown_space_is_crossed_only_when_allowed():
    cm = free()
    cm.costs[:, 10] = 255
    assert navfn_plan(cm, (0.55, 0.55), (1.55, 0.55), allow_unknown=True)
    assert navfn_plan(cm, (0.55, 0.55), (1.55, 0.55), allow_unknown=False) == []


def test_the_robots_own_cell_is_cleared():
    cm = free()
    cm.costs[5, 5] = 254
    assert navfn_plan(cm, (0.55, 0.55), (1.55, 0.55))
    assert cm.costs[5, 5] == 254  # the costmap itself is not changed


@pytest.mark.parametrize("seed", range(5))
def test_dijkstra_potential_and_the_baseline_astar_find_equally_cheap_paths(seed):
    rng = np.random.default_rng(seed)
    costs = rng.choice([0, 0, 0, 50, 150, 254], size=(40, 50)).astype(np.uint8)
    start, goal = (2, 2), (45, 35)
    costs[2, 2] = costs[35, 45] = 0
    cost = cell_costs(costs)
    pot, pred = potential(cost, start)
    cells, astar_cost = astar(cost, start, goal)
    k = goal[1] * 50 + goal[0]
    assert pot[k] < POT_HIGH and cells  # these seeds have a way through
    dijkstra_cells = path_cells(pred, k, 50)
    assert dijkstra_cells[0] == start and dijkstra_cells[-1] == goal
    assert pot[k] == pytest.approx(astar_cost)
    assert path_cost(dijkstra_cells, cost) == pytest.approx(astar_cost)
    assert path_cost(cells, cost) == pytest.approx(astar_cost)
    cm = Costmap2D(costs, 0.05, 0.0, 0.0)
    a = navfn_plan(cm, cm.map_to_world(*start), cm.map_to_world(*goal), use_dijkstra=False)
    d = navfn_plan(cm, cm.map_to_world(*start), cm.map_to_world(*goal))
    assert path_length(a) == pytest.approx(path_length(d), rel=0.2)


def test_an_unreachable_goal_in_a_closed_room_stops_once_the_robots_room_is_spread(monkeypatch):
    import workbench.navigation.navfn as navfn

    cm = free(60, 60)
    cm.costs[30, :] = 254  # a wall across: the upper half cannot be reached
    calls = []
    real = navfn.potential
    monkeypatch.setattr(navfn, "potential", lambda *a: calls.append(a[2]) or real(*a))
    assert navfn_plan(cm, (0.55, 0.55), (0.55, 5.55)) == []
    assert len(calls) == 1  # the lower half was spread whole at the first limit
    cm.costs[30, :] = 0
    cm.costs[:55, 10] = 254  # a wall with a gap far up: the detour is ~ 11 m for 1 m
    calls.clear()
    path = navfn_plan(cm, (0.55, 0.55), (1.55, 0.55))
    assert path and path_length(path) > 10.0
    assert len(calls) == 2 and calls[1] == 4 * calls[0]  # spread further once


@pytest.mark.parametrize("seed", range(4))
def test_a_graph_patched_where_the_costmap_changed_equals_one_built_anew(seed):
    from workbench.navigation.navfn_grid import edge_weights, patched_weights

    rng = np.random.default_rng(seed)
    costs = rng.integers(0, 200, (60, 80)).astype(np.uint8)
    before = cell_costs(costs)
    weights = edge_weights(before)
    for y, x, h, w in ((0, 0, 3, 5), (57, 75, 3, 5), (20, 30, 4, 1), (59, 0, 1, 80)):
        changed = costs.copy()
        changed[y : y + h, x : x + w] = rng.choice([0, 120, 253, 254, 255], size=(h, w))
        after = cell_costs(changed)
        patched = patched_weights(before, weights, after)
        assert patched is not None and np.array_equal(patched, edge_weights(after))
    everything = cell_costs(np.full_like(costs, 254))
    assert patched_weights(before, weights, everything) is None  # rebuilt, not patched


def test_plans_on_a_costmap_changing_cycle_by_cycle_equal_plans_on_graphs_built_anew():
    """navfn patches its last graph in place as the costmap changes; every plan must be
    the one a fresh graph gives (nothing of an earlier costmap may leak into it)."""
    from workbench.navigation.navfn_grid import clear_graph_cache

    rng = np.random.default_rng(11)
    costs = np.zeros((60, 80), np.uint8)
    costs[20:40, 30] = 254
    plans = []
    for _ in range(12):
        costs = costs.copy()
        y, x = rng.integers(5, 55), rng.integers(5, 75)
        costs[y : y + 3, x : x + 3] = rng.choice([0, 120, 254])
        costmap = Costmap2D(costs, 0.05, 0.0, 0.0)
        plans.append((costmap, navfn_plan(costmap, (0.3, 0.3), (3.7, 2.6))))
    for costmap, plan in plans:
        clear_graph_cache()
        assert navfn_plan(costmap, (0.3, 0.3), (3.7, 2.6)) == plan
