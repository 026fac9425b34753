"""The sparse pose-graph optimiser."""

from __future__ import annotations

import numpy as np

from workbench.mapping import Edge, PoseGraph
from workbench.mapping.geometry import between, compose
from workbench.mapping.posegraph import _errors, _jacobian


def test_analytic_jacobian_matches_finite_differences():
    rng = np.random.default_rng(1)
    x = rng.normal(size=(5, 3))
    z = rng.normal(size=(4, 3))
    i, j = np.array([0, 1, 2, 0]), np.array([1, 2, 3, 4])
    jac = _jacobian(x, i, j, z, np.ones((4, 3)), 5).toarray()
    numeric = np.zeros_like(jac)
    e0 = _errors(x, i, j, z).reshape(-1)
    for k in range(15):
        d = np.zeros(15)
        d[k] = 1e-6
        numeric[:, k] = (_errors(x + d.reshape(5, 3), i, j, z).reshape(-1) - e0) / 1e-6
    np.testing.assert_allclose(jac, numeric, atol=1e-5)


def _square_tour(n_laps=2, side=4):
    poses = []
    for _ in range(n_laps):
        for corner in range(4):
            for step in range(side):
                theta = corner * np.pi / 2
                start = np.array([[0, 0], [side, 0], [side, side], [0, side]][corner], dtype=float)
                poses.append([*(start + step * np.array([np.cos(theta), np.sin(theta)])), theta])
    return np.array(poses)


def test_loop_closure_removes_accumulated_drift():
    rng = np.random.default_rng(2)
    truth = _square_tour()
    graph = PoseGraph()
    graph.add_node(truth[0])
    sigma = np.array([0.05, 0.05, 0.02])
    for k in range(1, len(truth)):
        z = between(truth[k - 1], truth[k]) + rng.normal(0, 1, 3) * sigma
        graph.add_node(compose(graph.nodes[-1], z))
        graph.add_edge(Edge(k - 1, k, z, sigma))
    lap = len(truth) // 2
    drift_before = np.abs(graph.nodes[lap:, :2] - truth[lap:, :2]).max()
    for k in range(lap, len(truth)):
        graph.add_edge(
            Edge(
                k - lap,
                k,
                between(truth[k - lap], truth[k]),
                np.array([0.01, 0.01, 0.005]),
                loop=True,
            )
        )
    graph.optimize(iterations=20)
    drift_after = np.abs(graph.nodes[lap:, :2] - truth[lap:, :2]).max()
    assert drift_after < 0.5 * drift_before
    np.testing.assert_allclose(graph.nodes[0], truth[0])  # the gauge stays put


def test_a_false_loop_is_down_weighted_by_the_robust_kernel():
    truth = _square_tour(n_laps=1, side=5)
    graph = PoseGraph()
    for p in truth:
        graph.add_node(p)
    sigma = np.array([0.02, 0.02, 0.01])
    for k in range(1, len(truth)):
        graph.add_edge(Edge(k - 1, k, between(truth[k - 1], truth[k]), sigma))
    graph.add_edge(Edge(0, len(truth) - 1, np.array([3.0, -2.0, 1.0]), sigma, loop=True))
    graph.optimize(iterations=30)
    assert np.abs(graph.nodes[:, :2] - truth[:, :2]).max() < 0.5
    assert graph.chi2()[-1] > 100  # the false closure stays unexplained
