"""navfn's traversal costs on a costmap and the 8-connected grid graph both planners search.

navfn (``navfn/src/navfn.cpp``, Noetic) turns a costmap cost ``c`` into a cell cost
``COST_NEUTRAL + COST_FACTOR * c`` = ``50 + 0.8 c`` (truncated, at most 253); costs of
253 and 254 are obstacles, unknown (255) costs 253 when ``allow_unknown`` and is an
obstacle otherwise; the outermost ring of cells is always an obstacle. Its potential
grows by the cell cost per cell travelled (a 4-neighbour wave with interpolation,
approximating Euclidean travel). Here the potential is the shortest-path cost on the
8-connected grid: a step into a cell costs the cell's cost times the step length
(1, or sqrt 2 diagonally); a diagonal step needs both cells beside it free, so paths
do not squeeze between two obstacles touching at a corner.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from workbench.navigation.costs import INSCRIBED_INFLATED_OBSTACLE, NO_INFORMATION

COST_NEUTRAL = 50
COST_FACTOR = 0.8
#: navfn's obstacle cell cost.
COST_OBS = 254
#: A cell's potential before it is reached (navfn's ``POT_HIGH``).
POT_HIGH = 1.0e10

#: Neighbour offsets (dy, dx): four straight, then four diagonal.
OFFSETS = ((0, 1), (1, 0), (0, -1), (-1, 0), (1, 1), (1, -1), (-1, 1), (-1, -1))


def cell_costs(costs: np.ndarray, allow_unknown: bool = True) -> np.ndarray:
    """navfn's cell costs (float, ``inf`` for obstacles) of a costmap's costs (``setCostmap``)."""
    c = np.asarray(costs, dtype=np.uint8)
    value = np.minimum((COST_NEUTRAL + COST_FACTOR * c.astype(np.float64)).astype(np.int64), 253)
    out = np.where(c < INSCRIBED_INFLATED_OBSTACLE, value.astype(np.float64), np.inf)
    if allow_unknown:
        out = np.where(c == NO_INFORMATION, float(COST_OBS - 1), out)
    out[0, :] = out[-1, :] = np.inf
    out[:, 0] = out[:, -1] = np.inf
    return out


@functools.lru_cache(maxsize=8)
def grid_edges(size_y: int, size_x: int) -> tuple[np.ndarray, ...]:
    """The 8-connected edges of a grid, grouped by source cell.

    Returns:
        ``(indptr, target, length, side_a, side_b)``: CSR row pointers, each edge's
        target cell, its length in cells, and for diagonal edges the two cells beside
        it (for straight edges both are the target).
    """
    n = size_x * size_y
    index = np.arange(n).reshape(size_y, size_x)
    src, dst, length, side_a, side_b = [], [], [], [], []
    for dy, dx in OFFSETS:
        ys = slice(max(0, -dy), size_y - max(0, dy))
        xs = slice(max(0, -dx), size_x - max(0, dx))
        yt = slice(max(0, dy), size_y - max(0, -dy))
        xt = slice(max(0, dx), size_x - max(0, -dx))
        s = index[ys, xs].ravel()
        t = index[yt, xt].ravel()
        src.append(s)
        dst.append(t)
        length.append(np.full(s.size, math.hypot(dx, dy)))
        if dx and dy:
            side_a.append(s + dx)  # the cell beside the step along x
            side_b.append(s + dy * size_x)  # and along y
        else:
            side_a.append(t)
            side_b.append(t)
    src_all = np.concatenate(src)
    order = np.argsort(src_all, kind="stable")
    indptr = np.concatenate(([0], np.cumsum(np.bincount(src_all, minlength=n))))
    arrays = (
        indptr,
        np.concatenate(dst)[order],
        np.concatenate(length)[order],
        np.concatenate(side_a)[order],
        np.concatenate(side_b)[order],
    )
    for a in arrays:
        a.setflags(write=False)
    return arrays


def potential(cell_cost: np.ndarray, start: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """The potential from ``start`` = ``(mx, my)`` over the grid, and each cell's predecessor.

    Args:
        cell_cost: :func:`cell_costs` of the grid, shape ``(size_y, size_x)``.
        start: The start cell; it is passable whatever its cost.

    Returns:
        ``(potential, predecessor)``, flat over cells: the cost of the cheapest path
        (:data:`POT_HIGH` where unreachable) and the previous cell on it (-9999 at the
        start and where unreachable).
    """
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import dijkstra

    size_y, size_x = cell_cost.shape
    indptr, target, length, side_a, side_b = grid_edges(size_y, size_x)
    flat = cell_cost.ravel()
    weight = length * flat[target]
    diagonal = side_a != target
    blocked = diagonal & ~(np.isfinite(flat[side_a]) & np.isfinite(flat[side_b]))
    weight[blocked] = np.inf
    n = size_x * size_y
    graph = csr_matrix((weight, target, indptr), shape=(n, n))
    start_index = start[1] * size_x + start[0]
    dist, pred = dijkstra(graph, directed=True, indices=start_index, return_predecessors=True)
    dist = np.where(np.isfinite(dist), dist, POT_HIGH)
    return dist, pred


def path_cells(predecessor: np.ndarray, goal_index: int, size_x: int) -> list[tuple[int, int]]:
    """The cells ``(mx, my)`` from the start to ``goal_index`` by following predecessors."""
    cells = []
    k = int(goal_index)
    while k >= 0:
        cells.append((k % size_x, k // size_x))
        k = int(predecessor[k])
    cells.reverse()
    return cells


__all__ = [
    "COST_FACTOR",
    "COST_NEUTRAL",
    "COST_OBS",
    "OFFSETS",
    "POT_HIGH",
    "cell_costs",
    "grid_edges",
    "path_cells",
    "potential",
]
