"""costmap_2d's Bresenham ray tracing and convex polygon fill, vectorised over many rays.

``Costmap2D::raytraceLine`` walks from ``(x0, y0)`` towards ``(x1, y1)`` along the
dominant axis, stepping the other axis when the error term (started at half the
dominant length) overflows; the walk is cut to ``max_length`` cells (scaled on the
dominant axis) and visits its last cell too. After ``k`` steps the minor axis has
moved ``(e0 + k * d_minor) // d_major`` cells, which is what is computed here for
all rays at once.
"""

from __future__ import annotations

import numpy as np


def raytrace_cells(
    x0: int, y0: int, x1: np.ndarray, y1: np.ndarray, max_length: float = np.inf
) -> tuple[np.ndarray, np.ndarray]:
    """All cells the rays from ``(x0, y0)`` to each ``(x1[i], y1[i])`` visit.

    Args:
        x0: Start cell x (the same for every ray).
        y0: Start cell y.
        x1: End cells x, shape ``(N,)``.
        y1: End cells y, shape ``(N,)``.
        max_length: Longest ray in cells (``raytraceLine``'s ``max_length``).

    Returns:
        ``(xs, ys)``: the visited cells of all rays concatenated (repeats possible).
    """
    x1 = np.asarray(x1, dtype=np.int64).reshape(-1)
    y1 = np.asarray(y1, dtype=np.int64).reshape(-1)
    if x1.size == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    dx, dy = x1 - x0, y1 - y0
    adx, ady = np.abs(dx), np.abs(dy)
    sx = np.where(dx > 0, 1, -1)
    sy = np.where(dy > 0, 1, -1)
    x_major = adx >= ady
    da = np.where(x_major, adx, ady)
    db = np.where(x_major, ady, adx)
    dist = np.hypot(dx, dy)
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = np.where(dist == 0.0, 1.0, np.minimum(1.0, max_length / dist))
    steps = np.minimum((scale * da).astype(np.int64), da)
    longest = int(steps.max()) + 1
    k = np.arange(longest, dtype=np.int64)[None, :]
    valid = k <= steps[:, None]
    e0 = (da // 2)[:, None]
    safe_da = np.maximum(da, 1)[:, None]
    minor = (e0 + k * db[:, None]) // safe_da
    major = k
    xm = x_major[:, None]
    xs = x0 + sx[:, None] * np.where(xm, major, minor)
    ys = y0 + sy[:, None] * np.where(xm, minor, major)
    return xs[valid], ys[valid]


def convex_fill_cells(xs: np.ndarray, ys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cells inside a convex polygon given by its vertex cells (``convexFillCells``).

    The outline is traced with :func:`raytrace_cells` edge by edge (closing the
    polygon), then each column is filled from its lowest to its highest outline cell.

    Args:
        xs: Vertex cells x (at least 3 vertices, else nothing is filled).
        ys: Vertex cells y.
    """
    xs = np.asarray(xs, dtype=np.int64)
    ys = np.asarray(ys, dtype=np.int64)
    if xs.size < 3:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    ox, oy = [], []
    for i in range(xs.size):
        j = (i + 1) % xs.size
        cx, cy = raytrace_cells(int(xs[i]), int(ys[i]), xs[j : j + 1], ys[j : j + 1])
        ox.append(cx)
        oy.append(cy)
    outline_x, outline_y = np.concatenate(ox), np.concatenate(oy)
    x_min = int(outline_x.min())
    width = int(outline_x.max()) - x_min + 1
    low = np.full(width, np.iinfo(np.int64).max)
    high = np.full(width, np.iinfo(np.int64).min)
    np.minimum.at(low, outline_x - x_min, outline_y)
    np.maximum.at(high, outline_x - x_min, outline_y)
    counts = high - low + 1
    cols = np.repeat(np.arange(width) + x_min, counts)
    starts = np.repeat(low, counts)
    offsets = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    return cols, starts + offsets


__all__ = ["convex_fill_cells", "raytrace_cells"]
