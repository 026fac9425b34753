"""A 2-D pose graph optimised by sparse Gauss-Newton (Levenberg-Marquardt damped) with scipy.

Each edge ``(i, j, z, sqrt_info)`` says that pose ``j`` seen from pose ``i``
is ``z``; its residual is ``sqrt_info · (z⁻¹ ⊕ x_i⁻¹ ⊕ x_j)`` (with a wrapped
angle), linearised analytically. Loop-closure edges use a Cauchy kernel by
iteratively reweighting, and node 0 is held fixed (the gauge).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import sparse
from scipy.sparse.linalg import spsolve

from workbench.mapping.geometry import wrap_angle


@dataclass
class Edge:
    """A relative-pose constraint from node ``i`` to node ``j``.

    Attributes:
        i: From node.
        j: To node.
        z: Measured pose of ``j`` in ``i``'s frame ``(x, y, theta)``.
        sigma: Standard deviations ``(x, y, theta)`` (m, m, rad) of the measurement.
        loop: Whether this is a loop closure (robust kernel applies).
    """

    i: int
    j: int
    z: np.ndarray
    sigma: np.ndarray
    loop: bool = False


@dataclass
class PoseGraph:
    """Nodes (poses ``(x, y, theta)``) and relative-pose edges.

    Attributes:
        nodes: ``(n, 3)`` array of poses (m, rad), updated by :meth:`optimize`.
        edges: The constraints.
        cauchy: Scale of the Cauchy kernel on loop edges (in standard deviations).
    """

    nodes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    edges: list[Edge] = field(default_factory=list)
    cauchy: float = 3.0

    def add_node(self, pose: np.ndarray) -> int:
        """Append a node and return its index."""
        self.nodes = np.vstack([self.nodes, np.asarray(pose, dtype=float).reshape(1, 3)])
        return len(self.nodes) - 1

    def add_edge(self, edge: Edge) -> None:
        """Append a constraint."""
        self.edges.append(edge)

    def _arrays(self):
        i = np.array([e.i for e in self.edges], dtype=np.int64)
        j = np.array([e.j for e in self.edges], dtype=np.int64)
        z = np.array([e.z for e in self.edges], dtype=float).reshape(-1, 3)
        w = 1.0 / np.array([e.sigma for e in self.edges], dtype=float).reshape(-1, 3)
        loop = np.array([e.loop for e in self.edges], dtype=bool)
        return i, j, z, w, loop

    def residuals(self, nodes: np.ndarray | None = None) -> np.ndarray:
        """Whitened residuals ``(m, 3)`` of all edges at ``nodes`` (default: current)."""
        x = self.nodes if nodes is None else nodes
        i, j, z, w, _ = self._arrays()
        return _errors(x, i, j, z) * w

    def chi2(self) -> np.ndarray:
        """Squared whitened error per edge."""
        return (self.residuals() ** 2).sum(axis=1)

    def optimize(self, iterations: int = 10, tolerance: float = 1e-6) -> float:
        """Optimise the node poses in place; returns the final robust cost."""
        if len(self.edges) == 0 or len(self.nodes) < 2:
            return 0.0
        i, j, z, w, loop = self._arrays()
        x = self.nodes.copy()
        n = len(x)
        lam = 1e-4
        cost = _cost(_errors(x, i, j, z) * w, loop, self.cauchy)
        for _ in range(iterations):
            e = _errors(x, i, j, z) * w
            rw = _robust_weights(e, loop, self.cauchy)
            jac = _jacobian(x, i, j, z, w * rw[:, None], n)
            r = (e * rw[:, None]).reshape(-1)
            h = (jac.T @ jac).tocsc()
            g = jac.T @ r
            # Fix node 0 (the gauge) by removing its columns.
            keep = np.arange(3, 3 * n)
            h = h[keep][:, keep]
            g = g[keep]
            while True:
                damped = h + sparse.diags(lam * (h.diagonal() + 1e-9))
                dx = -spsolve(damped.tocsc(), g)
                candidate = x.copy()
                candidate[1:] += dx.reshape(-1, 3)
                candidate[:, 2] = wrap_angle(candidate[:, 2])
                new_cost = _cost(_errors(candidate, i, j, z) * w, loop, self.cauchy)
                if new_cost <= cost or lam > 1e6:
                    break
                lam *= 10.0
            if new_cost > cost:
                break
            improvement = cost - new_cost
            x, cost = candidate, new_cost
            lam = max(lam / 10.0, 1e-8)
            if improvement <= tolerance * max(cost, 1.0) or np.abs(dx).max() < 1e-7:
                break
        self.nodes = x
        return float(cost)


def _errors(x: np.ndarray, i: np.ndarray, j: np.ndarray, z: np.ndarray) -> np.ndarray:
    ci, si = np.cos(x[i, 2]), np.sin(x[i, 2])
    dx = x[j, 0] - x[i, 0]
    dy = x[j, 1] - x[i, 1]
    lx = ci * dx + si * dy  # x_j in frame i
    ly = -si * dx + ci * dy
    cz, sz = np.cos(z[:, 2]), np.sin(z[:, 2])
    ex = cz * (lx - z[:, 0]) + sz * (ly - z[:, 1])
    ey = -sz * (lx - z[:, 0]) + cz * (ly - z[:, 1])
    et = wrap_angle(x[j, 2] - x[i, 2] - z[:, 2])
    return np.stack([ex, ey, et], axis=1)


def _robust_weights(e: np.ndarray, loop: np.ndarray, scale: float) -> np.ndarray:
    s2 = (e**2).sum(axis=1)
    weights = np.ones(len(e))
    weights[loop] = 1.0 / np.sqrt(1.0 + s2[loop] / (scale * scale))
    return weights


def _cost(e: np.ndarray, loop: np.ndarray, scale: float) -> float:
    s2 = (e**2).sum(axis=1)
    c2 = scale * scale
    return float(s2[~loop].sum() + (c2 * np.log1p(s2[loop] / c2)).sum())


def _jacobian(x, i, j, z, w, n) -> sparse.csr_matrix:
    m = len(i)
    ci, si = np.cos(x[i, 2]), np.sin(x[i, 2])
    dx = x[j, 0] - x[i, 0]
    dy = x[j, 1] - x[i, 1]
    cz, sz = np.cos(z[:, 2]), np.sin(z[:, 2])
    # d(lx, ly)/d(xj, yj) = R_i^T ; d/d(xi, yi) = -R_i^T ; d/dtheta_i = [ly, -lx] rotated form
    a11, a12, a21, a22 = ci, si, -si, ci
    dl_dth = np.stack([-si * dx + ci * dy, -ci * dx - si * dy], axis=1)
    # e_xy = R_z^T (l - t_z): multiply by R_z^T
    b11, b12, b21, b22 = cz, sz, -sz, cz
    j11 = b11 * a11 + b12 * a21
    j12 = b11 * a12 + b12 * a22
    j21 = b21 * a11 + b22 * a21
    j22 = b21 * a12 + b22 * a22
    jt1 = b11 * dl_dth[:, 0] + b12 * dl_dth[:, 1]
    jt2 = b21 * dl_dth[:, 0] + b22 * dl_dth[:, 1]
    rows, cols, vals = [], [], []

    def put(r_off, c_node, c_off, v):
        rows.append(3 * np.arange(m) + r_off)
        cols.append(3 * c_node + c_off)
        vals.append(v)

    put(0, j, 0, j11 * w[:, 0])
    put(0, j, 1, j12 * w[:, 0])
    put(1, j, 0, j21 * w[:, 1])
    put(1, j, 1, j22 * w[:, 1])
    put(0, i, 0, -j11 * w[:, 0])
    put(0, i, 1, -j12 * w[:, 0])
    put(1, i, 0, -j21 * w[:, 1])
    put(1, i, 1, -j22 * w[:, 1])
    put(0, i, 2, jt1 * w[:, 0])
    put(1, i, 2, jt2 * w[:, 1])
    put(2, j, 2, w[:, 2])
    put(2, i, 2, -w[:, 2])
    return sparse.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(3 * m, 3 * n)
    )
