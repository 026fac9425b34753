"""base_local_planner's ``TrajectoryPlanner``: sample velocities, simulate, score, pick one.

The behaviour of ``base_local_planner/src/trajectory_planner.cpp`` (Noetic), with every
sample simulated and scored at once in numpy instead of one trajectory at a time:

* **Window.** In DWA mode (``dwa: true``) the sampled velocities are those reachable within
  one control period (``1/controller_frequency``), else within ``sim_time``; near the goal
  ``max_vel_x`` is capped at distance/``sim_time``.
* **Samples**, in the planner's order: ``vx_samples`` forward speeds, each straight and with
  ``vtheta_samples - 1`` turn rates; for holonomic robots two slight strafes (0.1, ±0.1);
  rotations in place (at least ``min_in_place_vel_theta``); then, only if nothing was legal,
  holonomic strafes at ``y_vels`` and finally backing up at ``escape_vel``.
* **Simulation.** Each sample is simulated for ``sim_time`` in steps of ``sim_granularity``
  m / ``angular_sim_granularity`` rad, the speed moving from the current velocity towards
  the sample within the acceleration limits.
* **Legality.** A point outside the costmap or whose footprint outline touches a lethal or
  unknown cell makes the trajectory illegal (cost -1); a point with no way to the path or
  goal (distance at the map's cell count) makes it -2.
* **Cost** = ``path_distance_bias`` x path distance + ``goal_distance_bias`` x goal distance
  (both at the trajectory's end, in cells, or metres with ``meter_scoring``) +
  ``occdist_scale`` x the largest cell cost met. The lowest legal cost wins, ties to the
  earlier sample; a rotation in place is chosen by the goal distance of a point
  ``heading_lookahead`` ahead of its end, with the planner's oscillation flags.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from workbench.navigation.costs import LETHAL_OBSTACLE, NO_INFORMATION
from workbench.navigation.trajectory_map_grid import DistanceMaps

ILLEGAL = -1.0
NO_WAY = -2.0
#: Headings for which the footprint outline's cells are precomputed.
HEADING_BINS = 32
_PAD = 64  # cells beyond the map a pose key may lie (such poses are illegal anyway)


@dataclass
class RolloutParams:
    """The planner's numbers (names of TrajectoryPlannerROS's parameters; SI units)."""

    max_vel_x: float = 0.5
    min_vel_x: float = 0.1
    max_vel_theta: float = 1.0
    min_vel_theta: float = -1.0
    min_in_place_vel_theta: float = 0.4
    acc_lim_x: float = 2.5
    acc_lim_y: float = 2.5
    acc_lim_theta: float = 3.2
    sim_time: float = 1.0
    sim_granularity: float = 0.025
    angular_sim_granularity: float = 0.025
    vx_samples: int = 3
    vtheta_samples: int = 20
    path_distance_bias: float = 0.6
    goal_distance_bias: float = 0.8
    occdist_scale: float = 0.01
    heading_lookahead: float = 0.325
    oscillation_reset_dist: float = 0.05
    escape_reset_dist: float = 0.10
    escape_reset_theta: float = math.pi / 4
    holonomic_robot: bool = True
    escape_vel: float = -0.1
    dwa: bool = True
    y_vels: tuple[float, ...] = (-0.3, -0.1, 0.1, 0.3)
    sim_period: float = 0.05


@dataclass
class Scored:
    """Every sample of one cycle: velocities, costs and simulated poses."""

    v: np.ndarray  # (N, 3) vx, vy, vtheta
    cost: np.ndarray  # (N,)
    poses: np.ndarray  # (N, K, 3)
    steps: np.ndarray  # (N,) points of each trajectory


@dataclass
class Choice:
    """The chosen command and its trajectory (cost < 0: nothing legal)."""

    vx: float
    vy: float
    vtheta: float
    cost: float
    poses: np.ndarray  # (k, 3)


@dataclass
class _Oscillation:
    rotating_left: bool = False
    rotating_right: bool = False
    stuck_left: bool = False
    stuck_right: bool = False
    strafe_left: bool = False
    strafe_right: bool = False
    prev: tuple[float, float] = (0.0, 0.0)
    escaping: bool = False
    escape: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def reset_flags(self) -> None:
        self.rotating_left = self.rotating_right = self.stuck_left = self.stuck_right = False
        self.strafe_left = self.strafe_right = False


def _toward(goal: np.ndarray, current: np.ndarray, acc: float, dt: np.ndarray) -> np.ndarray:
    """``computeNewVelocity``: move towards ``goal`` by at most ``acc * dt``."""
    return np.where(
        goal >= current, np.minimum(goal, current + acc * dt), np.maximum(goal, current - acc * dt)
    )


@dataclass
class CostGrid:
    """The local costmap the planner scores against (a snapshot)."""

    costs: np.ndarray  # uint8 [my, mx]
    resolution: float
    origin_x: float
    origin_y: float

    def cells(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(mx, my, inside) of world points ``(..., 2)``."""
        mx = np.floor((xy[..., 0] - self.origin_x) / self.resolution).astype(np.int64)
        my = np.floor((xy[..., 1] - self.origin_y) / self.resolution).astype(np.int64)
        size_y, size_x = self.costs.shape
        inside = (mx >= 0) & (mx < size_x) & (my >= 0) & (my < size_y)
        return mx, my, inside

    def lookup(
        self, table: np.ndarray, xy: np.ndarray, outside: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """``table[my, mx]`` at world points (``outside`` where off the grid) and the inside mask."""
        mx, my, inside = self.cells(xy)
        values = np.full(mx.shape, outside, dtype=float)
        values[inside] = table[my[inside], mx[inside]]
        return values, inside


def outline_points(footprint: np.ndarray, spacing: float) -> np.ndarray:
    """Points along the closed footprint polygon at most ``spacing`` apart (robot frame)."""
    poly = np.asarray(footprint, dtype=float).reshape(-1, 2)
    if len(poly) < 2:
        return np.zeros((1, 2))
    closed = np.vstack([poly, poly[:1]])
    parts = []
    for a, b in zip(closed[:-1], closed[1:], strict=True):
        n = max(int(np.ceil(np.hypot(*(b - a)) / spacing)), 1)
        parts.append(a + (np.arange(n)[:, None] / n) * (b - a))
    return np.concatenate(parts)


@dataclass
class TrajectoryPlanner:
    """Trajectory rollout / DWA over a costmap (``TrajectoryPlanner`` of base_local_planner).

    Args:
        params: The planner's numbers.
        footprint: The robot's footprint polygon ``(n, 2)`` in its own frame (m).
    """

    params: RolloutParams
    footprint: np.ndarray
    osc: _Oscillation = field(default_factory=_Oscillation)
    _offset_cache: dict[float, np.ndarray] = field(default_factory=dict, repr=False)

    def simulate(
        self, pose: np.ndarray, vel: np.ndarray, samples: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Poses ``(N, K, 3)`` and step counts ``(N,)`` of ``samples`` ``(N, 3)`` from ``pose``."""
        p = self.params
        samples = np.asarray(samples, dtype=float).reshape(-1, 3)
        vmag = np.hypot(samples[:, 0], samples[:, 1])
        steps = np.floor(
            np.maximum(
                vmag * p.sim_time / p.sim_granularity,
                np.abs(samples[:, 2]) / p.angular_sim_granularity,
            )
            + 0.5
        ).astype(int)
        steps = np.maximum(steps, 1)
        dt = p.sim_time / steps
        count = len(samples)
        k_max = int(steps.max()) if count else 1
        poses = np.empty((count, k_max, 3))
        x = np.full(count, float(pose[0]))
        y = np.full(count, float(pose[1]))
        th = np.full(count, float(pose[2]))
        vx = np.full(count, float(vel[0]))
        vy = np.full(count, float(vel[1]))
        vth = np.full(count, float(vel[2]))
        for i in range(k_max):
            poses[:, i, 0], poses[:, i, 1], poses[:, i, 2] = x, y, th
            vx = _toward(samples[:, 0], vx, p.acc_lim_x, dt)
            vy = _toward(samples[:, 1], vy, p.acc_lim_y, dt)
            vth = _toward(samples[:, 2], vth, p.acc_lim_theta, dt)
            c, s = np.cos(th), np.sin(th)
            x = x + (vx * c - vy * s) * dt
            y = y + (vx * s + vy * c) * dt
            th = th + vth * dt
        return poses, steps

    def score(
        self,
        grid: CostGrid,
        maps: DistanceMaps,
        pose: np.ndarray,
        vel: np.ndarray,
        samples: np.ndarray,
        scales: tuple[float, float, float],
    ) -> Scored:
        """Simulate and score ``samples`` (``generateTrajectory`` for all of them).

        Args:
            scales: (path, goal, occupancy) factors after ``meter_scoring``.
        """
        poses, steps = self.simulate(pose, vel, samples)
        count, k_max = poses.shape[:2]
        valid_step = np.arange(k_max)[None, :] < steps[:, None]
        xy = poses[..., :2]
        center_cost, inside = grid.lookup(grid.costs, xy, 0.0)
        fp_bad, fp_max = self.outline_costs(grid, poses, inside)
        path_d, _ = grid.lookup(maps.path, xy, maps.impossible + 1)
        goal_d, _ = grid.lookup(maps.goal, xy, maps.impossible + 1)
        illegal = (~inside | fp_bad) & valid_step
        no_way = (
            inside & ~fp_bad & ((path_d >= maps.impossible) | (goal_d >= maps.impossible))
        ) & valid_step
        failing = illegal | no_way
        first_fail = np.where(failing.any(axis=1), failing.argmax(axis=1), k_max)
        rows = np.arange(count)
        code = np.where(
            first_fail < k_max,
            np.where(illegal[rows, np.minimum(first_fail, k_max - 1)], ILLEGAL, NO_WAY),
            0.0,
        )
        occ = np.where(valid_step, np.maximum(center_cost, fp_max), 0.0).max(axis=1)
        last = steps - 1
        cost = scales[0] * path_d[rows, last] + scales[1] * goal_d[rows, last] + scales[2] * occ
        cost = np.where(first_fail < k_max, code, cost)
        return Scored(samples, cost, poses, steps)

    def outline_costs(
        self, grid: CostGrid, poses: np.ndarray, inside: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """(illegal, largest cost) of the footprint outline at each pose ``(N, K, 3)``.

        The outline's cells are taken relative to the pose's cell for one of
        :data:`HEADING_BINS` headings, and each distinct (cell, heading) is looked up once.
        A lethal or unknown outline cell, or one off the map, is illegal.
        """
        offsets = self._offsets(grid.resolution)
        mx, my, _ = grid.cells(poses[..., :2])
        bins = (
            np.floor(poses[..., 2] / (2 * math.pi) * HEADING_BINS + 0.5).astype(np.int64)
            % HEADING_BINS
        )
        size_y, size_x = grid.costs.shape
        span = size_x + 2 * _PAD
        keys = (
            (np.clip(my, -_PAD, size_y + _PAD - 1) + _PAD) * span
            + np.clip(mx, -_PAD, size_x + _PAD - 1)
            + _PAD
        )
        keys = keys * HEADING_BINS + bins
        unique, inverse = np.unique(keys.ravel(), return_inverse=True)
        cell, ubin = np.divmod(unique, HEADING_BINS)
        uy, ux = np.divmod(cell, span)
        uy, ux = uy - _PAD, ux - _PAD
        offs = offsets[ubin]  # (U, M, 2)
        cx = ux[:, None] + offs[..., 0]
        cy = uy[:, None] + offs[..., 1]
        ok = (cx >= 0) & (cx < size_x) & (cy >= 0) & (cy < size_y)
        values = np.full(cx.shape, NO_INFORMATION, dtype=np.uint8)
        values[ok] = grid.costs[cy[ok], cx[ok]]
        bad_u = ((values == LETHAL_OBSTACLE) | (values == NO_INFORMATION)).any(axis=1)
        max_u = values.max(axis=1).astype(float)
        bad = bad_u[inverse].reshape(keys.shape) & inside
        return bad, np.where(bad, 0.0, max_u[inverse].reshape(keys.shape))

    def _offsets(self, resolution: float) -> np.ndarray:
        """Outline cell offsets per heading bin ``(HEADING_BINS, M, 2)`` (repeats pad rows)."""
        cached = self._offset_cache.get(resolution)
        if cached is not None:
            return cached
        outline = outline_points(self.footprint, resolution * 0.5)
        rows = []
        for b in range(HEADING_BINS):
            a = 2 * math.pi * b / HEADING_BINS
            c, s = math.cos(a), math.sin(a)
            pts = outline @ np.array([[c, s], [-s, c]])
            rows.append(np.unique(np.floor(pts / resolution + 0.5).astype(np.int64), axis=0))
        width = max(len(r) for r in rows)
        table = np.stack([np.vstack([r, np.repeat(r[:1], width - len(r), axis=0)]) for r in rows])
        self._offset_cache[resolution] = table
        return table

    # --- the sample set and the choice -------------------------------------------------

    def window(self, vel: np.ndarray, goal_dist: float | None) -> tuple[float, float, float, float]:
        """(min_vx, max_vx, min_vth, max_vth) reachable from ``vel``."""
        p = self.params
        max_vx = p.max_vel_x if goal_dist is None else min(p.max_vel_x, goal_dist / p.sim_time)
        horizon = p.sim_period if p.dwa else p.sim_time
        max_vx = max(min(max_vx, vel[0] + p.acc_lim_x * horizon), p.min_vel_x)
        min_vx = max(p.min_vel_x, vel[0] - p.acc_lim_x * horizon)
        max_vth = min(p.max_vel_theta, vel[2] + p.acc_lim_theta * horizon)
        min_vth = max(p.min_vel_theta, vel[2] - p.acc_lim_theta * horizon)
        return min_vx, max_vx, min_vth, max_vth

    def choose(
        self,
        grid: CostGrid,
        maps: DistanceMaps,
        pose: np.ndarray,
        vel: np.ndarray,
        scales: tuple[float, float, float],
        goal_dist: float | None = None,
    ) -> Choice:
        """``createTrajectories``: the best command from ``pose`` at velocity ``vel``."""
        p = self.params
        x, y, theta = (float(v) for v in pose)
        min_vx, max_vx, min_vth, max_vth = self.window(vel, goal_dist)
        dvx = (max_vx - min_vx) / max(p.vx_samples - 1, 1)
        dvth = (max_vth - min_vth) / max(p.vtheta_samples - 1, 1)
        forward: list[tuple[float, float, float]] = []
        if not self.osc.escaping:
            for i in range(p.vx_samples):
                vx = min_vx + i * dvx
                forward.append((vx, 0.0, 0.0))
                forward.extend((vx, 0.0, min_vth + j * dvth) for j in range(p.vtheta_samples - 1))
            if p.holonomic_robot:
                forward += [(0.1, 0.1, 0.0), (0.1, -0.1, 0.0)]
        turn_raw = [min_vth + i * dvth for i in range(p.vtheta_samples)]
        turns = [
            (
                0.0,
                0.0,
                max(v, p.min_in_place_vel_theta) if v > 0 else min(v, -p.min_in_place_vel_theta),
            )
            for v in turn_raw
        ]
        scored = self.score(grid, maps, pose, vel, np.array(forward + turns), scales)
        best = -1
        nf = len(forward)
        legal = scored.cost[:nf] >= 0
        if legal.any():
            masked = np.where(legal, scored.cost[:nf], np.inf)
            best = int(np.argmin(masked))
        heading_dist = math.inf
        for i, raw in enumerate(turn_raw):
            k = nf + i
            cost = scored.cost[k]
            best_cost = scored.cost[best] if best >= 0 else -1.0
            better = cost <= best_cost or best_cost < 0 or (best >= 0 and scored.v[best, 1] != 0.0)
            if cost < 0 or not better or not (raw > dvth or raw < -dvth):
                continue
            end = scored.poses[k, scored.steps[k] - 1]
            ahead = end[:2] + p.heading_lookahead * np.array([math.cos(end[2]), math.sin(end[2])])
            gd, inside = grid.lookup(maps.goal, ahead[None, :], math.inf)
            if not inside[0] or gd[0] >= heading_dist:
                continue
            if (raw < 0 and not self.osc.stuck_left) or (raw > 0 and not self.osc.stuck_right):
                best, heading_dist = k, float(gd[0])
        if best >= 0:
            self._track(scored.v[best], x, y, theta)
            return self._choice(scored, best)
        if p.holonomic_robot and p.y_vels:
            strafes = self.score(
                grid, maps, pose, vel, np.array([(0.0, v, 0.0) for v in p.y_vels]), scales
            )
            ok = np.flatnonzero(strafes.cost >= 0)
            if len(ok):
                pick = int(ok[np.argmin(strafes.cost[ok])])
                self._track(strafes.v[pick], x, y, theta)
                return self._choice(strafes, pick)
        back = self.score(grid, maps, pose, vel, np.array([(p.escape_vel, 0.0, 0.0)]), scales)
        dist = math.hypot(x - self.osc.prev[0], y - self.osc.prev[1])
        if dist > p.oscillation_reset_dist:
            self.osc.reset_flags()
        if not self.osc.escaping and back.cost[0] > NO_WAY:
            self.osc.escaping, self.osc.escape = True, (x, y, theta)
        self._maybe_end_escape(x, y, theta)
        choice = self._choice(back, 0)
        if choice.cost == ILLEGAL:  # backing up is allowed even when the footprint hits
            choice.cost = 1.0
        return choice

    def _choice(self, scored: Scored, k: int) -> Choice:
        vx, vy, vth = (float(v) for v in scored.v[k])
        return Choice(vx, vy, vth, float(scored.cost[k]), scored.poses[k, : scored.steps[k]].copy())

    def _track(self, v: np.ndarray, x: float, y: float, theta: float) -> None:
        """The oscillation flags after choosing ``v`` (stuck turning both ways etc.)."""
        o = self.osc
        if not v[0] > 0:
            if v[2] < 0:
                o.stuck_right = o.stuck_right or o.rotating_right
                o.rotating_left = True
            elif v[2] > 0:
                o.stuck_left = o.stuck_left or o.rotating_left
                o.rotating_right = True
            elif v[1] > 0:
                o.strafe_left = True
            elif v[1] < 0:
                o.strafe_right = True
            o.prev = (x, y)
        if math.hypot(x - o.prev[0], y - o.prev[1]) > self.params.oscillation_reset_dist:
            o.reset_flags()
        self._maybe_end_escape(x, y, theta)

    def _maybe_end_escape(self, x: float, y: float, theta: float) -> None:
        o = self.osc
        ex, ey, eth = o.escape
        turned = abs(math.remainder(theta - eth, 2 * math.pi))
        if (
            math.hypot(x - ex, y - ey) > self.params.escape_reset_dist
            or turned > self.params.escape_reset_theta
        ):
            o.escaping = False
