"""The parameters of graph SLAM (:class:`~workbench.mapping.incremental.Slam`, ``run_slam``)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class SlamConfig:
    """Parameters of SLAM (defaults suit indoor logs such as the Intel lab).

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
        loop_linear_window: Largest half-width of the loop-closure translation search (m);
            the window is three standard deviations of the graph's uncertainty of the
            pair, between ``linear_window`` and this.
        loop_angular_window: Largest half-width of the loop-closure rotation search (rad).
        loop_min_score: Match score a loop closure must reach.
        loop_chain: Keyframes either side of a candidate that form its map.
        loop_every: Loop closure is tried on every this many keyframes.
        loop_max_chi2: A closure whose whitened squared error after optimisation exceeds
            this is rejected as a false match.
        loop_defer_chi2: A closure the current estimate already explains (its squared
            Mahalanobis distance under the match's own covariance at most this) is added
            without optimising the graph, until those added since the last optimisation
            sum past this; 0 optimises after every closure. A live robot revisits known
            places every few keyframes, and most closures then agree to a fraction of a
            std dev: optimising the whole graph for each moved nothing.
        loop_max_sigma: A loop-closure match must be at least this well determined:
            largest std dev of its position (m) and of its heading (rad), from the score
            surface. A match in a corridor knows nothing along it: it would only repeat
            the current (drifted) estimate, so it is rejected.
        loop_gate: Largest squared Mahalanobis distance between a loop-closure match and
            the graph's estimate, under their summed covariances (99.9 % of chi-square
            with 3 degrees of freedom).
        sequential_sigma: Std devs (x, y, theta) of matched sequential edges when
            ``match_covariance`` is off.
        odometry_sigma: Std devs (x, y, theta) of edges from odometry alone when
            ``match_covariance`` is off.
        loop_sigma: Std devs (x, y, theta) of loop-closure edges when ``match_covariance``
            is off.
        match_covariance: Estimate each match's covariance from its score surface, lean on
            odometry along directions the match does not constrain, weight pose-graph edges
            by it and check loop closures against it.
        covariance_floor: Std devs (x, y, theta) added to every match covariance.
        points_per_measurement: How many scan points count as one independent
            measurement in the score-surface covariance.
        weigh_odometry: Move each match's position toward the odometry's prediction along
            directions where the match's variance is over twice the odometry's (from
            ``odometry_noise``), by their variance-weighted mean. A live robot's wheel
            odometry between two scans is good to millimetres while a match along a wall
            can slide by centimetres; logs whose odometry has a scale bias map better
            without (only unconstrained directions then take the odometry).
        odometry_window: Size the front end's search window from ``odometry_noise``: three
            std devs of the motion since the last processed scan, at least
            ``min_window`` and at most ``linear_window`` / ``angular_window`` (a live
            robot's scans come a fraction of a second apart; a log's odometry may be
            noisier than the model says, so logs search the whole window).
        min_window: Smallest half-widths ``(m, rad)`` of that odometry-sized window.
        odometry_noise: Std devs of odometry ``(m per m, m per rad, rad per m, rad per
            rad)`` (as GMapping's ``srr srt str stt``).
        surface_bridge: Gaps up to this long between collinear scan points are filled in
            the matching maps (m); 0 fills only gaps below 0.3 m.
        linear_update: A scan is processed only after the odometry moved this far since
            the last processed scan (m); 0 processes every scan.
        angular_update: ... or turned this far (rad).
        temporal_update: ... or this much time passed (s); negative: never by time.
        max_urange: Readings beyond this are mapped as free space up to it, never as an
            obstacle, and so are no-return readings (m).
        map_size: Side of the live map's first square, centred on the first pose (m); it
            grows when scans reach beyond it.
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
    loop_defer_chi2: float = 0.0
    loop_max_sigma: tuple[float, float] = (0.1, float(np.radians(1.5)))
    loop_gate: float = 16.27
    sequential_sigma: tuple[float, float, float] = (0.02, 0.02, float(np.radians(0.5)))
    odometry_sigma: tuple[float, float, float] = (0.1, 0.1, float(np.radians(5.0)))
    loop_sigma: tuple[float, float, float] = (0.03, 0.03, float(np.radians(1.0)))
    match_covariance: bool = True
    weigh_odometry: bool = False
    covariance_floor: tuple[float, float, float] = (0.01, 0.01, float(np.radians(0.2)))
    points_per_measurement: float = 4.0
    odometry_window: bool = False
    min_window: tuple[float, float] = (0.15, float(np.radians(5.0)))
    odometry_noise: tuple[float, float, float, float] = (0.1, 0.05, 0.02, 0.1)
    surface_bridge: float = 3.0
    linear_update: float = 0.0
    angular_update: float = 0.0
    temporal_update: float = -1.0
    max_urange: float = 30.0
    map_size: float = 20.0
    min_points: int = 20
    seed: int = 0
