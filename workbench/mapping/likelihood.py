"""Likelihood fields for scan matching: a blurred image of map points and its coarse upper bound.

The fine field holds, per cell centre, ``exp(-d² / 2σ²)`` of the distance
``d`` to the nearest map point (its exact position, not its cell), read from
a lookup table indexed by the quantised squared distance (so the blur costs
one distance transform and one table lookup). The coarse field is the maximum of the fine field over each
``factor x factor`` block to the upper right of a cell: the coarse score of a
translation is then an upper bound of the fine score of every translation in
that block, which makes a two-level branch-and-bound search exact.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage


def gaussian_table(sigma_cells: float, radius_cells: int) -> np.ndarray:
    """Likelihood per squared distance in table units: ``table[d2] = exp(-d2 / (2 sigma²))``."""
    d2 = np.arange(radius_cells * radius_cells + 1, dtype=float)
    return np.exp(-0.5 * d2 / (sigma_cells * sigma_cells)).astype(np.float32)


class LikelihoodField:
    """A likelihood field over map points.

    Args:
        points: Map points ``(N, 2)`` in the map frame (m).
        resolution: Cell size (m).
        sigma: Standard deviation of the blur (m).
        margin: Extra border around the points (m); must exceed the search window.
        factor: Block size of the coarse field (cells).
        bounds: Optional ``(xmin, ymin, xmax, ymax)`` to clip the field to (m).
    """

    def __init__(
        self,
        points: np.ndarray,
        resolution: float = 0.05,
        sigma: float = 0.05,
        margin: float = 1.0,
        factor: int = 4,
        bounds: tuple[float, float, float, float] | None = None,
    ) -> None:
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        self.points = points
        self.sigma = float(sigma)
        self._tree = None
        self.resolution = float(resolution)
        self.factor = int(factor)
        low = points.min(axis=0) - margin
        high = points.max(axis=0) + margin
        if bounds is not None:
            low = np.maximum(low, np.array(bounds[:2]))
            high = np.minimum(high, np.array(bounds[2:]))
            high = np.maximum(high, low + resolution)
        self.origin = low
        shape = (np.ceil((high - low) / resolution).astype(int) + 2)[::-1]  # (rows=y, cols=x)
        ix = np.floor((points[:, 0] - low[0]) / resolution).astype(np.int64)
        iy = np.floor((points[:, 1] - low[1]) / resolution).astype(np.int64)
        inside = (ix >= 1) & (iy >= 1) & (ix < shape[1] - 1) & (iy < shape[0] - 1)
        self.fine = np.zeros(shape, dtype=np.float32)
        if inside.any():
            # Each occupied cell remembers the mean of its points, so distances are measured
            # to the points themselves rather than to cell centres (no quantisation bias).
            flat = iy[inside] * shape[1] + ix[inside]
            count = np.bincount(flat, minlength=shape[0] * shape[1])
            sum_x = np.bincount(flat, points[inside, 0], minlength=count.size)
            sum_y = np.bincount(flat, points[inside, 1], minlength=count.size)
            occupied = count > 0
            mean_x = np.zeros(count.size)
            mean_y = np.zeros(count.size)
            mean_x[occupied] = sum_x[occupied] / count[occupied]
            mean_y[occupied] = sum_y[occupied] / count[occupied]
            empty = ~occupied.reshape(shape)
            near_r, near_c = ndimage.distance_transform_edt(
                empty, return_distances=False, return_indices=True
            )
            near = near_r * shape[1] + near_c
            centre_x = low[0] + (np.arange(shape[1]) + 0.5) * resolution
            centre_y = low[1] + (np.arange(shape[0]) + 0.5) * resolution
            d2 = (centre_x[None, :] - mean_x[near]) ** 2 + (centre_y[:, None] - mean_y[near]) ** 2
            # Lookup table over squared distance in steps of (resolution / 8)².
            quantum = (resolution / 8.0) ** 2
            table = gaussian_table(
                sigma / np.sqrt(quantum), int(np.ceil(3.0 * sigma / np.sqrt(quantum)))
            )
            index = np.minimum(np.rint(d2 / quantum).astype(np.int64), len(table))
            self.fine = np.append(table, np.float32(0.0))[index]
        self._zero_border(self.fine)
        self.coarse = _block_max(self.fine, self.factor)
        self._zero_border(self.coarse)

    def tree(self):
        """A k-d tree of the map points (built on first use)."""
        if self._tree is None:
            from scipy.spatial import cKDTree

            self._tree = cKDTree(self.points, balanced_tree=False)  # builds faster, same answers
        return self._tree

    @staticmethod
    def _zero_border(image: np.ndarray) -> None:
        image[0, :] = 0.0
        image[-1, :] = 0.0
        image[:, 0] = 0.0
        image[:, -1] = 0.0

    @property
    def shape(self) -> tuple[int, int]:
        """``(rows, cols)`` of the field."""
        return self.fine.shape  # type: ignore[return-value]

    def cells(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Continuous cell coordinates ``(u, v)`` (x, y) of world points ``(..., 2)``."""
        u = (points[..., 0] - self.origin[0]) / self.resolution
        v = (points[..., 1] - self.origin[1]) / self.resolution
        return u, v

    def score(self, points: np.ndarray) -> float:
        """Mean fine likelihood of world points ``(N, 2)`` (nearest cell), in ``[0, 1]``."""
        u, v = self.cells(points)
        iu = np.clip(np.floor(u).astype(np.int64), 0, self.shape[1] - 1)
        iv = np.clip(np.floor(v).astype(np.int64), 0, self.shape[0] - 1)
        return float(self.fine[iv, iu].mean()) if len(iu) else 0.0

    def interpolate(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Bilinear likelihood at world points ``(N, 2)`` and its gradient ``(N, 2)`` (per metre)."""
        value, du, dv = self.interpolate_xy(points[:, 0], points[:, 1])
        return value, np.stack([du, dv], axis=1)

    def interpolate_xy(
        self, x: np.ndarray, y: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Bilinear likelihood at world points ``(x, y)`` and its gradient along x and y (per
        metre), as three arrays (the matcher's inner loop calls it thousands of times)."""
        rows, cols = self.shape
        u = (x - self.origin[0]) / self.resolution - 0.5  # cell centres sit at half-integers
        v = (y - self.origin[1]) / self.resolution - 0.5
        u0 = np.minimum(np.maximum(np.floor(u), 0.0), cols - 2)
        v0 = np.minimum(np.maximum(np.floor(v), 0.0), rows - 2)
        fu = np.minimum(np.maximum(u - u0, 0.0), 1.0)
        fv = np.minimum(np.maximum(v - v0, 0.0), 1.0)
        corner = (v0 * cols + u0).astype(np.int64)
        f = self.fine.reshape(-1)
        a, b = f[corner], f[corner + 1]
        c, d = f[corner + cols], f[corner + cols + 1]
        gu, gv = 1.0 - fu, 1.0 - fv
        value = gv * (gu * a + fu * b) + fv * (gu * c + fu * d)
        du = (gv * (b - a) + fv * (d - c)) / self.resolution
        dv = (gu * (c - a) + fu * (d - b)) / self.resolution
        return value, du, dv


def _block_max(image: np.ndarray, factor: int) -> np.ndarray:
    """``out[i, j] = max(image[i:i+factor, j:j+factor])`` (zero beyond the edge)."""
    out = image.copy()
    # Running maximum along each axis, doubling the covered span each step.
    span = 1
    while span < factor:
        step = min(span, factor - span)
        shifted = np.zeros_like(out)
        shifted[:-step, :] = out[step:, :]
        np.maximum(out, shifted, out=out)
        span += step
    span = 1
    while span < factor:
        step = min(span, factor - span)
        shifted = np.zeros_like(out)
        shifted[:, :-step] = out[:, step:]
        np.maximum(out, shifted, out=out)
        span += step
    return out
