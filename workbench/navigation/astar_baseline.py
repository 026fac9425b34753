"""A plain heapq A* on navfn's grid: the baseline the planning benchmark compares against.

Same graph as :mod:`workbench.navigation.navfn_grid` (8-connected, a step costs the
entered cell's navfn cost times its length, no corner cutting), heuristic the
straight-line distance times the cheapest cell cost (``COST_NEUTRAL``), so it finds
paths of the same cost as the Dijkstra potential. Written as one would by hand:
Python lists, ``heapq``, one cell at a time.
"""

from __future__ import annotations

import heapq
import math

import numpy as np

from workbench.navigation.navfn_grid import COST_NEUTRAL, OFFSETS


def astar(
    cell_cost: np.ndarray, start: tuple[int, int], goal: tuple[int, int]
) -> tuple[list[tuple[int, int]], float]:
    """The cheapest path from ``start`` to ``goal`` (cells ``(mx, my)``).

    Args:
        cell_cost: navfn cell costs (``inf`` for obstacles), shape ``(size_y, size_x)``.
        start: The start cell (passable whatever its cost).
        goal: The goal cell.

    Returns:
        ``(cells, cost)``: the path's cells from start to goal and its cost; ``([],
        inf)`` when the goal cannot be reached.
    """
    size_y, size_x = cell_cost.shape
    flat = cell_cost.ravel().tolist()
    passable = [math.isfinite(c) for c in flat]
    s = start[1] * size_x + start[0]
    g = goal[1] * size_x + goal[0]
    gx, gy = goal
    if not passable[g] and s != g:
        return [], math.inf
    best = {s: 0.0}
    parent = {s: -1}
    closed: set[int] = set()
    steps = [(dx, dy, math.hypot(dx, dy)) for dy, dx in OFFSETS]
    heap = [(math.hypot(start[0] - gx, start[1] - gy) * COST_NEUTRAL, 0.0, s)]
    while heap:
        _, cost, k = heapq.heappop(heap)
        if k in closed:
            continue
        if k == g:
            cells = []
            while k >= 0:
                cells.append((k % size_x, k // size_x))
                k = parent[k]
            return cells[::-1], cost
        closed.add(k)
        x, y = k % size_x, k // size_x
        for dx, dy, length in steps:
            nx, ny = x + dx, y + dy
            if not (0 <= nx < size_x and 0 <= ny < size_y):
                continue
            n = ny * size_x + nx
            if not passable[n] or n in closed:
                continue
            if dx and dy and not (passable[y * size_x + nx] and passable[ny * size_x + x]):
                continue
            new = cost + length * flat[n]
            if new < best.get(n, math.inf):
                best[n] = new
                parent[n] = k
                h = math.hypot(nx - gx, ny - gy) * COST_NEUTRAL
                heapq.heappush(heap, (new + h, new, n))
    return [], math.inf


__all__ = ["astar"]
