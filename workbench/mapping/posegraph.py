"""A 2-D pose graph optimised by sparse Gauss-Newton (Levenberg-Marquardt damped) with scipy.

Each edge ``(i, j, z, sqrt_info)`` says that pose ``j`` seen from pose ``i``
is ``z``; its residual is ``sqrt_info · (z⁻¹ ⊕ x_i⁻¹ ⊕ x_j)`` (with a wrapped
angle, expressed in the frame of ``z``), linearised analytically. An edge's
uncertainty is either three standard deviations or a full 3 x 3 information
matrix (a scan match in a corridor knows its position across the corridor
far better than along it). Loop-closure edges use a Cauchy kernel by
iteratively reweighting, and node 0 is held fixed (the gauge). The graph
also gives the marginal covariance of the relative pose of two nodes, which
loop closures are checked against.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import sparse
from scipy.sparse.linalg import splu, spsolve

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
        information: Optional 3 x 3 information matrix of the error (in the frame of
            ``z``); when given it replaces ``sigma``.
    """

    i: int
    j: int
    z: np.ndarray
    sigma: np.ndarray
    loop: bool = False
    information: np.ndarray | None = None

    def sqrt_information(self) -> np.ndarray:
        """``S`` with ``S.T @ S`` the information matrix (whitened error = ``S @ e``)."""
        if self.information is None:
            return np.diag(1.0 / np.asarray(self.sigma, dtype=float))
        info = 0.5 * (self.information + self.information.T)
        return np.linalg.cholesky(info + 1e-12 * np.eye(3)).T


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
    _stacked: _EdgeArrays | None = field(default=None, init=False, repr=False, compare=False)

    def add_node(self, pose: np.ndarray) -> int:
        """Append a node and return its index."""
        self.nodes = np.vstack([self.nodes, np.asarray(pose, dtype=float).reshape(1, 3)])
        return len(self.nodes) - 1

    def add_edge(self, edge: Edge) -> None:
        """Append a constraint."""
        self.edges.append(edge)

    def _arrays(self):
        """The edges as arrays, extended as edges are appended (a live graph grows by a few
        edges between optimisations; whitening every edge anew each time dominated)."""
        stacked = self._stacked
        if stacked is None or not stacked.prefix_of(self.edges):
            stacked = self._stacked = _EdgeArrays.of(self.edges)
        else:
            stacked.sync(self.edges)
        return stacked.i, stacked.j, stacked.z, stacked.w, stacked.loop

    def residuals(self, nodes: np.ndarray | None = None) -> np.ndarray:
        """Whitened residuals ``(m, 3)`` of all edges at ``nodes`` (default: current)."""
        x = self.nodes if nodes is None else nodes
        i, j, z, w, _ = self._arrays()
        return _whiten(_errors(x, i, j, z), w)

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
        cost = _cost(_whiten(_errors(x, i, j, z), w), loop, self.cauchy)
        for _ in range(iterations):
            e = _whiten(_errors(x, i, j, z), w)
            rw = _robust_weights(e, loop, self.cauchy)
            jac = _jacobian(x, i, j, z, w * rw[:, None, None], n)
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
                new_cost = _cost(_whiten(_errors(candidate, i, j, z), w), loop, self.cauchy)
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

    def information_matrix(self) -> sparse.csc_matrix:
        """``J^T J`` of the whitened (robustly weighted) errors at the current nodes, node 0 removed."""
        n = len(self.nodes)
        if not self.edges:
            return sparse.identity(3 * max(n - 1, 0), format="csc") * 1e-9
        i, j, z, w, loop = self._arrays()
        e = _whiten(_errors(self.nodes, i, j, z), w)
        rw = _robust_weights(e, loop, self.cauchy)
        jac = _jacobian(self.nodes, i, j, z, w * rw[:, None, None], n)
        h = (jac.T @ jac).tocsc()
        keep = np.arange(3, 3 * n)
        return (h[keep][:, keep] + sparse.identity(len(keep)) * 1e-9).tocsc()

    def relative_covariance(self, i: int, j: int, z: np.ndarray | None = None) -> np.ndarray:
        """Marginal covariance ``(3, 3)`` of the error of a measurement ``z`` of node ``j``
        seen from node ``i`` (default: their current relative pose), in ``z``'s frame.

        It is how far the graph lets the pair move relative to each other, from
        the inverse of its information matrix (node 0 held fixed).
        """
        x = self.nodes
        if z is None:
            z = between_pose(x[i], x[j])
        cols = [3 * k - 3 + c for k in (i, j) if k > 0 for c in range(3)]
        joint = np.zeros((6, 6))
        if cols:
            h = self.information_matrix()
            rhs = np.zeros((h.shape[0], len(cols)))
            rhs[cols, np.arange(len(cols))] = 1.0
            solved = splu(h).solve(rhs)[cols]
            index = [a for a, k in enumerate((i, i, i, j, j, j)) if k > 0]
            joint[np.ix_(index, index)] = solved
        jac = _jacobian(
            x, np.array([i]), np.array([j]), np.asarray(z, float)[None], np.eye(3)[None], len(x)
        ).toarray()
        a = np.concatenate([jac[:, 3 * i : 3 * i + 3], jac[:, 3 * j : 3 * j + 3]], axis=1)
        return a @ joint @ a.T


class _EdgeArrays:
    """Edge fields stacked into arrays, for the edges ``edges[:count]`` it was built from."""

    def __init__(self) -> None:
        self.objects: list[Edge] = []
        self.i = np.zeros(0, dtype=np.int64)
        self.j = np.zeros(0, dtype=np.int64)
        self.z = np.zeros((0, 3))
        self.w = np.zeros((0, 3, 3))
        self.loop = np.zeros(0, dtype=bool)

    @classmethod
    def of(cls, edges: list[Edge]) -> _EdgeArrays:
        stacked = cls()
        stacked.sync(edges)
        return stacked

    def prefix_of(self, edges: list[Edge]) -> bool:
        """Whether the stacked edges are still ``edges``' first ones (or ``edges`` is a
        prefix of them, after edges were popped), the same objects unchanged."""
        k = min(len(self.objects), len(edges))
        return k == 0 or (self.objects[k - 1] is edges[k - 1] and self.objects[0] is edges[0])

    def sync(self, edges: list[Edge]) -> None:
        count = len(self.objects)
        if len(edges) < count:
            del self.objects[len(edges) :]
            k = len(edges)
            self.i, self.j, self.z = self.i[:k], self.j[:k], self.z[:k]
            self.w, self.loop = self.w[:k], self.loop[:k]
            return
        new = edges[count:]
        if not new:
            return
        self.objects.extend(new)
        self.i = np.concatenate([self.i, np.array([e.i for e in new], dtype=np.int64)])
        self.j = np.concatenate([self.j, np.array([e.j for e in new], dtype=np.int64)])
        self.z = np.concatenate([self.z, np.array([e.z for e in new], dtype=float).reshape(-1, 3)])
        w = np.array([e.sqrt_information() for e in new], dtype=float).reshape(-1, 3, 3)
        self.w = np.concatenate([self.w, w])
        self.loop = np.concatenate([self.loop, np.array([e.loop for e in new], dtype=bool)])


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


def _whiten(e: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Whitened errors ``S_k @ e_k`` for ``(m, 3)`` errors and ``(m, 3, 3)`` or ``(m, 3)`` ``S``."""
    if w.ndim == 2:
        return e * w
    return np.einsum("kab,kb->ka", w, e)


def between_pose(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The pose of ``b`` in the frame of ``a`` (``a⁻¹ ⊕ b``)."""
    c, s = np.cos(a[2]), np.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return np.array([c * dx + s * dy, -s * dx + c * dy, float(wrap_angle(b[2] - a[2]))])


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
    """Sparse Jacobian ``(3m, 3n)`` of the whitened errors; ``w`` is ``(m, 3)`` (diagonal
    square-root information) or ``(m, 3, 3)`` (full)."""
    m = len(i)
    ci, si = np.cos(x[i, 2]), np.sin(x[i, 2])
    dx = x[j, 0] - x[i, 0]
    dy = x[j, 1] - x[i, 1]
    cz, sz = np.cos(z[:, 2]), np.sin(z[:, 2])
    # e_xy = R_z^T (R_i^T (t_j - t_i) - t_z), e_theta = theta_j - theta_i - theta_z.
    a11, a12, a21, a22 = ci, si, -si, ci
    dl_dth = np.stack([-si * dx + ci * dy, -ci * dx - si * dy], axis=1)
    b11, b12, b21, b22 = cz, sz, -sz, cz
    jj = np.zeros((m, 3, 3))
    jj[:, 0, 0] = b11 * a11 + b12 * a21
    jj[:, 0, 1] = b11 * a12 + b12 * a22
    jj[:, 1, 0] = b21 * a11 + b22 * a21
    jj[:, 1, 1] = b21 * a12 + b22 * a22
    jj[:, 2, 2] = 1.0
    ji = -jj.copy()
    ji[:, 0, 2] = b11 * dl_dth[:, 0] + b12 * dl_dth[:, 1]
    ji[:, 1, 2] = b21 * dl_dth[:, 0] + b22 * dl_dth[:, 1]
    ji[:, 2, 2] = -1.0
    w = np.asarray(w, dtype=float)
    if w.ndim == 2:
        w = w[:, :, None] * np.eye(3)[None]
    ji = np.einsum("kab,kbc->kac", w, ji)
    jj = np.einsum("kab,kbc->kac", w, jj)
    rows = np.repeat(3 * np.arange(m)[:, None] + np.arange(3)[None], 3, axis=1)  # (m, 9)
    col_off = np.tile(np.arange(3), 3)[None]
    cols_i = 3 * i[:, None] + col_off
    cols_j = 3 * j[:, None] + col_off
    return sparse.csr_matrix(
        (
            np.concatenate([ji.reshape(m, 9).ravel(), jj.reshape(m, 9).ravel()]),
            (
                np.concatenate([rows.ravel(), rows.ravel()]),
                np.concatenate([cols_i.ravel(), cols_j.ravel()]),
            ),
        ),
        shape=(3 * m, 3 * n),
    )
