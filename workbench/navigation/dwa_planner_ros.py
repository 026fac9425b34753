"""dwa_local_planner's ``DWAPlannerROS`` (``base_local_planner: dwa_local_planner/DWAPlannerROS``).

Parameters under ``~DWAPlannerROS`` with dwa_local_planner's names and defaults (Noetic):
``max_vel_trans`` 0.55 / ``min_vel_trans`` 0.1 (older ``max_trans_vel``/``min_trans_vel``),
``max_vel_x`` 0.55, ``min_vel_x`` 0.0, ``max_vel_y`` 0.1, ``min_vel_y`` -0.1,
``max_vel_theta`` 1.0 / ``min_vel_theta`` 0.4 (older ``max_rot_vel``/``min_rot_vel``; the
smallest useful turn rate), ``acc_lim_x``/``acc_lim_y`` 2.5, ``acc_lim_theta`` 3.2,
``sim_time`` 1.7, ``sim_granularity`` 0.025, ``angular_sim_granularity`` 0.1,
``vx_samples`` 3, ``vy_samples`` 10, ``vth_samples`` 20 (0 or less: 1, with dwa_planner's
warning; turtlebot3's burger sets ``vy_samples: 0``), ``path_distance_bias`` 32,
``goal_distance_bias`` 24, ``occdist_scale`` 0.01, ``forward_point_distance`` 0.325,
``oscillation_reset_dist`` 0.05, ``oscillation_reset_angle`` 0.2,
``xy_goal_tolerance`` 0.10, ``yaw_goal_tolerance`` 0.05, ``latch_xy_goal_tolerance`` false,
``prune_plan`` true, ``use_dwa`` true; ``controller_frequency`` searched upwards.

Each cycle samples the full grid of ``vx x vy x vth`` velocities reachable within one control
period (zero added when the window spans it), drops samples slower than both minimum speeds
or faster than ``max_vel_trans``, simulates them at constant velocity (with ``use_dwa``; else
accelerating within the limits over ``sim_time``) and scores each by its end point:
``0.5 res path_distance_bias`` x (path distance + path distance of the point
``forward_point_distance`` ahead) +
``0.5 res goal_distance_bias`` x (goal distance + distance of the point ahead to the goal
moved ahead the same way; both points ahead count only farther than
``forward_point_distance`` from the goal) + ``occdist_scale`` x the largest footprint cost; samples the
oscillation flags forbid (:class:`OscillationFlags`) are refused. Near the goal
it stops and rotates as TrajectoryPlannerROS does, and :meth:`is_goal_reached` logs
``Goal reached``. dwa_local_planner's twirling cost and the speed-scaled
footprint are not modelled.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from workbench.navigation.local_planner_params import ParamReader, controller_frequency
from workbench.navigation.local_planner_ros import TrajectoryPlannerROS
from workbench.navigation.trajectory_map_grid import distance_maps
from workbench.navigation.trajectory_rollout import CostGrid, RolloutParams


def velocity_samples(low: float, high: float, count: int) -> np.ndarray:
    """base_local_planner's ``VelocityIterator``: ``low`` alone when ``low == high``, else
    ``max(count, 2)`` evenly spaced values from ``low`` to ``high`` (also when ``low > high``:
    a window the acceleration limit pins, e.g. ``acc_lim_y`` 0 with odometry's vy a hair off
    zero, still gives its two ends), plus 0 inside a range that crosses it."""
    if low == high:
        return np.array([low])
    values = np.linspace(low, high, max(count, 2))
    if low < 0.0 < high and not np.any(np.abs(values) < 1e-12):
        values = np.sort(np.append(values, 0.0))
    return values


def samples_count(node: Any, reader: ParamReader, name: str, axis: str, default: int) -> int:
    """A ``v*_samples`` parameter; 0 or less becomes 1 with dwa_planner's warning."""
    value = reader.integer(name, default, minimum=-(2**31))
    if value > 0:
        return value
    node.get_logger().warn(
        f"You've specified that you don't want any samples in the {axis} dimension. We'll at "
        f"least assume that you want to sample one value... so we're going to set {name} to 1 "
        "instead"
    )
    return 1


class OscillationFlags:
    """base_local_planner's ``OscillationCostFunction`` as dwa_local_planner uses it.

    Once the chosen command flips between forward and backward (or, while hardly moving,
    between turning left and right), the opposite direction is refused until the robot
    has moved ``reset_dist`` (m) or turned ``reset_angle`` (rad) from where it flipped;
    a new global plan clears the flags (``DWAPlanner::setPlan``).
    """

    def __init__(self, reset_dist: float, reset_angle: float) -> None:
        self.reset_dist = reset_dist
        self.reset_angle = reset_angle
        self.reset()
        self.prev = np.zeros(3)

    def reset(self) -> None:
        self.moving = {"x": 0, "th": 0}  # the sign last chosen
        self.only = {"x": 0, "th": 0}  # the only sign allowed (0: any)

    def refused(self, samples: np.ndarray) -> np.ndarray:
        """The samples ``(N, 3)`` the flags forbid."""
        out = np.zeros(len(samples), dtype=bool)
        for key, column in (("x", 0), ("th", 2)):
            if self.only[key]:
                out |= np.sign(samples[:, column]) == -self.only[key]
        return out

    def update(
        self, pose: np.ndarray, chosen: tuple[float, float, float], min_trans: float
    ) -> None:
        """``updateOscillationFlags`` after a valid command was chosen at ``pose``."""
        flipped = self._flip("x", chosen[0])
        if abs(chosen[0]) <= min_trans:
            flipped = self._flip("th", chosen[2]) or flipped
        if flipped:
            self.prev = np.array(pose[:3], dtype=float)
        if any(self.only.values()):
            moved = math.hypot(pose[0] - self.prev[0], pose[1] - self.prev[1])
            if moved > self.reset_dist or abs(pose[2] - self.prev[2]) > self.reset_angle:
                self.reset()

    def _flip(self, key: str, value: float) -> bool:
        sign = int(np.sign(value))
        if sign == 0:
            return False
        flipped = self.moving[key] == -sign
        if flipped:
            self.only[key] = sign
        self.moving[key] = sign
        return flipped


class DWAPlannerROS(TrajectoryPlannerROS):
    """``dwa_local_planner/DWAPlannerROS`` on the shared rollout and scoring machinery."""

    def read_params(self, node: Any, name: str) -> tuple[RolloutParams, dict[str, Any]]:
        r = ParamReader(node, f"~{name}")
        max_theta = r.number_either("max_vel_theta", "max_rot_vel", 1.0)
        min_theta = r.number_either("min_vel_theta", "min_rot_vel", 0.4)
        sim_granularity = r.number("sim_granularity", 0.025, positive=True)
        params = RolloutParams(
            max_vel_x=r.number("max_vel_x", 0.55),
            min_vel_x=r.number("min_vel_x", 0.0),
            max_vel_theta=max_theta,
            min_vel_theta=-max_theta,
            min_in_place_vel_theta=min_theta,
            acc_lim_x=r.number("acc_lim_x", 2.5),
            acc_lim_y=r.number("acc_lim_y", 2.5),
            acc_lim_theta=r.number_either("acc_lim_theta", "acc_lim_th", 3.2),
            sim_time=r.number("sim_time", 1.7, positive=True),
            sim_granularity=sim_granularity,
            angular_sim_granularity=r.number("angular_sim_granularity", 0.1, positive=True),
            vx_samples=samples_count(node, r, "vx_samples", "x", 3),
            vtheta_samples=samples_count(node, r, "vth_samples", "theta", 20),
            path_distance_bias=r.number("path_distance_bias", 32.0),
            goal_distance_bias=r.number("goal_distance_bias", 24.0),
            occdist_scale=r.number("occdist_scale", 0.01),
            heading_lookahead=r.number("forward_point_distance", 0.325),
            holonomic_robot=False,
            dwa=r.flag("use_dwa", True),
            sim_period=1.0 / controller_frequency(node, f"~{name}"),
        )
        self.max_vel_trans = r.number_either("max_vel_trans", "max_trans_vel", 0.55)
        self.min_vel_trans = r.number_either("min_vel_trans", "min_trans_vel", 0.1)
        self.max_vel_y = r.number("max_vel_y", 0.1)
        self.min_vel_y = r.number("min_vel_y", -0.1)
        self.vy_samples = samples_count(node, r, "vy_samples", "y", 10)
        self.oscillation = OscillationFlags(
            r.number("oscillation_reset_dist", 0.05), r.number("oscillation_reset_angle", 0.2)
        )
        host = {
            "xy_goal_tolerance": r.number("xy_goal_tolerance", 0.10),
            "yaw_goal_tolerance": r.number("yaw_goal_tolerance", 0.05),
            "latch_xy_goal_tolerance": r.flag("latch_xy_goal_tolerance", False),
            "meter_scoring": True,
            "meter_scoring_set": True,
            "prune_plan": r.flag("prune_plan", True),
        }
        return params, host

    def announce(self, node: Any, host: dict[str, Any]) -> None:
        """DWAPlannerROS has no meter_scoring warning."""

    def samples(self, vel: np.ndarray) -> np.ndarray:
        """The velocity samples ``(N, 3)`` of this cycle's window."""
        p = self.params
        horizon = p.sim_period if p.dwa else p.sim_time
        lo = [
            max(p.min_vel_x, vel[0] - p.acc_lim_x * horizon),
            max(self.min_vel_y, vel[1] - p.acc_lim_y * horizon),
            max(-p.max_vel_theta, vel[2] - p.acc_lim_theta * horizon),
        ]
        hi = [
            min(p.max_vel_x, vel[0] + p.acc_lim_x * horizon),
            min(self.max_vel_y, vel[1] + p.acc_lim_y * horizon),
            min(p.max_vel_theta, vel[2] + p.acc_lim_theta * horizon),
        ]
        counts = (p.vx_samples, self.vy_samples, p.vtheta_samples)
        axes = [velocity_samples(lo[i], hi[i], counts[i]) for i in range(3)]
        grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(3, -1).T
        vmag = np.hypot(grid[:, 0], grid[:, 1])
        eps = 1e-4
        too_slow = (vmag + eps < self.min_vel_trans) & (
            np.abs(grid[:, 2]) + eps < p.min_in_place_vel_theta
        )
        too_fast = vmag - eps > self.max_vel_trans
        return grid[~too_slow & ~too_fast]

    def _front_maps(self, grid: CostGrid, pose: np.ndarray, window: np.ndarray, maps: Any) -> Any:
        """Goal distances to the plan's end moved ``forward_point_distance`` along its heading."""
        front = window.copy()
        d = self.params.heading_lookahead
        if len(front) >= 2:
            heading = math.atan2(front[-1, 1] - front[-2, 1], front[-1, 0] - front[-2, 0])
            front[-1, :2] += d * np.array([math.cos(heading), math.sin(heading)])
        return distance_maps(
            grid.costs,
            grid.resolution,
            (grid.origin_x, grid.origin_y),
            front[:, :2],
            maps.within_robot,
            with_path=False,
        )

    def drive(
        self,
        grid: CostGrid,
        maps: Any,
        pose: np.ndarray,
        vel: np.ndarray,
        goal: np.ndarray,
        scales: tuple,
    ) -> tuple[bool, tuple[float, float, float]]:
        p = self.params
        samples = self.samples(vel)
        if len(samples) == 0:
            return False, (0.0, 0.0, 0.0)
        planner = self.planner
        if p.dwa:  # constant velocity over the whole simulation
            planner = dataclasses.replace(
                self.planner,
                params=dataclasses.replace(
                    p, acc_lim_x=math.inf, acc_lim_y=math.inf, acc_lim_theta=math.inf
                ),
            )
        scored = planner.score(grid, maps, pose, vel, samples, (0.0, 0.0, p.occdist_scale))
        ends = scored.poses[np.arange(len(samples)), scored.steps - 1]
        ahead = ends[:, :2] + p.heading_lookahead * np.c_[np.cos(ends[:, 2]), np.sin(ends[:, 2])]
        res = grid.resolution
        path_end, _ = grid.lookup(maps.path, ends[:, :2], maps.impossible + 1)
        goal_end, _ = grid.lookup(maps.goal, ends[:, :2], maps.impossible + 1)
        # within forward_point_distance of the goal the nose's costs are off (dwa_planner.cpp:
        # "trying to keep the nose close to anything destabilizes behavior")
        near_goal = math.hypot(goal[0] - pose[0], goal[1] - pose[1]) <= p.heading_lookahead
        align = 0.0 if near_goal else 1.0
        if near_goal:
            path_ahead = goal_ahead = np.zeros(len(samples))
            blocked = np.zeros(len(samples), dtype=bool)
        else:
            path_ahead, _ = grid.lookup(maps.path, ahead, maps.impossible + 1)
            front = self._front_maps(grid, pose, self._window, maps)
            goal_ahead, _ = grid.lookup(front.goal, ahead, front.impossible + 1)
            blocked = (path_ahead >= maps.impossible) | (goal_ahead >= front.impossible)
        cost = (
            0.5 * res * p.path_distance_bias * (path_end + align * path_ahead)
            + 0.5 * res * p.goal_distance_bias * (goal_end + align * goal_ahead)
            + scored.cost
        )
        refused = self.oscillation.refused(samples)
        cost = np.where((scored.cost < 0) | blocked | refused, -1.0, cost)
        legal = np.flatnonzero(cost >= 0)
        if len(legal) == 0:
            self.node.get_logger().debug(
                "The dwa local planner failed to find a valid plan, cost functions discarded all candidates. "
                "This can mean there is an obstacle too close to the robot."
            )
            self.node.get_logger().warn("DWA planner failed to produce path.")
            self.publish_path(self.local_pub, ends[:0])
            return False, (0.0, 0.0, 0.0)
        best = int(legal[np.argmin(cost[legal])])
        vx, vy, vth = (float(v) for v in samples[best])
        self.oscillation.update(pose, (vx, vy, vth), self.min_vel_trans)
        self.node.get_logger().debug(
            f"A valid velocity command of ({vx:.2f}, {vy:.2f}, {vth:.2f}) was found for this cycle."
        )
        self.publish_path(self.local_pub, scored.poses[best, : scored.steps[best]])
        return True, (vx, vy, vth)

    def on_new_plan(self) -> None:
        super().on_new_plan()
        self.oscillation.reset()

    def _maps(self, grid: CostGrid, pose: np.ndarray, window: np.ndarray) -> Any:
        self._window = window
        return super()._maps(grid, pose, window)

    def is_goal_reached(self) -> bool:
        reached = super().is_goal_reached()
        if reached:
            self.node.get_logger().info("Goal reached")
        return reached
