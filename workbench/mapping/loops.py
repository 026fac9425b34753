"""Loop closure: match a new keyframe against older ones and check the match before trusting it.

A candidate closure is a scan match of the new keyframe against the map of
an older stretch of keyframes, searched in a window sized by how far the
pose graph lets the two poses move relative to each other. It must pass, in
order:

1. ``score``: the match explains enough of the scan;
2. ``degenerate``: the match is determined in every direction (its score
   surface covariance, see :mod:`workbench.mapping.uncertainty`). In a
   corridor the match is free along the corridor and simply returns the
   search's starting point: it "agrees" with the current estimate however
   wrong that is, and trusting it would freeze the drift into the map;
3. ``gate``: the difference between the match and the graph's estimate is
   plausible under their summed covariances (a Mahalanobis test against the
   graph's marginal covariance of the pair, not against the estimate alone);
4. ``chi2``: after adding the edge and optimising, the closure is explained.

With ``loop_defer_chi2`` a closure the estimate already explains is added without
optimising (check 4 then holds as it stands: the edge's squared error is the distance
measured in check 3); the graph is optimised once such closures add up past it.

A match that the current estimate already explains under the gate against the match's
covariance alone passes without the graph's marginal covariance (adding a covariance only
shrinks the Mahalanobis distance); a live map revisits known places every few keyframes,
and the marginal costs a sparse factorisation of the whole graph.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from workbench.mapping.config import SlamConfig
from workbench.mapping.geometry import between
from workbench.mapping.matcher import MatchResult
from workbench.mapping.posegraph import Edge, PoseGraph, _errors
from workbench.mapping.uncertainty import to_frame

#: ``match(chain_nodes, guess, linear_window, angular_window) -> MatchResult | None``
Matcher = Callable[[range, np.ndarray, float, float], "MatchResult | None"]


@dataclass
class LoopOutcome:
    """What happened to one loop-closure attempt.

    Attributes:
        accepted: Whether an edge was added.
        reason: ``"accepted"`` or the failed check (``"no candidate"``, ``"score"``,
            ``"degenerate"``, ``"gate"``, ``"chi2"``).
        candidate: The older node matched against (-1 when none).
        match: The match (None when none was made).
        mahalanobis2: Squared Mahalanobis distance of the match from the estimate (an
            upper bound, against the match's covariance alone, when that settled it).
        optimized: Whether the graph was optimised (the nodes may have moved).
    """

    accepted: bool
    reason: str
    candidate: int = -1
    match: MatchResult | None = None
    mahalanobis2: float = float("nan")
    optimized: bool = False


def information(covariance: np.ndarray) -> np.ndarray:
    """The inverse of a symmetric positive definite covariance, via its eigenvalues."""
    values, vectors = np.linalg.eigh(0.5 * (covariance + covariance.T))
    values = np.maximum(values, 1e-12)
    return (vectors / values) @ vectors.T


def check_and_add(
    graph: PoseGraph,
    candidate: int,
    node: int,
    match: MatchResult,
    config: SlamConfig,
    deferred: float = 0.0,
) -> LoopOutcome:
    """Checks 1-4 of a loop-closure match of ``node`` against ``candidate``; adds the edge if
    they pass and leaves the graph as it was if not. The graph is optimised unless the
    closure's distance plus ``deferred`` (those of closures added since the last
    optimisation) stays within ``loop_defer_chi2``."""
    if match.score < config.loop_min_score:
        return LoopOutcome(False, "score", candidate, match)
    z = between(graph.nodes[candidate], match.pose)
    if match.covariance is None:
        edge = Edge(candidate, node, z, np.array(config.loop_sigma), loop=True)
        d2 = float("nan")
    else:
        sigmas = match.sigmas()
        if sigmas[0] > config.loop_max_sigma[0] or sigmas[2] > config.loop_max_sigma[1]:
            return LoopOutcome(False, "degenerate", candidate, match)
        measured = to_frame(match.covariance, float(match.pose[2]))
        error = _errors(graph.nodes, np.array([candidate]), np.array([node]), z[None])[0]
        d2 = float(error @ information(measured) @ error)
        edge = Edge(
            candidate,
            node,
            z,
            np.array(config.loop_sigma),
            loop=True,
            information=information(measured),
        )
        if d2 + deferred <= config.loop_defer_chi2:
            graph.add_edge(edge)
            return LoopOutcome(True, "accepted", candidate, match, d2)
        if d2 > config.loop_gate:
            predicted = graph.relative_covariance(candidate, node, z)
            d2 = float(error @ information(predicted + measured) @ error)
        if d2 > config.loop_gate:
            return LoopOutcome(False, "gate", candidate, match, d2)
    before = graph.nodes.copy()
    graph.add_edge(edge)
    graph.optimize()
    if graph.chi2()[-1] > config.loop_max_chi2:
        graph.edges.pop()
        graph.nodes = before
        return LoopOutcome(False, "chi2", candidate, match, d2, optimized=True)
    return LoopOutcome(True, "accepted", candidate, match, d2, optimized=True)


def search_window(
    graph: PoseGraph, candidate: int, node: int, config: SlamConfig
) -> tuple[float, float]:
    """Translation and rotation half-widths covering three std devs of the pair's uncertainty."""
    cov = graph.relative_covariance(candidate, node)
    linear = 3.0 * float(np.sqrt(max(np.linalg.eigvalsh(cov[:2, :2]).max(), 0.0)))
    angular = 3.0 * float(np.sqrt(max(cov[2, 2], 0.0)))
    return (
        float(np.clip(linear, config.linear_window, config.loop_linear_window)),
        float(np.clip(angular, config.angular_window, config.loop_angular_window)),
    )


def close_loop(
    graph: PoseGraph, node: int, match: Matcher, config: SlamConfig, deferred: float = 0.0
) -> LoopOutcome:
    """Try to close a loop from ``node`` to the nearest old enough keyframe (``deferred``: see
    :func:`check_and_add`)."""
    newest = node - config.loop_min_separation
    if newest < 0 or node % config.loop_every:
        return LoopOutcome(False, "no candidate")
    here = graph.nodes[node]
    old = graph.nodes[: newest + 1]
    dist = np.hypot(old[:, 0] - here[0], old[:, 1] - here[1])
    candidates = np.flatnonzero(dist < config.loop_search_radius)
    if len(candidates) == 0:
        return LoopOutcome(False, "no candidate")
    best = int(candidates[np.argmin(dist[candidates])])
    chain = range(max(0, best - config.loop_chain), min(newest, best + config.loop_chain) + 1)
    # Usually the estimate is already close: try a small window before the wide one.
    result = match(chain, here, config.linear_window, config.angular_window)
    if result is not None and result.score < config.loop_min_score:
        if config.match_covariance:
            linear, angular = search_window(graph, best, node, config)
        else:
            linear, angular = config.loop_linear_window, config.loop_angular_window
        result = match(chain, here, linear, angular)
    if result is None:
        return LoopOutcome(False, "score", best)
    return check_and_add(graph, best, node, result, config, deferred)
