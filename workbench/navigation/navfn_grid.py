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

import copy
import functools
import math
import threading
from collections import OrderedDict
from collections.abc import Hashable
from typing import Any

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
def grid_edges(size_y: int, size_x: int) -> tuple[np.ndarray, np.ndarray]:
    """The 8-connected edges of a grid padded by one cell on each side.

    Every padded cell has 8 edge slots, in :data:`OFFSETS` order, so the CSR row pointers
    are ``0, 8, 16, ...`` and the weights of one slot are a shifted slice of the costs.

    Returns:
        ``(indptr, indices)`` of the padded grid's ``(size_y + 2) * (size_x + 2)`` cells
        (targets beyond the padding are clipped; their weights are infinite).
    """
    width = size_x + 2
    n = width * (size_y + 2)
    shifts = np.array([dy * width + dx for dy, dx in OFFSETS])
    indices = np.clip(np.arange(n)[:, None] + shifts[None, :], 0, n - 1).ravel()
    indptr = np.arange(0, 8 * n + 1, 8)
    indices.setflags(write=False)
    indptr.setflags(write=False)
    return indptr, indices


def _shifted(values: np.ndarray, shift: int) -> np.ndarray:
    """``values[i + shift]`` for every ``i`` (``inf`` beyond the ends)."""
    out = np.empty_like(values)
    n = values.size
    if shift >= 0:
        out[: n - shift] = values[shift:]
        out[n - shift :] = np.inf
    else:
        out[-shift:] = values[:shift]
        out[:-shift] = np.inf
    return out


def edge_weights(cell_cost: np.ndarray) -> np.ndarray:
    """The weights of :func:`grid_edges`' slots: step length times the entered cell's cost.

    A diagonal step is infinite unless both cells beside it are passable.
    """
    size_y, size_x = cell_cost.shape
    width = size_x + 2
    padded = np.pad(cell_cost, 1, constant_values=np.inf).ravel()
    diagonal = padded * math.sqrt(2.0)
    blocked = np.where(np.isfinite(padded), 0.0, np.inf)
    weights = np.empty((padded.size, 8))
    for k, (dy, dx) in enumerate(OFFSETS):
        if dx and dy:
            column = _shifted(diagonal, dy * width + dx)
            column += _shifted(blocked, dx)
            column += _shifted(blocked, dy * width)
        else:
            column = _shifted(padded, dy * width + dx)
        weights[:, k] = column
    return weights.ravel()


#: Graphs of recent costmaps, by content: a costmap that did not change is not rebuilt.
_GRAPHS: OrderedDict[Hashable, Any] = OrderedDict()
_GRAPHS_KEPT = 4
_GRAPHS_LOCK = threading.Lock()
#: The last graph built and the cell costs it was built from: a costmap that changed in a
#: small window (the obstacle layer around the robot) gets a copy with that window redone.
_LAST: list[tuple[np.ndarray, Any]] = []
#: Largest share of the grid a changed window may cover to be patched rather than rebuilt.
PATCH_SHARE = 0.25


def patched_weights(
    old_cost: np.ndarray, old_weights: np.ndarray, cell_cost: np.ndarray, in_place: bool = False
) -> np.ndarray | None:
    """:func:`edge_weights` of ``cell_cost`` from those of ``old_cost`` (same shape), redoing
    only the cells around the ones that changed; None when too much changed. With
    ``in_place`` the old weights are overwritten (and returned) instead of copied."""
    changed = old_cost != cell_cost
    rows = np.flatnonzero(changed.any(axis=1))
    if rows.size == 0:
        return old_weights if in_place else old_weights.copy()
    cols = np.flatnonzero(changed.any(axis=0))
    size_y, size_x = cell_cost.shape
    # sources whose 8 slots read a changed cell lie within one cell of it; their slots
    # read costs up to one cell further, so the window computed has two cells of margin
    y0, y1 = max(int(rows[0]) - 2, 0), min(int(rows[-1]) + 3, size_y)
    x0, x1 = max(int(cols[0]) - 2, 0), min(int(cols[-1]) + 3, size_x)
    if (y1 - y0) * (x1 - x0) > PATCH_SHARE * cell_cost.size:
        return None
    window = edge_weights(cell_cost[y0:y1, x0:x1]).reshape(y1 - y0 + 2, x1 - x0 + 2, 8)
    weights = old_weights if in_place else old_weights.copy()
    full = weights.reshape(size_y + 2, size_x + 2, 8)
    # padded rows/columns of the sources redone: one cell in from the window's edge, except
    # where the window reaches the grid's edge (its padding is the grid's padding there)
    a = 0 if y0 == 0 else 2
    b = y1 - y0 + 2 if y1 == size_y else y1 - y0
    c = 0 if x0 == 0 else 2
    d = x1 - x0 + 2 if x1 == size_x else x1 - x0
    full[y0 + a : y0 + b, x0 + c : x0 + d] = window[a:b, c:d]
    return weights


#: Held by a planner while it builds a graph in place and searches it (see grid_graph).
PLAN_LOCK = threading.RLock()


def grid_graph(
    cell_cost: np.ndarray, key: Hashable | None = None, *, in_place: bool = False
) -> Any:
    """The CSR graph of :func:`grid_edges` and :func:`edge_weights` (cached under ``key``).

    With ``in_place`` (callers holding :data:`PLAN_LOCK` until they are done with the
    graph) a patched graph overwrites the last one's weights instead of copying them (a
    400 x 400 grid's weights are 10 MB; navfn replans at 5 Hz) and the last one leaves the
    cache.
    """
    from scipy.sparse import csr_matrix

    if key is not None:
        with _GRAPHS_LOCK:
            graph = _GRAPHS.get(key)
            if graph is not None:
                _GRAPHS.move_to_end(key)
                return graph
    indptr, indices = grid_edges(*cell_cost.shape)
    n = indptr.size - 1
    weights = None
    with _GRAPHS_LOCK:
        last = _LAST[0] if _LAST else None
    if last is not None and last[0].shape == cell_cost.shape:
        weights = patched_weights(last[0], last[1].data, cell_cost, in_place)
    if weights is None or last is None:
        graph = csr_matrix((edge_weights(cell_cost), indices, indptr), shape=(n, n))
    elif in_place:
        graph = last[1]
        with _GRAPHS_LOCK:
            for stale in [k for k, g in _GRAPHS.items() if g is graph]:
                del _GRAPHS[stale]
    else:  # the same structure (checked when it was built) with the new weights
        graph = copy.copy(last[1])
        graph.data = weights
    with _GRAPHS_LOCK:
        _LAST[:] = [(cell_cost.copy(), graph)]
        if key is not None:
            _GRAPHS[key] = graph
            while len(_GRAPHS) > _GRAPHS_KEPT:
                _GRAPHS.popitem(last=False)
    return graph


def clear_graph_cache() -> None:
    """Forget the cached graphs."""
    with _GRAPHS_LOCK:
        _GRAPHS.clear()
        _LAST.clear()


def potential(
    cell_cost: np.ndarray,
    start: tuple[int, int],
    limit: float = np.inf,
    graph: Any = None,
) -> tuple[np.ndarray, np.ndarray]:
    """The potential from ``start`` = ``(mx, my)`` over the grid, and each cell's predecessor.

    Args:
        cell_cost: :func:`cell_costs` of the grid, shape ``(size_y, size_x)``.
        start: The start cell; it is passable whatever its cost (a step's cost is the
            cell it enters, so the start's own cost never counts).
        limit: Stop spreading beyond this potential (cells past it stay at ``POT_HIGH``).
        graph: :func:`grid_graph` of ``cell_cost`` if already built.

    Returns:
        ``(potential, predecessor)``, flat over cells (``my * size_x + mx``): the cost of
        the cheapest path (:data:`POT_HIGH` where unreachable) and the previous cell on it
        (negative at the start and where unreachable).
    """
    from scipy.sparse.csgraph import dijkstra

    size_y, size_x = cell_cost.shape
    width = size_x + 2
    if graph is None:
        graph = grid_graph(cell_cost)
    source = (start[1] + 1) * width + start[0] + 1
    dist, pred = dijkstra(
        graph, directed=True, indices=source, return_predecessors=True, limit=limit
    )
    dist = dist.reshape(size_y + 2, width)[1:-1, 1:-1].ravel()
    pred = pred.reshape(size_y + 2, width)[1:-1, 1:-1].ravel()
    row, column = np.divmod(pred, width)
    pred = np.where(pred >= 0, (row - 1) * size_x + column - 1, -9999)
    return np.where(np.isfinite(dist), dist, POT_HIGH), pred


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
    "clear_graph_cache",
    "edge_weights",
    "grid_graph",
    "PLAN_LOCK",
    "grid_edges",
    "patched_weights",
    "path_cells",
    "potential",
]
