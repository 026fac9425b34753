"""Loop closures are checked against the match's and the graph's uncertainty."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import Edge, LikelihoodField, PoseGraph, SlamConfig, match_scan
from workbench.mapping.geometry import between, compose, transform_points
from workbench.mapping.loops import check_and_add


def _out_and_back(scale: float) -> tuple[np.ndarray, PoseGraph]:
    """Truth and a graph of a drive 10 m down a corridor and back, the odometry of the way
    back ``scale`` too long."""
    out = [[0.2 * k, 0.0, 0.0] for k in range(51)]
    back = [[10.0 - 0.2 * k, 0.0, np.pi] for k in range(1, 51)]
    truth = np.array(out + back)
    graph = PoseGraph()
    graph.add_node(truth[0])
    sigma = np.array([0.02, 0.02, np.radians(0.5)])
    for k in range(1, len(truth)):
        z = between(truth[k - 1], truth[k])
        if k > 50:
            z = z * np.array([1 + scale, 1 + scale, 1.0])
        graph.add_node(compose(graph.nodes[-1], z))
        graph.add_edge(Edge(k - 1, k, z, sigma))
    return truth, graph


def _corridor_points() -> tuple[LikelihoodField, np.ndarray]:
    xs = np.linspace(-10, 30, 1600)
    walls = np.concatenate(
        [np.column_stack([xs, xs * 0 + 1.0]), np.column_stack([xs, xs * 0 - 1.0])]
    )
    ahead = np.linspace(-4, 4, 80)
    scan = np.concatenate(
        [np.column_stack([ahead, ahead * 0 + 1.0]), np.column_stack([ahead, ahead * 0 - 1.0])]
    )
    return LikelihoodField(walls, 0.05, 0.05), scan


def test_a_corridor_closure_that_agrees_with_the_drifted_estimate_is_rejected():
    truth, graph = _out_and_back(scale=0.05)
    node, candidate = 95, 5  # the same place (x = 1 m), seen on the way out and back
    assert np.hypot(*(truth[node, :2] - truth[candidate, :2])) < 1e-9
    drift = graph.nodes[node, 0] - graph.nodes[candidate, 0]
    assert abs(drift) > 0.4  # the estimate thinks they lie almost half a metre apart
    field, scan = _corridor_points()
    # The match starts from the estimate and, along the corridor, stays there.
    prior = (0.2, np.radians(10.0))
    match = match_scan(field, scan, graph.nodes[node], prior=prior, covariance=True)
    assert abs(match.pose[0] - graph.nodes[node, 0]) < 0.1
    assert match.score > SlamConfig().loop_min_score  # the score check passes

    # Trusting the match as a precise constraint (no covariance) freezes the drift in.
    frozen = PoseGraph(graph.nodes.copy(), list(graph.edges))
    legacy = match_scan(field, scan, graph.nodes[node], prior=prior)
    outcome = check_and_add(frozen, candidate, node, legacy, SlamConfig(match_covariance=False))
    assert outcome.accepted
    assert abs(frozen.nodes[node, 0] - frozen.nodes[candidate, 0]) > 0.4

    # Checked against its own uncertainty it is refused, and the graph is untouched.
    edges = len(graph.edges)
    outcome = check_and_add(graph, candidate, node, match, SlamConfig())
    assert not outcome.accepted and outcome.reason == "degenerate"
    assert len(graph.edges) == edges


def test_a_precise_closure_far_outside_the_graph_uncertainty_is_rejected():
    truth, graph = _out_and_back(scale=0.0)
    node, candidate = 95, 5
    # A well-determined match that puts the node 2 m away from where a drift-free graph says.
    wrong = compose(graph.nodes[node], np.array([2.0, 0.0, 0.0]))
    match = match_scan(*_room(wrong), wrong, covariance=True)
    assert match.sigmas()[0] < 0.1
    outcome = check_and_add(graph, candidate, node, match, SlamConfig())
    assert outcome.reason == "gate" and outcome.mahalanobis2 > 100


def _room(pose: np.ndarray) -> tuple[LikelihoodField, np.ndarray]:
    """A closed 4 m x 3 m room and its scan taken from its middle at ``pose``."""
    t = np.linspace(0, 1, 200)[:, None]
    corners = np.array([[-2, -1.5], [2, -1.5], [2, 1.5], [-2, 1.5], [-2, -1.5]], dtype=float)
    walls = np.concatenate(
        [a + t * (b - a) for a, b in zip(corners[:-1], corners[1:], strict=True)]
    )
    return LikelihoodField(transform_points(pose, walls), 0.05, 0.05), walls[::3]


def test_relative_covariance_of_a_chain_is_the_sum_of_its_edges():
    graph = PoseGraph()
    sigma = np.array([0.1, 0.05, 0.01])
    for k in range(4):
        graph.add_node([k * 1.0, 0.0, 0.0])
    for k in range(3):
        graph.add_edge(Edge(k, k + 1, np.array([1.0, 0.0, 0.0]), sigma))
    cov = graph.relative_covariance(1, 2)
    np.testing.assert_allclose(np.diag(cov), sigma**2, rtol=1e-6)
    # Across two edges the heading uncertainty of the first one moves the second's end.
    cov = graph.relative_covariance(1, 3)
    assert cov[0, 0] == pytest.approx(2 * sigma[0] ** 2, rel=1e-6)
    assert cov[1, 1] == pytest.approx(2 * sigma[1] ** 2 + sigma[2] ** 2, rel=1e-6)


def _closure_seen_off(shift: float):  # type: ignore[no-untyped-def]
    """A drift-free out-and-back graph and a loop-closure match of node 95 against node 5
    (the same place) that sees it ``shift`` m along x off the estimate."""
    _, graph = _out_and_back(scale=0.0)
    node, candidate = 95, 5
    seen = compose(graph.nodes[node], np.array([shift, 0.0, 0.0]))
    match = match_scan(*_room(seen), graph.nodes[node], covariance=True)
    return graph, candidate, node, match


def test_a_closure_the_estimate_explains_is_added_without_optimising():
    # 5 mm off: well inside the match's own uncertainty.
    graph, candidate, node, match = _closure_seen_off(0.005)
    before = graph.nodes.copy()
    edges = len(graph.edges)
    config = SlamConfig(loop_defer_chi2=1.0)
    outcome = check_and_add(graph, candidate, node, match, config)
    assert outcome.accepted and not outcome.optimized
    assert 0.0 < outcome.mahalanobis2 < 1.0
    assert len(graph.edges) == edges + 1 and graph.edges[-1].loop
    np.testing.assert_array_equal(graph.nodes, before)  # nothing moved: not optimised
    assert graph.chi2()[-1] == pytest.approx(outcome.mahalanobis2)  # check 4 holds as is

    # Once the deferred closures add up past the limit the graph is optimised.
    graph.edges.pop()
    deferred = 1.0 - 0.5 * outcome.mahalanobis2
    outcome = check_and_add(graph, candidate, node, match, config, deferred=deferred)
    assert outcome.accepted and outcome.optimized


def test_a_closure_that_moves_the_estimate_is_optimised_at_once():
    # 6 cm off a drift-free graph: plausible (the gate passes) but not explained as it stands.
    graph, candidate, node, match = _closure_seen_off(0.06)
    before = graph.nodes.copy()
    outcome = check_and_add(graph, candidate, node, match, SlamConfig(loop_defer_chi2=1.0))
    assert outcome.accepted and outcome.optimized
    assert outcome.mahalanobis2 > 1.0
    assert np.abs(graph.nodes - before).max() > 0.01
