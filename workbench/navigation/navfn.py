"""navfn's global planner: ``navfn_plan`` on a costmap and ``NavfnROS`` on a node.

As ``NavfnROS::makePlan`` (navfn, Noetic): the robot's cell is cleared, the
potential is spread from the robot over the costmap's navfn costs
(:mod:`~workbench.navigation.navfn_grid`), then the goal window
``goal +- tolerance`` is scanned in steps of one cell (rows from the bottom, each
from the left) for the point nearest the goal whose potential is below
``POT_HIGH``; the path runs from the robot to it. The path is extracted by
following each cell's predecessor on the cheapest 8-connected path (navfn descends
the gradient of its interpolated potential instead): poses at cell centres, from the
robot's cell to the goal window's cell, then the chosen point itself as navfn
appends it. ``use_dijkstra=False`` searches with A* when no tolerance is asked
(same path cost); with a tolerance the full potential is needed and Dijkstra runs.

``NavfnROS`` reads ``~<name>/allow_unknown`` (true), ``~<name>/default_tolerance``
(0 m), ``~<name>/visualize_potential``, ``~<name>/planner_window_x/y`` (accepted, not
used), publishes each plan on ``~<name>/plan`` (``nav_msgs/Path``) and serves
``~<name>/make_plan`` (``nav_msgs/GetPlan``, the tolerance of the request is ignored
as navfn ignores it).
"""

from __future__ import annotations

import hashlib
import math
import threading
import time
from typing import Any

import numpy as np

from workbench.navigation.astar_baseline import astar
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_params import Params
from workbench.navigation.navfn_grid import (
    COST_NEUTRAL,
    PLAN_LOCK,
    POT_HIGH,
    cell_costs,
    grid_graph,
    path_cells,
    potential,
)

OFF_MAP_GOAL = (
    "The goal sent to the navfn planner is off the global costmap. Planning will always fail to "
    "this goal."
)
OFF_MAP_START = (
    "The robot's start position is off the global costmap. Planning will always fail, are you "
    "sure the robot has been properly localized?"
)


def goal_window(
    goal: tuple[float, float], tolerance: float, resolution: float
) -> tuple[np.ndarray, np.ndarray]:
    """The points navfn tries around ``goal``: x and y grids, rows of constant y (m)."""
    steps = []
    for centre in goal:
        values = []
        value = centre - tolerance
        while value <= centre + tolerance:
            values.append(value)
            value += resolution
        steps.append(np.array(values))
    return np.meshgrid(steps[0], steps[1])


def _best_goal(
    costmap: Costmap2D,
    pot: np.ndarray,
    passable: np.ndarray,
    goal: tuple[float, float],
    tolerance: float,
) -> tuple[tuple[float, float, int] | None, bool]:
    """The window point nearest the goal with a potential, and whether that is certain.

    With a potential spread only up to a limit, a passable window point nearer the goal
    than the one found (or any passable one when none was found) may lie beyond the
    limit: then the answer is not certain and the potential must spread further.
    """
    wx, wy = goal_window(goal, tolerance, costmap.resolution)
    points = np.column_stack((wx.ravel(), wy.ravel()))
    mx, my, inside = costmap.world_to_map_array(points)
    index = my * costmap.size_x + mx
    values = np.full(points.shape[0], np.inf)
    values[inside] = pot[index[inside]]
    open_ = np.zeros(points.shape[0], bool)
    open_[inside] = passable[index[inside]]
    sdist = (points[:, 0] - goal[0]) ** 2 + (points[:, 1] - goal[1]) ** 2
    legal = values < POT_HIGH
    unresolved = open_ & ~legal
    if not legal.any():
        return None, not unresolved.any()
    i = int(np.argmin(np.where(legal, sdist, np.inf)))
    certain = not (unresolved & (sdist <= sdist[i])).any()
    return (float(points[i, 0]), float(points[i, 1]), int(index[i])), certain


def _exhausted(pot: np.ndarray, passable: np.ndarray, shape: tuple[int, ...]) -> bool:
    """Whether no passable cell next to a reached one is left unreached."""
    from scipy.ndimage import binary_dilation

    reached = (pot < POT_HIGH).reshape(shape)
    border = binary_dilation(reached, structure=np.ones((3, 3), bool)) & ~reached
    return not (border & passable.reshape(shape)).any()


def _spread(
    costmap: Costmap2D,
    cell_cost: np.ndarray,
    graph: Any,
    start: tuple[int, int],
    goal: tuple[float, float],
    tolerance: float,
) -> tuple[tuple[float, float, int] | None, np.ndarray]:
    """Spread the potential until the goal window's answer is certain (navfn, too, stops
    spreading once it reached the goal); returns the best point and the predecessors.

    The first limit is twice the cost of a straight line of free cells to the far side of
    the goal window; each retry quadruples it, the last spreads over the whole grid. When
    the potential reached every cell it can reach (no passable cell borders the reached
    ones), spreading further changes nothing.
    """
    passable = np.isfinite(cell_cost).ravel()
    sx, sy = costmap.map_to_world(*start)
    cells = (math.hypot(goal[0] - sx, goal[1] - sy) + 1.5 * tolerance) / costmap.resolution
    limit = 2.0 * COST_NEUTRAL * (cells + 10.0)
    full = COST_NEUTRAL * 4.0 * (costmap.size_x + costmap.size_y)
    while True:
        pot, pred = potential(cell_cost, start, limit, graph)
        best, certain = _best_goal(costmap, pot, passable, goal, tolerance)
        if certain or math.isinf(limit) or _exhausted(pot, passable, cell_cost.shape):
            return best, pred
        limit = limit * 4.0 if limit < full else math.inf


def navfn_plan(
    costmap: Costmap2D,
    start: tuple[float, float],
    goal: tuple[float, float],
    *,
    tolerance: float = 0.0,
    allow_unknown: bool = True,
    use_dijkstra: bool = True,
) -> list[tuple[float, float]]:
    """A path from ``start`` to (near) ``goal`` over ``costmap``, or ``[]`` when there is none.

    Args:
        costmap: The costmap (not changed).
        start: The robot's position in the costmap's frame (m).
        goal: The goal position (m).
        tolerance: How far from the goal the path may end (m).
        allow_unknown: Whether unknown cells may be crossed.
        use_dijkstra: Spread the full potential (True) or search with A*.

    Returns:
        Points (m) from the robot's cell to the goal, the last one the goal (or the
        nearest reachable point within ``tolerance``).
    """
    start_cell = costmap.world_to_map(*start)
    if start_cell is None:
        return []
    goal_cell = costmap.world_to_map(*goal)
    if goal_cell is None and tolerance <= 0.0:
        return []
    # navfn clears the robot's cell (clearRobotCell); a step costs the cell it enters, so
    # the start's own cost never counts and the costmap's costs are used as they are
    cell_cost = cell_costs(costmap.costs, allow_unknown)
    size_x = costmap.size_x
    if not use_dijkstra and tolerance <= 0.0 and goal_cell is not None:
        cells, cost = astar(cell_cost, start_cell, goal_cell)
        if not cells:
            return []
        end: tuple[float, float] = (float(goal[0]), float(goal[1]))
    else:
        key = (
            costmap.costs.shape,
            allow_unknown,
            hashlib.blake2b(costmap.costs.tobytes(), digest_size=16).digest(),
        )
        with PLAN_LOCK:
            graph = grid_graph(cell_cost, key, in_place=True)
            best, pred = _spread(costmap, cell_cost, graph, start_cell, goal, tolerance)
        if best is None:
            return []
        cells = path_cells(pred, best[2], size_x)
        end = (best[0], best[1])
    path = [costmap.map_to_world(mx, my) for mx, my in cells]
    path.append(end)
    return path


class NavfnROS:
    """navfn on a host node, planning on a :class:`~workbench.navigation.costmap_ros.CostmapROS`.

    Args:
        node: The host ``workbench.bus.Node`` (``move_base``).
        name: The planner's name (``NavfnROS``).
        costmap: The global costmap.

    Raises:
        CostmapError: A parameter has the wrong type (one line naming it).
    """

    def __init__(self, node: Any, name: str, costmap: Any) -> None:
        from workbench.msgs.nav_msgs import GetPlan, Path

        self.node = node
        self.name = name
        self.costmap_ros = costmap
        self.log = node.get_logger()
        params = Params(node, node.resolve_name("~" + name, "parameter name"))
        self.allow_unknown = params.flag("allow_unknown", True)
        self.default_tolerance = params.number("default_tolerance", 0.0)
        self.visualize_potential = params.flag("visualize_potential", False)
        self.planner_window_x = params.number("planner_window_x", 0.0)
        self.planner_window_y = params.number("planner_window_y", 0.0)
        self._lock = threading.Lock()
        self._last_warning: dict[str, float] = {}
        self.plan_pub = node.create_publisher(f"~{name}/plan", Path, 1)
        self.service = node.create_service(f"~{name}/make_plan", GetPlan, self._on_make_plan)

    @property
    def global_frame(self) -> str:
        """The frame plans are in (the costmap's)."""
        return str(self.costmap_ros.global_frame)

    def _warn_throttled(self, text: str) -> None:
        now = time.monotonic()
        if now - self._last_warning.get(text, -10.0) >= 1.0:
            self._last_warning[text] = now
            self.log.warn(text)

    def make_plan(self, start: Any, goal: Any, tolerance: float | None = None) -> list[Any]:
        """Plan from ``start`` to ``goal`` (``geometry_msgs/PoseStamped`` in the global frame).

        Returns:
            The plan's poses (empty when there is none); it is also published.
        """
        tolerance = self.default_tolerance if tolerance is None else float(tolerance)
        frame = self.global_frame
        if goal.header.frame_id.lstrip("/") != frame:
            self.log.error(
                "The goal pose passed to this planner must be in the %s frame.  It is instead "
                "in the %s frame.",
                frame,
                goal.header.frame_id,
            )
            return []
        if start.header.frame_id.lstrip("/") != frame:
            self.log.error(
                "The start pose passed to this planner must be in the %s frame.  It is instead "
                "in the %s frame.",
                frame,
                start.header.frame_id,
            )
            return []
        with self._lock:
            costmap = self.costmap_ros.costmap()
            s = (float(start.pose.position.x), float(start.pose.position.y))
            g = (float(goal.pose.position.x), float(goal.pose.position.y))
            if costmap.world_to_map(*s) is None:
                self._warn_throttled(OFF_MAP_START)
                return []
            if costmap.world_to_map(*g) is None and tolerance <= 0.0:
                self._warn_throttled(OFF_MAP_GOAL)
                return []
            points = navfn_plan(
                costmap, s, g, tolerance=tolerance, allow_unknown=self.allow_unknown
            )
            plan = self._poses(points, goal)
        self.publish_plan(plan)
        return plan

    def _poses(self, points: list[tuple[float, float]], goal: Any) -> list[Any]:
        from workbench.msgs.geometry_msgs import PoseStamped

        stamp = self.node.now()
        plan = []
        for i, (x, y) in enumerate(points):
            pose = PoseStamped()
            pose.header.stamp = stamp
            pose.header.frame_id = self.global_frame
            pose.pose.position.x, pose.pose.position.y = x, y
            if i == len(points) - 1:
                pose.pose.orientation = goal.pose.orientation  # navfn appends the goal pose
            else:
                pose.pose.orientation.w = 1.0
            plan.append(pose)
        return plan

    def publish_plan(self, plan: list[Any]) -> None:
        """Publish ``plan`` on ``~<name>/plan`` (``publishPlan``)."""
        from workbench.msgs.nav_msgs import Path

        path = Path()
        if plan:
            path.header.frame_id = plan[0].header.frame_id
            path.header.stamp = plan[0].header.stamp
        else:
            path.header.frame_id = self.global_frame
            path.header.stamp = self.node.now()
        path.poses = list(plan)
        self.plan_pub.publish(path)

    def _on_make_plan(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import GetPlan

        response = GetPlan.Response()
        response.plan.poses = self.make_plan(request.start, request.goal)
        response.plan.header.stamp = self.node.now()
        response.plan.header.frame_id = self.global_frame
        return response


def path_length(points: list[tuple[float, float]]) -> float:
    """The length of a polyline (m)."""
    return float(sum(math.dist(a, b) for a, b in zip(points[:-1], points[1:], strict=True)))


__all__ = ["OFF_MAP_GOAL", "OFF_MAP_START", "NavfnROS", "goal_window", "navfn_plan", "path_length"]
