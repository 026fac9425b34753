"""Joint trajectories given to the simulator, and the tracking report it returns.

The trajectory format shared with ``workbench.planning`` is plain arrays::

    JointTrajectory(joint_names=[...], t=(N,), q=(N, n), qd=(N, n), qdd=(N, n) or None)

``t`` is in seconds from the start of the motion (strictly increasing, first
value 0 or later), ``q`` in rad (m for prismatic joints), ``qd`` in rad/s
(m/s). Between samples the simulator interpolates with cubic Hermite splines
through ``(q, qd)``. A mapping with the same keys (the ``--json`` output of
``workbench plan``) or any object with those attributes is accepted too.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from workbench.errors import SimulationError


@dataclass
class JointTrajectory:
    """Positions and velocities of named joints at sample times.

    Attributes:
        joint_names: The n joints, in column order.
        t: Sample times, shape (N,), s, strictly increasing.
        q: Positions, shape (N, n), rad or m.
        qd: Velocities, shape (N, n), rad/s or m/s.
        qdd: Accelerations, shape (N, n), or None.
    """

    joint_names: list[str]
    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray | None = None

    @property
    def duration(self) -> float:
        """Time from the first to the last sample, s."""
        return float(self.t[-1] - self.t[0])

    def to_piecewise(self) -> Any:
        """A pydrake ``PiecewisePolynomial`` (cubic Hermite through q and qd), time from t[0]."""
        from pydrake.trajectories import PiecewisePolynomial

        if len(self.t) == 1:
            return PiecewisePolynomial(self.q[0].reshape(-1, 1))
        return PiecewisePolynomial.CubicHermite(self.t, self.q.T, self.qd.T)


def as_joint_trajectory(value: Any, joint_names: list[str] | None = None) -> JointTrajectory:
    """Check and convert a trajectory given as :class:`JointTrajectory`, mapping or object.

    Args:
        value: Something with ``t``, ``q``, ``qd`` (and ``joint_names``, ``qdd``).
        joint_names: Names to use when ``value`` has none.

    Raises:
        SimulationError: Missing fields, wrong shapes, non-finite values or
            times that do not increase.
    """
    raw: Any
    if isinstance(value, JointTrajectory) and joint_names is None:
        raw = value
        get = getattr
    elif isinstance(value, Mapping):
        raw = value

        def get(obj: Any, key: str, default: Any = None) -> Any:
            return obj.get(key, default)
    else:
        raw = value
        get = getattr
    names = get(raw, "joint_names", None) or joint_names
    if names is None:
        raise SimulationError("the trajectory has no joint_names", hint="give joint_names=[...]")
    try:
        t = np.asarray(get(raw, "t"), dtype=float).reshape(-1)
        q = np.atleast_2d(np.asarray(get(raw, "q"), dtype=float))
        qd_raw = get(raw, "qd", None)
        qd = np.zeros_like(q) if qd_raw is None else np.atleast_2d(np.asarray(qd_raw, float))
        qdd_raw = get(raw, "qdd", None)
        qdd = None if qdd_raw is None else np.atleast_2d(np.asarray(qdd_raw, dtype=float))
    except (TypeError, ValueError, AttributeError, KeyError) as exc:
        raise SimulationError(f"the trajectory needs numeric t, q and qd arrays ({exc})") from None
    names = [str(n) for n in names]
    n = len(names)
    if len(set(names)) != n:
        raise SimulationError("the trajectory names a joint twice: " + ", ".join(names))
    for label, array in (("q", q), ("qd", qd), ("qdd", qdd)):
        if array is None:
            continue
        if array.shape != (len(t), n):
            raise SimulationError(
                f"trajectory {label} has shape {array.shape}, expected ({len(t)}, {n}) "
                "(one row per time, one column per joint)"
            )
        if not np.all(np.isfinite(array)):
            raise SimulationError(f"trajectory {label} contains NaN or infinite values")
    if len(t) == 0:
        raise SimulationError("the trajectory has no samples")
    if not np.all(np.isfinite(t)) or np.any(np.diff(t) < 0) or t[0] < 0:
        raise SimulationError("trajectory times must be finite, >= 0 and increasing")
    repeated = np.flatnonzero(np.diff(t) == 0) + 1
    if repeated.size:
        # a repeated time is fine for a repeated point (e.g. a zero-length plan)
        if not np.allclose(q[repeated], q[repeated - 1], atol=1e-9):
            raise SimulationError(
                f"trajectory time {t[repeated[0]]:g} s appears twice with different positions"
            )
        keep = np.setdiff1d(np.arange(len(t)), repeated)
        t, q, qd = t[keep], q[keep], qd[keep]
        qdd = None if qdd is None else qdd[keep]
    return JointTrajectory(names, t, q, qd, qdd)


@dataclass
class TrackingReport:
    """How well a robot followed a trajectory in simulation.

    Attributes:
        robot: Robot (model instance) name.
        joint_names: The tracked joints.
        t: Sample times from the start of the motion, s, shape (M,).
        q_desired: Commanded positions at ``t``, shape (M, n).
        q_actual: Simulated positions at ``t``, shape (M, n).
        duration: Length of the commanded motion, s.
        settle_time: Extra time simulated after the end, s.
        max_error: Largest absolute error per joint over the motion, rad or m.
        rms_error: Root-mean-square error per joint, rad or m.
        final_error: Absolute error per joint at the end of settling, rad or m.
        tolerance: Final error below which the execution counts as succeeded.
        contacts: Names of body pairs seen in contact during the motion (excluding
            pairs filtered by the plant).
    """

    robot: str
    joint_names: list[str]
    t: np.ndarray
    q_desired: np.ndarray
    q_actual: np.ndarray
    duration: float
    settle_time: float
    max_error: np.ndarray
    rms_error: np.ndarray
    final_error: np.ndarray
    tolerance: float = 0.01
    contacts: list[tuple[str, str]] = field(default_factory=list)

    @property
    def succeeded(self) -> bool:
        """Every joint ended within ``tolerance`` of the final commanded position."""
        return bool(np.all(self.final_error <= self.tolerance))

    @property
    def max_abs_error(self) -> float:
        """The largest error of any joint at any sample, rad or m."""
        return float(np.max(self.max_error)) if self.max_error.size else 0.0

    def summary(self) -> str:
        """A few lines for the command line: duration, max/RMS/final error, contacts."""
        lines = [
            f"executed {self.duration:.3f} s (+{self.settle_time:.2f} s settling) on '{self.robot}': "
            f"max tracking error {self.max_abs_error:.4f}, "
            f"final error {float(np.max(self.final_error, initial=0.0)):.5f} "
            f"({'ok' if self.succeeded else 'NOT within'} tolerance {self.tolerance:g})"
        ]
        for name, mx, rms in zip(self.joint_names, self.max_error, self.rms_error, strict=False):
            lines.append(f"  {name:<24} max {mx:.4f}  rms {rms:.4f}")
        if self.contacts:
            lines.append("  contacts: " + ", ".join(f"{a}/{b}" for a, b in self.contacts))
        return "\n".join(lines)

    def to_dict(self) -> dict[str, Any]:
        """JSON-friendly summary (no per-sample arrays)."""
        return {
            "robot": self.robot,
            "joint_names": list(self.joint_names),
            "duration": self.duration,
            "settle_time": self.settle_time,
            "max_error": self.max_error.tolist(),
            "rms_error": self.rms_error.tolist(),
            "final_error": self.final_error.tolist(),
            "succeeded": self.succeeded,
            "contacts": [list(pair) for pair in self.contacts],
        }
