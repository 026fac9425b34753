"""KLD sampling and clustering over amcl's pose histogram (``pf.c``, ``pf_kdtree.c``).

Poses fall into bins of 0.5 m x 0.5 m x 10° (``pf_kdtree_alloc``: ``key = floor(v /
size)``). KLD-sampling (Fox 2003, ``pf_resample_limit``) needs, with ``k`` occupied
bins, ``n = ceil((k - 1) / (2 err) (1 - 2/(9(k-1)) + sqrt(2/(9(k-1))) z)³)`` samples,
clamped to ``[min_samples, max_samples]`` (``max_samples`` for ``k = 1``). Clusters are
the connected components of occupied bins, bins touching in any of the 26 directions
(``pf_kdtree_cluster``); headings are kept in ``[-pi, pi)`` here, so the heading bins
wrap around (bin -18 touches bin 17).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

#: Histogram bin sizes: x (m), y (m), heading (rad).
BIN_SIZE = (0.5, 0.5, 10 * np.pi / 180)
#: Heading bins around the circle.
HEADING_BINS = 36
_BIAS = 1 << 20


def resample_limits(min_samples: int, max_samples: int, err: float, z: float) -> np.ndarray:
    """``limits[k]``: the samples needed with ``k`` occupied bins, ``k = 0 .. max_samples``."""
    k = np.arange(max_samples + 1, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        b = 2.0 / (9.0 * (k - 1))
        x = 1.0 - b + np.sqrt(b) * z
        n = np.ceil((k - 1) / (2.0 * err) * x**3)
    n = np.clip(np.nan_to_num(n, nan=max_samples, posinf=max_samples), min_samples, max_samples)
    n[:2] = max_samples
    return n.astype(np.int64)


def bin_keys(poses: np.ndarray) -> np.ndarray:
    """``(N, 3)`` integer histogram keys of poses ``(x, y, theta)``."""
    return np.floor(poses / np.asarray(BIN_SIZE)).astype(np.int64)


def packed_keys(keys: np.ndarray) -> np.ndarray:
    """One int64 per ``(N, 3)`` key (21 bits per component)."""
    k = keys + _BIAS
    return (k[:, 0] << 42) | (k[:, 1] << 21) | k[:, 2]


def kld_count(poses: np.ndarray, limits: np.ndarray) -> int:
    """How many of ``poses``, drawn in order, pf.c's resampler keeps.

    It adds samples one by one and stops once the count exceeds the limit for the bins
    occupied so far (``sample_count > pf_resample_limit(leaf_count)``).
    """
    packed = packed_keys(bin_keys(poses))
    _, first = np.unique(packed, return_index=True)
    new_bin = np.zeros(len(poses), dtype=bool)
    new_bin[first] = True
    occupied = np.cumsum(new_bin)
    count = np.arange(1, len(poses) + 1)
    over = count > limits[np.minimum(occupied, len(limits) - 1)]
    return int(np.argmax(over)) + 1 if over.any() else len(poses)


def cluster_labels(poses: np.ndarray) -> np.ndarray:
    """``(N,)`` cluster label per pose: connected components of the occupied bins."""
    keys = bin_keys(poses)
    keys[:, 2] %= HEADING_BINS
    packed = packed_keys(keys)
    unique, inverse = np.unique(packed, return_inverse=True)
    ukeys = np.empty((len(unique), 3), dtype=np.int64)
    ukeys[inverse] = keys
    rows, cols = [np.arange(len(unique))], [np.arange(len(unique))]
    offsets = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
    for offset in offsets[13:]:  # half of the 26 neighbours; the graph is symmetric
        near = ukeys + offset
        near[:, 2] %= HEADING_BINS
        target = packed_keys(near)
        at = np.searchsorted(unique, target)
        at_clipped = np.minimum(at, len(unique) - 1)
        found = unique[at_clipped] == target
        rows.append(np.nonzero(found)[0])
        cols.append(at_clipped[found])
    r, c = np.concatenate(rows), np.concatenate(cols)
    graph = coo_matrix((np.ones(len(r), dtype=np.int8), (r, c)), shape=(len(unique),) * 2)
    _, labels = connected_components(graph, directed=False)
    return labels[inverse]


@dataclass
class Cluster:
    """One cluster's statistics (``pf_cluster_t``).

    Attributes:
        count: Particles in it.
        weight: Their total (normalised) weight.
        mean: Weighted mean ``(x, y, theta)`` (heading by circular mean).
        cov: ``(3, 3)`` covariance: xy block from weighted second moments, heading
            variance ``-2 ln R`` (R: mean resultant length), no cross terms.
    """

    count: int
    weight: float
    mean: np.ndarray
    cov: np.ndarray


def weighted_stats(poses: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Mean and covariance of a weighted pose set, as ``pf_cluster_stats`` forms the set's."""
    total = float(weights.sum())
    m = weights @ np.column_stack([poses[:, :2], np.cos(poses[:, 2]), np.sin(poses[:, 2])])
    mean = np.array([m[0] / total, m[1] / total, np.arctan2(m[3], m[2])])
    cov = np.zeros((3, 3))
    xy = poses[:, :2]
    cov[:2, :2] = (xy * weights[:, None]).T @ xy / total - np.outer(mean[:2], mean[:2])
    resultant = np.hypot(m[2], m[3]) / total
    cov[2, 2] = -2.0 * np.log(max(resultant, 1e-300))
    return mean, cov


def cluster_stats(poses: np.ndarray, weights: np.ndarray, labels: np.ndarray) -> list[Cluster]:
    """Statistics of each cluster, in label order (``pf_cluster_stats``)."""
    n = int(labels.max()) + 1 if len(labels) else 0
    count = np.bincount(labels, minlength=n)
    weight = np.bincount(labels, weights, minlength=n)
    x, y, theta = poses[:, 0], poses[:, 1], poses[:, 2]
    sums = [
        np.bincount(labels, weights * v, minlength=n)
        for v in (x, y, np.cos(theta), np.sin(theta), x * x, x * y, y * y)
    ]
    clusters = []
    for k in range(n):
        w = weight[k]
        if count[k] == 0 or w <= 0:
            continue
        mean = np.array([sums[0][k] / w, sums[1][k] / w, np.arctan2(sums[3][k], sums[2][k])])
        cov = np.zeros((3, 3))
        cov[0, 0] = sums[4][k] / w - mean[0] ** 2
        cov[0, 1] = cov[1, 0] = sums[5][k] / w - mean[0] * mean[1]
        cov[1, 1] = sums[6][k] / w - mean[1] ** 2
        resultant = np.hypot(sums[2][k], sums[3][k]) / w
        cov[2, 2] = -2.0 * np.log(max(resultant, 1e-300))
        clusters.append(Cluster(int(count[k]), float(w), mean, cov))
    return clusters


__all__ = [
    "BIN_SIZE",
    "Cluster",
    "bin_keys",
    "cluster_labels",
    "cluster_stats",
    "kld_count",
    "resample_limits",
    "weighted_stats",
]
