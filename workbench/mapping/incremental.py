"""Incremental graph SLAM: one scan at a time, as a live node needs it.

:class:`Slam` takes scans with their odometry and returns each scan's pose
in the map at once. A scan is processed (matched) only after the odometry
moved ``linear_update``, turned ``angular_update`` or ``temporal_update``
seconds passed since the last processed scan, as GMapping does; the others
are placed by odometry from the last processed one, which costs almost
nothing. A processed scan is matched against a local map of the last
keyframes (cached until the keyframes change) starting from the odometry
prediction. With ``match_covariance`` the match's score-surface covariance
tells which directions the match pins down: along the others (a corridor's
axis) the odometry prediction is kept, and with ``weigh_odometry`` the position
leans toward it wherever the match is clearly less sure than the odometry. After enough motion the scan becomes
a keyframe, a pose-graph node whose edge to the previous node carries the
information of odometry and match together; each new keyframe then tries a
loop closure (:mod:`workbench.mapping.loops`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.mapping.config import SlamConfig
from workbench.mapping.geometry import between, compose, transform_points, wrap_angle
from workbench.mapping.grid import OccupancyGrid
from workbench.mapping.likelihood import LikelihoodField
from workbench.mapping.loops import LoopOutcome, close_loop, information
from workbench.mapping.matcher import MatchResult, match_scan
from workbench.mapping.posegraph import Edge, PoseGraph
from workbench.mapping.scan import Scan, densify, free_ends
from workbench.mapping.uncertainty import odometry_covariance, score_surface_covariance, to_frame


@dataclass
class _Keyframe:
    scan: Scan
    odom: np.ndarray
    points: np.ndarray
    dense: np.ndarray


def match_points(scan: Scan, match_range: float) -> np.ndarray:
    """The scan's real returns closer than ``match_range`` (no-return readings excluded)."""
    ok = scan.valid()
    with np.errstate(invalid="ignore"):
        ok &= scan.ranges < match_range
    r, a = scan.ranges[ok], scan.angles[ok]
    return np.stack([r * np.cos(a), r * np.sin(a)], axis=1)


def lean_on_odometry(match: np.ndarray, guess: np.ndarray, covariance: np.ndarray) -> np.ndarray:
    """``match`` with its position along unconstrained directions taken from ``guess``.

    A direction is unconstrained when the covariance's std dev along it
    exceeds 1 m (the score surface marks those with a huge variance).
    """
    values, vectors = np.linalg.eigh(covariance[:2, :2])
    free = vectors[:, values > 1.0]
    out = np.asarray(match, dtype=float).copy()
    if free.shape[1]:
        out[:2] += free @ (free.T @ (guess[:2] - match[:2]))
    return out


def fuse_with_odometry(
    match: np.ndarray,
    match_covariance: np.ndarray,
    guess: np.ndarray,
    guess_covariance: np.ndarray,
) -> np.ndarray:
    """A scan match's position moved toward the odometry's prediction where the match is
    less certain than the odometry.

    Along each principal direction of the match's position covariance whose variance
    exceeds the odometry's, the position is the variance-weighted mean of the two (a
    corridor's axis: the odometry; a long wall seen at a slant: in between); along the
    others, and in heading, the match stands (odometry's systematic errors would leak
    into a map that a match pins down). Poses and covariances are in the map frame.
    """
    out = np.asarray(match, dtype=float).copy()
    values, vectors = np.linalg.eigh(0.5 * (match_covariance[:2, :2] + match_covariance[:2, :2].T))
    odometry = float(np.linalg.eigvalsh(guess_covariance[:2, :2]).max())
    weak = values > 2.0 * odometry
    if weak.any():
        weights = values[weak] / (values[weak] + odometry)
        basis = vectors[:, weak]
        out[:2] += basis @ (weights * (basis.T @ (np.asarray(guess, float)[:2] - out[:2])))
    return out


def front_window(config: SlamConfig, delta: np.ndarray) -> tuple[float, float, tuple[float, float]]:
    """Half-widths ``(m, rad)`` of the front end's search and the std devs ``(m, rad)`` of
    its odometry prior, after the odometry moved ``delta`` since the last processed scan.

    With ``odometry_window`` the window is three std devs of ``odometry_noise`` over
    ``delta`` (between ``min_window`` and the configured window) and the prior is a third
    of it; otherwise the configured window and ``prior_sigma``.
    """
    if not config.odometry_window:
        return config.linear_window, config.angular_window, config.prior_sigma
    cov = odometry_covariance(delta, config.odometry_noise)
    most_linear, most_angular = config.linear_window, config.angular_window
    least_linear = min(config.min_window[0], most_linear)
    least_angular = min(config.min_window[1], most_angular)
    linear = float(np.clip(3.0 * np.sqrt(cov[0, 0] + cov[1, 1]), least_linear, most_linear))
    angular = float(np.clip(3.0 * np.sqrt(cov[2, 2]), least_angular, most_angular))
    return linear, angular, (linear / 3.0, angular / 3.0)


class Slam:
    """Graph SLAM fed one scan at a time.

    Args:
        config: Parameters (defaults when None).
    """

    def __init__(self, config: SlamConfig | None = None) -> None:
        self.config = config or SlamConfig()
        self.graph = PoseGraph()
        self.keyframes: list[int] = []  # scan index per node
        self.loop_closures: list[tuple[int, int]] = []
        self.loop_attempts: list[LoopOutcome] = []
        self._frames: list[_Keyframe] = []
        self._anchor: list[int] = []  # node per scan
        self._offset: list[np.ndarray] = []  # pose of scan in its anchor node
        self._stamps: list[float] = []
        self._scores: list[float] = []
        self._last: tuple[int, np.ndarray, np.ndarray, float] | None = None  # processed
        self._latest_odom: np.ndarray | None = None
        self._version = 0  # bumped when optimisation moves nodes
        self._deferred = 0.0  # summed distances of closures added since the last optimisation
        self._fields: dict[tuple, LikelihoodField] = {}
        self._grid: OccupancyGrid | None = None
        self._grid_nodes = 0
        self._grid_version = -1
        self._drawn_poses = np.zeros((0, 3))  # keyframe poses when they were drawn

    # ----------------------------------------------------------------- public
    def add_scan(self, scan: Scan, odom_pose: np.ndarray | None = None) -> np.ndarray:
        """Add the next scan and return its sensor pose ``(x, y, theta)`` in the map.

        Args:
            scan: The scan (its ``stamp`` is used for ``temporal_update``).
            odom_pose: The sensor's odometric pose when the scan was taken; default
                ``scan.odom``.
        """
        odom = np.asarray(scan.odom if odom_pose is None else odom_pose, dtype=float).copy()
        index = len(self._anchor)
        self._latest_odom = odom
        self._stamps.append(float(scan.stamp))
        self._scores.append(float("nan"))
        if self._last is None:
            node = self.graph.add_node(odom)
            self._add_frame(index, scan, odom)
            self._anchor.append(node)
            self._offset.append(np.zeros(3))
            self._last = (index, odom, odom.copy(), float(scan.stamp))
            return odom.copy()
        _, prev_odom, prev_pose, prev_stamp = self._last
        delta = between(prev_odom, odom)
        guess = compose(prev_pose, delta)
        if not self._due(delta, float(scan.stamp) - prev_stamp):
            last = self._anchor[-1]
            self._anchor.append(last)
            self._offset.append(between(self.graph.nodes[last], guess))
            return guess
        pose = self._process(index, scan, odom, guess, delta, prev_pose)
        self._last = (index, odom, pose.copy(), float(scan.stamp))
        return pose

    def poses(self) -> np.ndarray:
        """Current pose estimate ``(N, 3)`` of every scan added so far."""
        if not self._anchor:
            return np.zeros((0, 3))
        base = self.graph.nodes[np.array(self._anchor)]
        return compose(base, np.array(self._offset))

    def pose(self) -> np.ndarray:
        """Current pose estimate of the latest scan."""
        node = self._anchor[-1]
        return compose(self.graph.nodes[node], self._offset[-1])

    def map_to_odom(self) -> np.ndarray:
        """The transform ``map -> odom`` that puts the latest odometry at :meth:`pose`."""
        if self._latest_odom is None:
            return np.zeros(3)
        return compose(self.pose(), between(self._latest_odom, np.zeros(3)))

    @property
    def stamps(self) -> np.ndarray:
        """Time of every scan added so far (s)."""
        return np.array(self._stamps)

    @property
    def scores(self) -> np.ndarray:
        """Front-end match score per scan (NaN where not matched)."""
        return np.array(self._scores)

    def optimize(self, iterations: int = 20) -> None:
        """Optimise the whole graph (at the end of a log, or now and then)."""
        self.graph.optimize(iterations=iterations)
        self._version += 1
        self._deferred = 0.0

    def map(self, resolution: float | None = None) -> OccupancyGrid:
        """The occupancy grid of the keyframes at their current poses.

        It starts as a ``map_size`` square round the first pose and grows to
        take in every scan. Keyframes added since the last call are
        integrated into the grid; after an optimisation moved a drawn keyframe's
        scan by half a cell or more, the grid is rebuilt.
        """
        cfg = self.config
        res = cfg.resolution if resolution is None else float(resolution)
        if (
            self._grid is None
            or self._grid.resolution != res
            or (self._grid_version != self._version and self._moved_since_drawn(res))
        ):
            first = self.graph.nodes[0] if len(self.graph.nodes) else np.zeros(3)
            half = 0.5 * cfg.map_size
            low = np.floor((first[:2] - half) / res) * res
            size = int(np.ceil(cfg.map_size / res))
            self._grid = OccupancyGrid(size, size, res, (low[0], low[1], 0.0))
            self._grid_nodes = 0
            self._grid_version = self._version
            self._drawn_poses = np.zeros((0, 3))
        grid = self._grid
        start = self._grid_nodes
        self._drawn_poses = np.vstack(
            [self._drawn_poses[:start], self.graph.nodes[start : len(self._frames)]]
        )
        for node in range(start, len(self._frames)):
            frame = self._frames[node]
            pose = self.graph.nodes[node]
            ends = transform_points(pose, free_ends(frame.scan, cfg.max_urange))
            if len(ends):
                grid.grow_to(np.vstack([ends, pose[None, :2]]), margin=1.0)
            grid.integrate_scan(
                pose,
                frame.scan.ranges,
                frame.scan.angles,
                max_range=frame.scan.max_range,
                min_range=frame.scan.min_range,
                free_range=cfg.max_urange,
            )
        self._grid_nodes = len(self._frames)
        self._grid_version = self._version
        return grid

    def _moved_since_drawn(self, resolution: float) -> bool:
        """Whether an optimisation moved a drawn keyframe's scan by half a cell or more (at
        the end of its longest beam): smaller corrections keep the grid, larger rebuild it."""
        drawn = self._grid_nodes
        if drawn == 0:
            return False
        now = self.graph.nodes[:drawn]
        then = self._drawn_poses[:drawn]
        reach = max(float(self.config.max_urange), 1.0)
        shift = np.hypot(*(now[:, :2] - then[:, :2]).T)
        turn = np.abs(np.angle(np.exp(1j * (now[:, 2] - then[:, 2]))))
        return bool(np.max(shift + reach * turn) >= 0.5 * resolution)

    # --------------------------------------------------------------- internal
    def _due(self, delta: np.ndarray, dt: float) -> bool:
        cfg = self.config
        if np.hypot(delta[0], delta[1]) >= cfg.linear_update:
            return True
        if abs(float(delta[2])) >= cfg.angular_update:
            return True
        return cfg.temporal_update >= 0 and dt >= cfg.temporal_update

    def _add_frame(self, index: int, scan: Scan, odom: np.ndarray) -> None:
        cfg = self.config
        points = match_points(scan, cfg.match_range)
        dense = densify(points, 0.5 * cfg.match_resolution, bridge=cfg.surface_bridge)
        self._frames.append(_Keyframe(scan, odom, points, dense))
        self.keyframes.append(index)

    def _node_points(self, nodes: range | list[int]) -> np.ndarray:
        parts = [transform_points(self.graph.nodes[n], self._frames[n].dense) for n in nodes]
        parts = [p for p in parts if len(p)]
        return np.concatenate(parts) if parts else np.zeros((0, 2))

    def _field(self, nodes: range, centre: np.ndarray, factor: int, cache: bool):
        cfg = self.config
        key = (nodes.start, nodes.stop, factor, self._version)
        if cache and key in self._fields:
            return self._fields[key]
        local = self._node_points(nodes)
        if len(local) < cfg.min_points:
            return None
        window = max(cfg.retry_linear_window, cfg.loop_linear_window)
        reach = cfg.match_range + window + 1.0
        bounds = (centre[0] - reach, centre[1] - reach, centre[0] + reach, centre[1] + reach)
        field = LikelihoodField(
            local,
            cfg.match_resolution,
            cfg.match_sigma,
            margin=window + 1.0,
            factor=factor,
            bounds=bounds,
        )
        if cache:
            self._fields = {k: v for k, v in self._fields.items() if k[:2] == key[:2]}
            self._fields[key] = field
        return field

    def _match(
        self,
        nodes: range,
        guess: np.ndarray,
        points: np.ndarray,
        linear: float,
        angular: float,
        prior: tuple[float, float] | None = None,
        cache: bool = False,
    ) -> MatchResult | None:
        cfg = self.config
        if len(points) < cfg.min_points:
            return None
        factor = 4 if linear <= cfg.linear_window + 1e-9 else 8
        centre = self.graph.nodes[nodes.stop - 1] if cache else guess
        field = self._field(nodes, centre, factor, cache)
        if field is None:
            return None
        result = match_scan(
            field,
            points,
            guess,
            linear_window=linear,
            angular_window=angular,
            angular_step=cfg.angular_step,
            prior=prior,
            prior_weight=cfg.prior_weight,
        )
        if cfg.match_covariance:
            cov = score_surface_covariance(
                field,
                points,
                result.pose,
                points_per_measurement=cfg.points_per_measurement,
            )
            result.covariance = cov + np.diag(np.square(cfg.covariance_floor))
        return result

    def _at_edge(self, pose: np.ndarray, guess: np.ndarray, linear: float, angular: float) -> bool:
        cfg = self.config
        shift = np.abs(pose[:2] - guess[:2]).max()
        turn = abs(float(wrap_angle(pose[2] - guess[2])))
        return bool(shift >= linear - cfg.match_resolution or turn >= angular - cfg.angular_step)

    def _process(
        self,
        index: int,
        scan: Scan,
        odom: np.ndarray,
        guess: np.ndarray,
        delta: np.ndarray,
        prev_pose: np.ndarray,
    ) -> np.ndarray:
        cfg = self.config
        points = match_points(scan, cfg.match_range)
        last = len(self._frames) - 1
        nodes = range(max(0, last - cfg.local_map_keyframes + 1), last + 1)
        args = (nodes, guess, points)
        linear, angular, prior = front_window(cfg, delta)
        result = self._match(*args, linear, angular, prior, True)
        if result is not None and (
            result.score < cfg.retry_score
            or self._at_edge(result.grid_pose, guess, linear, angular)
        ):
            # A poor fit, or a best pose on the edge of the window, usually means the odometry
            # is off by more than the window: search a wider window and keep whichever
            # fits better.
            wide = self._match(
                *args, cfg.retry_linear_window, cfg.retry_angular_window, cfg.prior_sigma, True
            )
            if wide is not None and wide.score > result.score:
                result = wide
        matched = result is not None and result.score >= cfg.min_score
        pose = guess
        if result is not None:
            self._scores[index] = result.score
        if matched and result is not None:
            pose = result.pose
            if result.covariance is not None and cfg.weigh_odometry:
                moved = odometry_covariance(delta, cfg.odometry_noise)
                prior = to_frame(moved, -float(prev_pose[2]))
                pose = fuse_with_odometry(result.pose, result.covariance, guess, prior)
            elif result.covariance is not None:
                pose = lean_on_odometry(result.pose, guess, result.covariance)
        last_pose = self.graph.nodes[last]
        rel = between(last_pose, pose)
        moved = np.hypot(rel[0], rel[1]) >= cfg.keyframe_distance
        turned = abs(rel[2]) >= cfg.keyframe_angle
        if not (moved or turned):
            self._anchor.append(last)
            self._offset.append(rel)
            return pose
        node = self.graph.add_node(pose)
        self._add_frame(index, scan, odom)
        self.graph.add_edge(
            self._sequential_edge(last, node, rel, odom, result if matched else None)
        )
        self._anchor.append(node)
        self._offset.append(np.zeros(3))
        outcome = close_loop(self.graph, node, self._loop_match, cfg, self._deferred)
        if outcome.reason != "no candidate":
            self.loop_attempts.append(outcome)
        # Only an accepted closure moves nodes: one refused after optimising restored them.
        if outcome.accepted:
            self.loop_closures.append((outcome.candidate, node))
            if outcome.optimized:
                self._deferred = 0.0
                self._version += 1
            else:
                self._deferred += outcome.mahalanobis2
            pose = self.graph.nodes[node].copy()
        return pose

    def _loop_match(
        self, chain: range, guess: np.ndarray, linear: float, angular: float
    ) -> MatchResult | None:
        points = self._frames[len(self._frames) - 1].points
        return self._match(chain, guess, points, linear, angular)

    def _sequential_edge(
        self, last: int, node: int, rel: np.ndarray, odom: np.ndarray, match: MatchResult | None
    ) -> Edge:
        cfg = self.config
        if not cfg.match_covariance:
            sigma = cfg.sequential_sigma if match is not None else cfg.odometry_sigma
            return Edge(last, node, rel, np.array(sigma))
        moved = between(self._frames[last].odom, odom)
        odo = to_frame(odometry_covariance(moved, cfg.odometry_noise), float(rel[2]))
        info = information(odo)
        if match is not None and match.covariance is not None:
            info = info + information(to_frame(match.covariance, float(self.graph.nodes[node][2])))
        return Edge(last, node, rel, np.array(cfg.sequential_sigma), information=info)
