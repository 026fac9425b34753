"""Trajectory accuracy: simulated odometry noise, absolute and relative (Kümmerle) errors.

The noise model is the odometry motion model of Thrun, Burgard and Fox
(Probabilistic Robotics, ``sample_motion_model_odometry``): each step is
split into rotate-translate-rotate ``(r1, t, r2)`` and

    r1 += N(0, a1 |r1| + a2 |t|),  t += N(0, a3 |t| + a4 (|r1| + |r2|)),  r2 += N(0, a1 |r2| + a2 |t|)

with ``a1`` in rad/rad, ``a2`` rad/m, ``a3`` m/m, ``a4`` m/rad (the numbers
are standard deviations, not variances). Backward motion is a negative
translation, so reversing does not read as a half turn.
"""

from __future__ import annotations

import numpy as np

from workbench.mapping.geometry import between, compose, wrap_angle

#: ``(a1, a2, a3, a4)`` of the three noise levels used by the benchmark and the notebook.
NOISE_LEVELS: dict[str, tuple[float, float, float, float]] = {
    "low": (0.02, 0.01, 0.02, 0.01),
    "middle": (0.05, 0.02, 0.05, 0.02),
    "high": (0.1, 0.05, 0.1, 0.05),
}


def noisy_odometry(
    reference: np.ndarray, alphas: tuple[float, float, float, float], seed: int
) -> np.ndarray:
    """Odometry ``(N, 3)`` made from the increments of ``reference`` with seeded model noise."""
    rng = np.random.default_rng(seed)
    a1, a2, a3, a4 = alphas
    out = [np.asarray(reference[0], dtype=float).copy()]
    for k in range(1, len(reference)):
        d = between(reference[k - 1], reference[k])
        t = float(np.hypot(d[0], d[1]))
        r1 = float(np.arctan2(d[1], d[0])) if t > 0.01 else 0.0
        if abs(r1) > np.pi / 2:  # driving backwards
            r1 = float(wrap_angle(r1 - np.pi))
            t = -t
        r2 = float(wrap_angle(d[2] - r1))
        r1n = r1 + rng.normal(0.0, a1 * abs(r1) + a2 * abs(t))
        tn = t + rng.normal(0.0, a3 * abs(t) + a4 * (abs(r1) + abs(r2)))
        r2n = r2 + rng.normal(0.0, a1 * abs(r2) + a2 * abs(t))
        step = np.array([tn * np.cos(r1n), tn * np.sin(r1n), r1n + r2n])
        out.append(compose(out[-1], step))
    return np.array(out)


def align(est: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """``est`` moved by the rigid 2-D transform that best fits its positions to ``ref``'s."""
    mu_e, mu_r = est[:, :2].mean(0), ref[:, :2].mean(0)
    a, b = est[:, :2] - mu_e, ref[:, :2] - mu_r
    theta = np.arctan2((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum(), (a * b).sum())
    c, s = np.cos(theta), np.sin(theta)
    xy = a @ np.array([[c, s], [-s, c]]) + mu_r
    return np.column_stack([xy, wrap_angle(est[:, 2] + theta)])


def absolute_trajectory_error(est: np.ndarray, ref: np.ndarray) -> float:
    """RMSE of positions (m) after the best rigid alignment of ``est`` onto ``ref``."""
    aligned = align(est, ref)
    return float(np.sqrt(np.mean(np.sum((aligned[:, :2] - ref[:, :2]) ** 2, axis=1))))


def relations(ref: np.ndarray, distance: float) -> list[tuple[int, int]]:
    """Pose pairs ``(i, j)``: ``j`` is the first pose at least ``distance`` m further along ``ref``."""
    path = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(ref[:, :2], axis=0).T))])
    pairs = []
    for i in range(len(ref)):
        j = int(np.searchsorted(path, path[i] + distance))
        if j < len(ref):
            pairs.append((i, j))
    return pairs


def relative_error(
    est: np.ndarray, ref: np.ndarray, pairs: list[tuple[int, int]]
) -> dict[str, float]:
    """Kümmerle et al. (2009) relative error over pose pairs.

    Returns:
        ``trans_mean``/``trans_std`` (m) and ``rot_mean``/``rot_std`` (deg) of the
        error of each estimated relative pose against the reference's, and ``pairs``.
    """
    i = np.array([p[0] for p in pairs], dtype=np.int64)
    j = np.array([p[1] for p in pairs], dtype=np.int64)
    e = between(between(ref[i], ref[j]), between(est[i], est[j]))
    trans = np.hypot(e[:, 0], e[:, 1])
    rot = np.degrees(np.abs(wrap_angle(e[:, 2])))
    return {
        "trans_mean": float(trans.mean()),
        "trans_std": float(trans.std()),
        "rot_mean": float(rot.mean()),
        "rot_std": float(rot.std()),
        "pairs": len(pairs),
    }
