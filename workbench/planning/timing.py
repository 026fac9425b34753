"""Time-optimal timing of a joint-space path with toppra, under velocity and acceleration limits.

The planner returns a piecewise-linear path (waypoints). :func:`time_parameterize`
densifies every straight segment, fits a clamped cubic spline through the points
(parametrised by chord length, so it stays close to the checked segments),
and runs toppra (reachability analysis) on a grid of path points. toppra
meets the limits at its grid points only, so the limits given to it are
scaled by a margin (0.9 at first); the result is sampled every millisecond
and, if any sample still exceeds a limit, the margin shrinks and toppra runs
again. What is returned never exceeds a limit at the checked samples.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from workbench.optional import require
from workbench.planning.errors import TrajectoryError

#: Time between samples when a trajectory is checked against its limits, seconds.
CHECK_DT = 0.001


@dataclass
class TimedTrajectory:
    """A joint trajectory q(t), its velocity and acceleration.

    Attributes:
        joint_names: Joint names (columns of q).
        duration: Length in seconds; t runs from 0 to ``duration``.
        velocity_limits: Per-joint limits it was timed under (rad/s or m/s).
        acceleration_limits: Per-joint limits it was timed under (rad/s² or m/s²).
        margin: Fraction of the limits handed to toppra.
        waypoints: The geometric path it follows (k, n).
    """

    joint_names: list[str]
    duration: float
    velocity_limits: np.ndarray
    acceleration_limits: np.ndarray
    margin: float
    waypoints: np.ndarray
    _trajectory: object = field(repr=False, default=None)
    _fixed: np.ndarray | None = field(repr=False, default=None)

    def sample(self, t: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, velocities and accelerations at times ``t`` (s), each (len(t), n)."""
        t = np.clip(np.atleast_1d(np.asarray(t, float)), 0.0, self.duration)
        if self._trajectory is None:  # a path of one point: the robot stays still
            q = np.repeat(self._fixed[None, :], len(t), axis=0)
            return q, np.zeros_like(q), np.zeros_like(q)
        traj = self._trajectory
        return np.atleast_2d(traj(t)), np.atleast_2d(traj(t, 1)), np.atleast_2d(traj(t, 2))

    def times(self, dt: float = 0.01) -> np.ndarray:
        """Uniform times every ``dt`` seconds, ending exactly at ``duration``."""
        count = max(1, math.ceil(self.duration / dt - 1e-9))
        return np.linspace(0.0, self.duration, count + 1)

    def peak_fractions(self, dt: float = CHECK_DT) -> tuple[np.ndarray, np.ndarray]:
        """Peak |velocity| and |acceleration| per joint as fractions of the limits."""
        _, qd, qdd = self.sample(self.times(dt))
        return (
            np.abs(qd).max(axis=0) / self.velocity_limits,
            np.abs(qdd).max(axis=0) / self.acceleration_limits,
        )


def densify(waypoints: np.ndarray, spacing: float) -> np.ndarray:
    """Points along the piecewise-linear path at most ``spacing`` apart (max-norm)."""
    points = [waypoints[0]]
    for a, b in zip(waypoints[:-1], waypoints[1:], strict=True):
        count = max(1, math.ceil(np.max(np.abs(b - a)) / spacing))
        for k in range(1, count + 1):
            points.append(a + (b - a) * (k / count))
    return np.array(points)


def _dedupe(waypoints: np.ndarray) -> np.ndarray:
    keep = [waypoints[0]]
    for w in waypoints[1:]:
        if np.max(np.abs(w - keep[-1])) > 1e-9:
            keep.append(w)
    return np.array(keep)


def spline_path(waypoints: np.ndarray, spacing: float):
    """A toppra spline through the densified path, parametrised by chord length."""
    ta = require("toppra")
    points = densify(waypoints, spacing)
    chords = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(chords)])
    return ta.SplineInterpolator(s / s[-1], points, bc_type="clamped"), points


def time_parameterize(
    waypoints: np.ndarray,
    velocity_limits: np.ndarray,
    acceleration_limits: np.ndarray,
    *,
    joint_names: list[str] | None = None,
    spacing: float = 0.5,
    margin: float = 0.9,
    max_retries: int = 6,
) -> TimedTrajectory:
    """Time a joint-space path as fast as the limits allow, starting and ending at rest.

    Args:
        waypoints: (k, n) joint positions, rad or m.
        velocity_limits: (n,) positive limits, rad/s or m/s.
        acceleration_limits: (n,) positive limits, rad/s² or m/s².
        joint_names: Names for the columns.
        spacing: Densification step of the straight segments (max-norm, rad or m).
        margin: Initial fraction of the limits handed to toppra.
        max_retries: How often to shrink the margin before giving up.

    Raises:
        TrajectoryError: toppra found no parameterization, or the limits stayed exceeded.
    """
    require("toppra")
    import toppra.algorithm as algo
    import toppra.constraint as constraint

    waypoints = _dedupe(np.atleast_2d(np.asarray(waypoints, float)))
    n = waypoints.shape[1]
    names = list(joint_names) if joint_names else [f"joint{i}" for i in range(n)]
    vlim = np.asarray(velocity_limits, float)
    alim = np.asarray(acceleration_limits, float)
    if (
        np.any(~np.isfinite(vlim))
        or np.any(vlim <= 0)
        or np.any(~np.isfinite(alim))
        or np.any(alim <= 0)
    ):
        raise TrajectoryError(
            "every joint needs a finite positive velocity and acceleration limit",
            hint="set them in planning.yaml (joint_limits)",
        )
    if len(waypoints) == 1:
        return TimedTrajectory(names, 0.0, vlim, alim, margin, waypoints, None, waypoints[0])
    path, points = spline_path(waypoints, spacing)
    # Enough grid points for the spline's pieces, few enough to stay fast.
    gridpoint_count = int(np.clip(4 * len(points), 60, 200))
    scale = margin
    for _ in range(max_retries + 1):
        constraints = [
            constraint.JointVelocityConstraint(np.stack([-vlim * scale, vlim * scale], axis=1)),
            constraint.JointAccelerationConstraint(np.stack([-alim * scale, alim * scale], axis=1)),
        ]
        gridpoints = np.linspace(0.0, 1.0, gridpoint_count)
        instance = algo.TOPPRA(
            constraints, path, gridpoints=gridpoints, parametrizer="ParametrizeSpline"
        )
        trajectory = instance.compute_trajectory(0.0, 0.0)
        if trajectory is None or not np.isfinite(trajectory.duration):
            raise TrajectoryError("toppra found no time parameterization of the path")
        result = TimedTrajectory(
            names, float(trajectory.duration), vlim, alim, scale, waypoints, trajectory, None
        )
        v_frac, a_frac = result.peak_fractions()
        if np.all(v_frac <= 1.0) and np.all(a_frac <= 1.0):
            return result
        scale *= 0.9 / max(float(v_frac.max()), float(a_frac.max()), 1.0)
    raise TrajectoryError(
        f"the timed trajectory kept exceeding its limits (peak {max(v_frac.max(), a_frac.max()):.3f} of the limit)"
    )
