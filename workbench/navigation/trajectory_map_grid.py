"""base_local_planner's ``MapGrid``: path and goal distance maps over the local costmap.

As ``base_local_planner/src/map_grid.cpp`` (Noetic): the global plan is first densified so
consecutive points are at most one cell apart (``adjustPlanResolution``); the *path*
map is seeded with every plan cell from the start of the plan until the plan leaves the
local costmap (cells of unknown cost skipped), the *goal* map with the last such cell
(the local goal). Distances then spread outwards over the 4-neighbourhood, one unit per
cell; lethal, inscribed and unknown cells are obstacles (distance = the map's cell count,
``obstacleCosts``) except cells under the robot's own footprint; cells never reached keep
the cell count + 1 (``unreachableCellCosts``). A trajectory point whose distance reaches
the cell count is "impossible".

The spreading runs as scipy's Dijkstra over unit edges instead of a queue.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.navigation.costs import INSCRIBED_INFLATED_OBSTACLE, LETHAL_OBSTACLE, NO_INFORMATION


@dataclass
class DistanceMaps:
    """Path and goal distances in cells, ``[my, mx]`` as the costmap."""

    path: np.ndarray  # float64 (size_y, size_x)
    goal: np.ndarray
    goal_xy: tuple[float, float] | None  # the local goal (world), None without a plan cell
    impossible: float  # the cell count: a distance at or above it is no way through
    within_robot: np.ndarray | None = None  # cells under the robot (never obstacles)


def densify(plan: np.ndarray, resolution: float) -> np.ndarray:
    """Insert points so consecutive plan points are at most ``resolution`` apart (m)."""
    plan = np.asarray(plan, dtype=float).reshape(-1, 2)
    if len(plan) < 2:
        return plan
    steps = np.hypot(*np.diff(plan, axis=0).T)
    counts = np.maximum(np.ceil(steps / resolution).astype(int), 1)
    parts = [plan[:1]]
    for a, b, n in zip(plan[:-1], plan[1:], counts, strict=True):
        t = np.arange(1, n + 1)[:, None] / n
        parts.append(a + t * (b - a))
    return np.concatenate(parts)


def plan_cells(
    costs: np.ndarray, resolution: float, origin: tuple[float, float], plan: np.ndarray
) -> np.ndarray:
    """Cells ``(k, 2)`` as (mx, my) of the plan's first run inside the map with known cost."""
    dense = densify(plan, resolution)
    cells = np.floor((dense - np.asarray(origin)) / resolution).astype(int)
    size_y, size_x = costs.shape
    inside = (
        (cells[:, 0] >= 0) & (cells[:, 0] < size_x) & (cells[:, 1] >= 0) & (cells[:, 1] < size_y)
    )
    usable = inside.copy()
    usable[inside] = costs[cells[inside, 1], cells[inside, 0]] != NO_INFORMATION
    if not usable.any():
        return np.empty((0, 2), dtype=int)
    first = int(np.argmax(usable))
    stop = np.flatnonzero(~usable[first:])
    end = first + (int(stop[0]) if len(stop) else len(usable) - first)
    return cells[first:end]


_NEIGHBOURS: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}


def _neighbour_edges(shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Every directed 4-neighbour edge ``(from, to)`` of a grid, sorted by ``from``."""
    edges = _NEIGHBOURS.get(shape)
    if edges is None:
        index = np.arange(shape[0] * shape[1]).reshape(shape)
        pairs = [
            (index[:, :-1], index[:, 1:]),
            (index[:, 1:], index[:, :-1]),
            (index[:-1, :], index[1:, :]),
            (index[1:, :], index[:-1, :]),
        ]
        source = np.concatenate([a.ravel() for a, _ in pairs])
        target = np.concatenate([b.ravel() for _, b in pairs])
        order = np.argsort(source, kind="stable")
        edges = _NEIGHBOURS[shape] = (source[order], target[order])
    return edges


def spread(
    seeds: np.ndarray, passable: np.ndarray, blocked_value: float, unreachable: float
) -> np.ndarray:
    """4-connected unit-step distances from ``seeds`` (mx, my) over ``passable`` cells.

    A seed spreads whether passable or not; a blocked cell next to a reached one gets
    ``blocked_value``, any other cell not reached ``unreachable``. Breadth first as
    MapGrid's queue, run as scipy's Dijkstra over the passable cells' unit edges.
    """
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import dijkstra

    dist = np.full(passable.shape, unreachable)
    if len(seeds) == 0:
        return dist
    shape = passable.shape
    cells = passable.size
    source, target = _neighbour_edges(shape)
    starts = np.unique(seeds[:, 1] * shape[1] + seeds[:, 0])
    open_cells = passable.ravel()
    leaves = open_cells.copy()
    leaves[starts] = True
    keep = leaves[source] & open_cells[target]
    indptr = np.zeros(cells + 1, dtype=np.int64)
    np.cumsum(np.bincount(source[keep], minlength=cells), out=indptr[1:])
    graph = csr_matrix((np.ones(int(keep.sum())), target[keep], indptr), shape=(cells, cells))
    found = dijkstra(graph, directed=True, indices=starts, min_only=True).reshape(shape)
    reached = np.isfinite(found)
    dist[reached] = found[reached]
    near = reached.copy()
    near[1:, :] |= reached[:-1, :]
    near[:-1, :] |= reached[1:, :]
    near[:, 1:] |= reached[:, :-1]
    near[:, :-1] |= reached[:, 1:]
    dist[near & ~passable & ~reached] = blocked_value
    return dist


def distance_maps(
    costs: np.ndarray,
    resolution: float,
    origin: tuple[float, float],
    plan: np.ndarray,
    within_robot: np.ndarray | None = None,
    *,
    with_path: bool = True,
) -> DistanceMaps:
    """The path and goal distance maps for ``plan`` (world ``(n, 2)``) on a costmap.

    Args:
        costs: uint8 costs ``[my, mx]``.
        resolution: Metres per cell.
        origin: World position of cell (0, 0)'s corner (m).
        plan: The global plan's points in the costmap's frame (m).
        within_robot: Boolean mask of cells under the robot's footprint (never obstacles).
        with_path: Spread the path map too (False: only the goal map; ``path`` is it too).
    """
    cells_count = float(costs.size)
    obstacle = (
        (costs == LETHAL_OBSTACLE)
        | (costs == INSCRIBED_INFLATED_OBSTACLE)
        | (costs == NO_INFORMATION)
    )
    if within_robot is not None:
        obstacle &= ~within_robot
    passable = ~obstacle
    seeds = plan_cells(costs, resolution, origin, plan)
    path = spread(seeds, passable, cells_count, cells_count + 1.0) if with_path else None
    goal_xy = None
    goal_seed = seeds[-1:]
    if len(goal_seed):
        mx, my = goal_seed[0]
        goal_xy = (origin[0] + (mx + 0.5) * resolution, origin[1] + (my + 0.5) * resolution)
    goal = spread(goal_seed, passable, cells_count, cells_count + 1.0)
    return DistanceMaps(goal if path is None else path, goal, goal_xy, cells_count, within_robot)
