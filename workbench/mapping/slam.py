"""Graph SLAM for a planar laser: scan-matching front end, loop closures, pose-graph back end.

Each scan is placed by correlative matching against a local map made of the
last keyframes, starting from the odometry prediction. A scan becomes a
keyframe (a pose-graph node) after enough motion. Each new keyframe is
matched, with a wide window, against the map around nearby older keyframes;
a match scoring above a threshold adds a loop-closure edge and the graph is
re-optimised. Scans that are not keyframes keep their pose relative to the
keyframe before them. The map is built at the end from all scans at their
optimised poses.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from workbench.mapping.geometry import between, compose, transform_points, wrap_angle
from workbench.mapping.grid import OccupancyGrid
from workbench.mapping.likelihood import LikelihoodField
from workbench.mapping.matcher import match_scan
from workbench.mapping.posegraph import Edge, PoseGraph
from workbench.mapping.scan import Scan, densify


@dataclass
class SlamConfig:
    """Parameters of :func:`run_slam` (defaults suit indoor logs such as the Intel lab).

    Attributes:
        resolution: Cell size of the output map (m).
        match_resolution: Cell size of the scan-matching likelihood fields (m).
        match_sigma: Blur of the likelihood field (m).
        match_range: Readings beyond this are not used for matching (m).
        linear_window: Half-width of the front end's translation search (m).
        angular_window: Half-width of the front end's rotation search (rad).
        angular_step: Rotation step of the searches (rad).
        min_score: Below this match score the odometry prediction is kept.
        retry_score: Below this score the front end searches again in a wider window.
        retry_linear_window: Half-width of that wider translation search (m).
        retry_angular_window: Half-width of that wider rotation search (rad).
        prior_sigma: Std devs (m, rad) of the odometry prior of the front end's search.
        prior_weight: Weight of that prior against the mean likelihood.
        keyframe_distance: Travel that makes a new keyframe (m).
        keyframe_angle: Turn that makes a new keyframe (rad).
        local_map_keyframes: How many recent keyframes form the local map.
        loop_search_radius: Older keyframes closer than this are loop candidates (m).
        loop_min_separation: Keyframes this recent (in count) are not loop candidates.
        loop_linear_window: Half-width of the loop-closure translation search (m).
        loop_angular_window: Half-width of the loop-closure rotation search (rad).
        loop_min_score: Match score a loop closure must reach.
        loop_chain: Keyframes either side of a candidate that form its map.
        loop_every: Loop closure is tried on every this many keyframes.
        loop_max_chi2: A closure whose whitened squared error after optimisation exceeds
            this is rejected as a false match.
        sequential_sigma: Std devs (x, y, theta) of matched sequential edges.
        odometry_sigma: Std devs (x, y, theta) of edges from odometry alone.
        loop_sigma: Std devs (x, y, theta) of loop-closure edges.
        min_points: Scans with fewer valid readings are not matched.
        seed: Seed of the random generator (reserved for randomised steps; the
            current pipeline is deterministic).
    """

    resolution: float = 0.05
    match_resolution: float = 0.05
    match_sigma: float = 0.05
    match_range: float = 20.0
    linear_window: float = 0.4
    angular_window: float = float(np.radians(20.0))
    angular_step: float = float(np.radians(0.5))
    min_score: float = 0.25
    retry_score: float = 0.45
    retry_linear_window: float = 0.8
    retry_angular_window: float = float(np.radians(45.0))
    prior_sigma: tuple[float, float] = (0.2, float(np.radians(30.0)))
    prior_weight: float = 0.05
    keyframe_distance: float = 0.2
    keyframe_angle: float = float(np.radians(10.0))
    local_map_keyframes: int = 12
    loop_search_radius: float = 4.0
    loop_min_separation: int = 25
    loop_linear_window: float = 1.5
    loop_angular_window: float = float(np.radians(20.0))
    loop_min_score: float = 0.55
    loop_chain: int = 5
    loop_every: int = 2
    loop_max_chi2: float = 9.0
    sequential_sigma: tuple[float, float, float] = (0.02, 0.02, float(np.radians(0.5)))
    odometry_sigma: tuple[float, float, float] = (0.1, 0.1, float(np.radians(5.0)))
    loop_sigma: tuple[float, float, float] = (0.03, 0.03, float(np.radians(1.0)))
    min_points: int = 20
    seed: int = 0


@dataclass
class SlamResult:
    """The output of :func:`run_slam`.

    Attributes:
        poses: Estimated sensor pose per scan ``(N, 3)`` in the map frame (m, rad).
        stamps: Time per scan (s).
        keyframes: Index of the scan of each pose-graph node.
        graph: The optimised pose graph.
        loop_closures: ``(node_i, node_j)`` per accepted loop closure.
        scores: Front-end match score per scan (NaN where not matched).
    """

    poses: np.ndarray
    stamps: np.ndarray
    keyframes: list[int]
    graph: PoseGraph
    loop_closures: list[tuple[int, int]] = field(default_factory=list)
    scores: np.ndarray = field(default_factory=lambda: np.zeros(0))


class _Front:
    def __init__(self, scans: list[Scan], config: SlamConfig) -> None:
        self.scans = scans
        self.cfg = config
        self.points = [s.points(config.match_range) for s in scans]
        self.dense = [densify(p, 0.5 * config.match_resolution) for p in self.points]
        self.graph = PoseGraph()
        self.keyframes: list[int] = []  # scan index per node
        self.anchor = np.zeros(len(scans), dtype=np.int64)  # node per scan
        self.offset = np.zeros((len(scans), 3))  # pose of scan in its anchor node
        self.scores = np.full(len(scans), np.nan)
        self.loops: list[tuple[int, int]] = []
        self.rejected = 0

    def node_points(self, nodes: range | list[int]) -> np.ndarray:
        parts = [
            transform_points(self.graph.nodes[n], self.dense[self.keyframes[n]]) for n in nodes
        ]
        parts = [p for p in parts if len(p)]
        return np.concatenate(parts) if parts else np.zeros((0, 2))

    def _match(self, nodes, guess, points, linear, angular, factor, prior=None):
        cfg = self.cfg
        local = self.node_points(nodes)
        if len(local) < cfg.min_points or len(points) < cfg.min_points:
            return None
        reach = cfg.match_range + linear + 1.0
        bounds = (guess[0] - reach, guess[1] - reach, guess[0] + reach, guess[1] + reach)
        lik = LikelihoodField(
            local,
            cfg.match_resolution,
            cfg.match_sigma,
            margin=linear + 1.0,
            factor=factor,
            bounds=bounds,
        )
        return match_scan(
            lik,
            points,
            guess,
            linear_window=linear,
            angular_window=angular,
            angular_step=cfg.angular_step,
            prior=prior,
            prior_weight=cfg.prior_weight,
        )

    def _at_edge(self, pose: np.ndarray, guess: np.ndarray) -> bool:
        cfg = self.cfg
        shift = np.abs(pose[:2] - guess[:2]).max()
        turn = abs(float(wrap_angle(pose[2] - guess[2])))
        return bool(
            shift >= cfg.linear_window - cfg.match_resolution
            or turn >= cfg.angular_window - cfg.angular_step
        )

    def add_scan(self, index: int, prev_index: int | None, prev_pose: np.ndarray | None):
        cfg = self.cfg
        scan = self.scans[index]
        if prev_index is None:
            pose = np.array(scan.odom, dtype=float)
            node = self.graph.add_node(pose)
            self.keyframes.append(index)
            self.anchor[index] = node
            return pose
        delta = between(self.scans[prev_index].odom, scan.odom)
        guess = compose(prev_pose, delta)
        last = len(self.keyframes) - 1
        nodes = range(max(0, last - cfg.local_map_keyframes + 1), last + 1)
        result = self._match(
            nodes,
            guess,
            self.points[index],
            cfg.linear_window,
            cfg.angular_window,
            4,
            cfg.prior_sigma,
        )
        if result is not None and (
            result.score < cfg.retry_score or self._at_edge(result.grid_pose, guess)
        ):
            # A poor fit, or a best pose on the edge of the window, usually means the odometry
            # is off by more than the window: search a wider window and keep whichever
            # fits better.
            wide = self._match(
                nodes,
                guess,
                self.points[index],
                cfg.retry_linear_window,
                cfg.retry_angular_window,
                8,
                cfg.prior_sigma,
            )
            if wide is not None and wide.score > result.score:
                result = wide
        matched = result is not None and result.score >= cfg.min_score
        pose = result.pose if matched else guess
        if result is not None:
            self.scores[index] = result.score
        last_pose = self.graph.nodes[last]
        rel = between(last_pose, pose)
        moved = np.hypot(rel[0], rel[1]) >= cfg.keyframe_distance
        turned = abs(rel[2]) >= cfg.keyframe_angle
        if moved or turned:
            node = self.graph.add_node(pose)
            self.keyframes.append(index)
            sigma = cfg.sequential_sigma if matched else cfg.odometry_sigma
            self.graph.add_edge(Edge(last, node, rel, np.array(sigma)))
            self.anchor[index] = node
            if self.close_loop(node):
                pose = self.graph.nodes[node].copy()
        else:
            self.anchor[index] = last
            self.offset[index] = rel
        return pose

    def close_loop(self, node: int) -> bool:
        cfg = self.cfg
        newest_candidate = node - cfg.loop_min_separation
        if newest_candidate < 0 or node % cfg.loop_every:
            return False
        here = self.graph.nodes[node]
        old = self.graph.nodes[: newest_candidate + 1]
        dist = np.hypot(old[:, 0] - here[0], old[:, 1] - here[1])
        candidates = np.flatnonzero(dist < cfg.loop_search_radius)
        if len(candidates) == 0:
            return False
        best = int(candidates[np.argmin(dist[candidates])])
        lo = max(0, best - cfg.loop_chain)
        hi = min(newest_candidate, best + cfg.loop_chain)
        points = self.points[self.keyframes[node]]
        chain = range(lo, hi + 1)
        # Usually the estimate is already close: try a small window before the wide one.
        result = self._match(chain, here, points, cfg.linear_window, cfg.angular_window, 4)
        if result is not None and result.score < cfg.loop_min_score:
            result = self._match(
                chain, here, points, cfg.loop_linear_window, cfg.loop_angular_window, 8
            )
        if result is None or result.score < cfg.loop_min_score:
            return False
        rel = between(self.graph.nodes[best], result.pose)
        before = self.graph.nodes.copy()
        self.graph.add_edge(Edge(best, node, rel, np.array(cfg.loop_sigma), loop=True))
        self.graph.optimize()
        # A closure the rest of the graph cannot agree with is a false match: undo it.
        if self.graph.chi2()[-1] > cfg.loop_max_chi2:
            self.graph.edges.pop()
            self.graph.nodes = before
            self.rejected += 1
            return False
        self.loops.append((best, node))
        return True

    def poses(self) -> np.ndarray:
        base = self.graph.nodes[self.anchor]
        return compose(base, self.offset)


def run_slam(
    scans: list[Scan],
    config: SlamConfig | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> SlamResult:
    """Estimate the sensor trajectory of a scan sequence.

    Args:
        scans: Scans in time order, each with its odometry.
        config: Parameters (defaults when None).
        progress: Called as ``progress(done, total)`` after each scan.

    Returns:
        The poses of all scans and the pose graph.
    """
    config = config or SlamConfig()
    front = _Front(scans, config)
    prev_index: int | None = None
    prev_pose: np.ndarray | None = None
    for index in range(len(scans)):
        pose = front.add_scan(index, prev_index, prev_pose)
        prev_index, prev_pose = index, pose
        if progress is not None:
            progress(index + 1, len(scans))
    front.graph.optimize(iterations=20)
    return SlamResult(
        poses=front.poses(),
        stamps=np.array([s.stamp for s in scans]),
        keyframes=list(front.keyframes),
        graph=front.graph,
        loop_closures=list(front.loops),
        scores=front.scores,
    )


def build_map(
    scans: list[Scan], poses: np.ndarray, resolution: float = 0.05, max_range: float = 30.0
) -> OccupancyGrid:
    """Integrate scans at their poses into an occupancy grid that covers them.

    Args:
        scans: The scans.
        poses: Sensor pose per scan ``(N, 3)`` (m, rad).
        resolution: Cell size (m).
        max_range: Readings beyond this are not integrated (m).
    """
    ends = [transform_points(p, s.points(max_range)) for s, p in zip(scans, poses, strict=True)]
    ends.append(np.asarray(poses)[:, :2])
    grid = OccupancyGrid.covering(np.concatenate(ends), resolution, margin=1.0)
    for scan, pose in zip(scans, poses, strict=True):
        ranges = np.where(scan.ranges > max_range, np.inf, scan.ranges)
        grid.integrate_scan(
            pose,
            ranges,
            scan.angles,
            max_range=min(scan.max_range, max_range + 1e-9),
            min_range=scan.min_range,
        )
    return grid
