"""base_local_planner's MapGrid and TrajectoryPlanner, vectorised: distances, rollouts, scores.

Expectations follow ``base_local_planner/src/map_grid.cpp`` and ``trajectory_planner.cpp``
(ros-planning/navigation, Noetic): 4-connected unit distances from the plan and the local
goal with lethal/inscribed/unknown cells as obstacles (cell count) and unreached cells at
cell count + 1; the step count ``int(max(|v| sim_time / sim_granularity, |w| /
angular_sim_granularity) + 0.5)``; velocities moving towards the sample within the
acceleration limits; cost ``pdist * path + gdist * goal + occdist * max cost``; -1 for a
footprint on a lethal cell or a point off the map, -2 for no way to the goal; the DWA window
of one control period; escape backwards when nothing else is legal.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.navigation.costs import INSCRIBED_INFLATED_OBSTACLE, LETHAL_OBSTACLE, NO_INFORMATION
from workbench.navigation.trajectory_map_grid import densify, distance_maps, plan_cells
from workbench.navigation.trajectory_rollout import CostGrid, RolloutParams, TrajectoryPlanner

RES = 0.05
ORIGIN = (-2.0, -2.0)


def square(half: float) -> np.ndarray:
    return np.array([[half, half], [-half, half], [-half, -half], [half, -half]])


def free(n: int = 80) -> np.ndarray:
    return np.zeros((n, n), dtype=np.uint8)


def grid_of(costs: np.ndarray) -> CostGrid:
    return CostGrid(costs, RES, *ORIGIN)


def test_densify_spacing() -> None:
    dense = densify(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.33]]), RES)
    assert np.hypot(*np.diff(dense, axis=0).T).max() <= RES + 1e-12
    assert dense[0].tolist() == [0.0, 0.0] and np.allclose(dense[-1], [1.0, 0.33])


def test_plan_cells_stop_when_the_plan_leaves_the_map() -> None:
    plan = np.array([[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [0.0, 1.0]])  # leaves at x = 2, comes back
    cells = plan_cells(free(), RES, ORIGIN, plan)
    assert cells[:, 0].max() == 79 and cells[-1, 1] == 40  # stops at the edge, never returns


def test_distances_are_four_connected_cells() -> None:
    costs = free()
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [1.0, 0.0]]))
    # plan cells along my = 40, mx 40..60; a cell 3 rows above, 5 columns past the end
    assert maps.path[43, 40] == 3.0
    assert maps.path[43, 65] == 3.0 + 5.0
    assert maps.goal_xy == pytest.approx((1.025, 0.025))
    assert maps.goal[40, 60] == 0.0 and maps.goal[40, 50] == 10.0 and maps.goal[45, 60] == 5.0
    assert maps.impossible == costs.size


def test_distances_go_around_walls_and_mark_obstacles() -> None:
    costs = free()
    costs[30:51, 55] = LETHAL_OBSTACLE  # a wall just before the goal's column
    costs[60:70, 60:70] = INSCRIBED_INFLATED_OBSTACLE
    costs[0:5, 0:5] = NO_INFORMATION
    costs[10:20, 10] = LETHAL_OBSTACLE
    costs[10, 10:20] = LETHAL_OBSTACLE
    costs[20, 10:20] = LETHAL_OBSTACLE
    costs[10:21, 20] = LETHAL_OBSTACLE  # a closed box: its inside is never reached
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [1.0, 0.0]]))
    n = costs.size
    assert maps.goal[40, 55] == n  # the wall cell itself, touched by the wavefront
    assert maps.goal[40, 54] > 6  # around the wall (straight would be 6)
    assert maps.goal[40, 54] == 11 + 6 + 11  # up to row 51, across, back down
    assert maps.goal[15, 15] == n + 1
    assert maps.goal[65, 65] == n + 1  # inside the inscribed block: unreachable
    assert maps.goal[2, 2] == n + 1


def test_cells_under_the_robot_are_not_obstacles() -> None:
    costs = free()
    costs[38:43, 38:43] = LETHAL_OBSTACLE
    under = np.zeros_like(costs, dtype=bool)
    under[38:43, 38:43] = True
    blocked = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [0.5, 0.0]]))
    freed = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [0.5, 0.0]]), under)
    assert blocked.path[40, 40] == 0.0  # a plan cell is a seed whatever its cost
    assert blocked.goal[40, 42] == costs.size and freed.goal[40, 42] == 8.0


def planner(**kw) -> TrajectoryPlanner:
    defaults = dict(holonomic_robot=False, vx_samples=5, vtheta_samples=9, dwa=False)
    defaults.update(kw)
    return TrajectoryPlanner(RolloutParams(**defaults), square(0.15))


def test_step_count_and_acceleration() -> None:
    tp = planner(acc_lim_x=1.0, sim_time=1.0, sim_granularity=0.025, angular_sim_granularity=0.1)
    poses, steps = tp.simulate(
        np.zeros(3), np.zeros(3), np.array([[0.5, 0, 0], [0, 0, 1.0], [0, 0, 0]])
    )
    assert steps.tolist() == [20, 10, 1]
    dt = 1.0 / 20
    # speeds 0.05, 0.10, ... capped at 0.5: position after step k is dt * sum of speeds
    speeds = np.minimum(np.arange(1, 20) * 1.0 * dt, 0.5)
    assert poses[0, 1:20, 0] == pytest.approx(np.cumsum(speeds) * dt)
    assert poses[1, 9, 2] == pytest.approx(sum(min(3.2 * 0.1 * k, 1.0) * 0.1 for k in range(1, 10)))


def test_cost_formula_on_a_straight_run() -> None:
    costs = free()
    costs[:, 70] = 100  # a cost band the run does not reach
    costs[38:43, 46] = 50  # crossed by the run
    tp = planner()
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.1], [1.5, 0.1]]))
    scored = tp.score(
        grid_of(costs),
        maps,
        np.zeros(3),
        np.array([0.5, 0, 0]),
        np.array([[0.5, 0, 0]]),
        (0.6, 0.8, 0.01),
    )
    end = scored.poses[0, scored.steps[0] - 1]
    mx, my = int((end[0] + 2) / RES), int((end[1] + 2) / RES)
    expected = 0.6 * maps.path[my, mx] + 0.8 * maps.goal[my, mx] + 0.01 * 50
    assert scored.cost[0] == pytest.approx(expected)


def test_illegal_and_no_way_trajectories() -> None:
    costs = free()
    costs[:, 50] = LETHAL_OBSTACLE  # a wall 0.5 m ahead across the whole map
    tp = planner()
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [-1.0, 0.0]]))
    scored = tp.score(
        grid_of(costs),
        maps,
        np.zeros(3),
        np.zeros(3),
        np.array([[0.5, 0, 0], [-0.1, 0, 0]]),
        (0.6, 0.8, 0.01),
    )
    assert scored.cost[0] == -1.0 and scored.cost[1] >= 0
    # an unreachable pocket: beyond a wall the plan cannot get past, there is no way
    costs2 = free()
    costs2[:, 55] = LETHAL_OBSTACLE
    maps2 = distance_maps(costs2, RES, ORIGIN, np.array([[1.5, 0.0], [1.9, 0.0]]))
    s2 = tp.score(
        grid_of(costs2), maps2, np.zeros(3), np.zeros(3), np.array([[0.2, 0, 0]]), (0.6, 0.8, 0.01)
    )
    assert s2.cost[0] == -2.0


def test_off_the_map_is_illegal() -> None:
    tp = planner()
    maps = distance_maps(free(), RES, ORIGIN, np.array([[1.9, 0.0], [3.0, 0.0]]))
    s = tp.score(
        grid_of(free()),
        maps,
        np.array([1.7, 0.0, 0.0]),
        np.zeros(3),
        np.array([[0.5, 0, 0]]),
        (0.6, 0.8, 0.01),
    )
    assert s.cost[0] == -1.0


def test_dwa_window_is_one_control_period() -> None:
    rollout = planner(sim_time=1.0, sim_period=0.1)
    dwa = planner(dwa=True, sim_time=1.0, sim_period=0.1)
    vel = np.array([0.2, 0.0, 0.0])
    assert rollout.window(vel, None) == pytest.approx((0.1, 0.5, -1.0, 1.0))
    assert dwa.window(vel, None) == pytest.approx((0.1, 0.45, -0.32, 0.32))
    assert rollout.window(vel, 0.3) == pytest.approx((0.1, 0.3, -1.0, 1.0))  # capped near the goal


def test_choose_drives_along_the_path() -> None:
    tp = planner(vx_samples=6, vtheta_samples=11)
    maps = distance_maps(free(), RES, ORIGIN, np.array([[0.0, 0.0], [1.9, 0.0]]))
    choice = tp.choose(
        grid_of(free()), maps, np.zeros(3), np.zeros(3), (0.6, 0.8, 0.01), goal_dist=1.9
    )
    assert (
        choice.vx == pytest.approx(0.5) and choice.vtheta == pytest.approx(0.0) and choice.cost >= 0
    )


def test_choose_turns_in_place_towards_a_goal_behind() -> None:
    tp = planner(min_vel_x=0.3, vx_samples=3, vtheta_samples=11)
    costs = free()
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [-1.5, 0.0]]))
    choice = tp.choose(
        grid_of(costs), maps, np.zeros(3), np.zeros(3), (0.6, 0.8, 0.01), goal_dist=1.5
    )
    # forward trajectories all end further from the goal than turning in place
    assert choice.vx == 0.0 and abs(choice.vtheta) >= 0.4


def test_boxed_in_robot_backs_up() -> None:
    costs = free()
    costs[35:46, 44] = LETHAL_OBSTACLE  # a wall 0.2 m ahead
    costs[44, 30:45] = LETHAL_OBSTACLE  # and 0.2 m to each side: turning sweeps a corner into them
    costs[36, 30:45] = LETHAL_OBSTACLE
    tp = planner(escape_vel=-0.1)
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [1.5, 0.0]]))
    choice = tp.choose(
        grid_of(costs), maps, np.zeros(3), np.zeros(3), (0.6, 0.8, 0.01), goal_dist=1.5
    )
    assert (choice.vx, choice.vtheta) == (-0.1, 0.0) and choice.cost > 0
    assert tp.osc.escaping
    # while escaping, forward samples are not tried even where they would be legal
    assert (
        tp.choose(grid_of(free()), maps, np.zeros(3), np.zeros(3), (0.6, 0.8, 0.01), 1.5).vx <= 0.0
    )


def test_rotations_keep_a_footprint_check() -> None:
    costs = free()
    tp = TrajectoryPlanner(
        RolloutParams(holonomic_robot=False),
        np.array([[0.3, 0.05], [-0.3, 0.05], [-0.3, -0.05], [0.3, -0.05]]),
    )
    costs[45:48, 40:42] = LETHAL_OBSTACLE  # hit by the long thin robot turning a quarter turn
    maps = distance_maps(costs, RES, ORIGIN, np.array([[0.0, 0.0], [1.0, 0.0]]))
    s = tp.score(
        grid_of(costs),
        maps,
        np.zeros(3),
        np.zeros(3),
        np.array([[0.0, 0.0, math.pi / 2], [0.0, 0.0, 0.0]]),
        (0.6, 0.8, 0.01),
    )
    assert s.cost[0] == -1.0 and s.cost[1] >= 0


def _queue_spread(seeds, passable, blocked_value, unreachable):
    """MapGrid's queue (map_grid.cpp computeTargetDistance), cell by cell."""
    from collections import deque

    dist = np.full(passable.shape, unreachable)
    queue = deque()
    for mx, my in seeds:
        dist[my, mx] = 0.0
        queue.append((mx, my))
    seen = {(int(mx), int(my)) for mx, my in seeds}
    while queue:
        mx, my = queue.popleft()
        for nx, ny in ((mx + 1, my), (mx - 1, my), (mx, my + 1), (mx, my - 1)):
            if not (0 <= nx < passable.shape[1] and 0 <= ny < passable.shape[0]):
                continue
            if (nx, ny) in seen:
                continue
            if not passable[ny, nx]:
                dist[ny, nx] = blocked_value
                continue
            seen.add((nx, ny))
            dist[ny, nx] = dist[my, mx] + 1.0
            queue.append((nx, ny))
    return dist


def test_distance_spreading_equals_map_grids_queue_on_random_grids():
    from workbench.navigation.trajectory_map_grid import spread

    rng = np.random.default_rng(4)
    for _ in range(60):
        shape = (int(rng.integers(3, 40)), int(rng.integers(3, 40)))
        passable = rng.random(shape) > rng.uniform(0.0, 0.5)
        count = int(rng.integers(1, 12))
        seeds = np.stack(
            [rng.integers(0, shape[1], count), rng.integers(0, shape[0], count)], axis=1
        )
        np.testing.assert_array_equal(
            spread(seeds, passable, 999.0, 1000.0),
            _queue_spread(seeds, passable, 999.0, 1000.0),
        )
