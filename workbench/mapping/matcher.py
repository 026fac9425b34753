"""Correlative scan matching: exact two-level branch-and-bound search plus sub-cell refinement.

The search (as in Olson's real-time correlative matcher, used by Karto and
slam_toolbox) scores every rotation in an angular window and every cell
offset in a linear window by the summed likelihood of the scan's points.
The rotated point sets are computed once per search. Coarse offsets are
scored against the block-maximum field, which bounds the fine scores inside
each block; blocks are expanded best first until no coarse bound beats the
best fine score, so the result equals the exhaustive fine search. A few
Gauss-Newton steps on the bilinear likelihood then refine the pose below one
cell and one angular step.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.mapping.geometry import rotated_points, transform_points, wrap_angle
from workbench.mapping.likelihood import LikelihoodField
from workbench.mapping.uncertainty import score_surface_covariance


@dataclass
class MatchResult:
    """The outcome of a scan match.

    Attributes:
        pose: Best sensor pose ``(x, y, theta)`` in the field's frame (m, rad).
        score: Mean likelihood of the scan's points at ``pose``, in ``[0, 1]``.
        grid_pose: The best pose on the search lattice, before refinement.
        expanded: How many coarse blocks were searched at full resolution.
        covariance: Covariance ``(3, 3)`` of ``pose`` in the field's frame from the score
            surface (see :mod:`workbench.mapping.uncertainty`): small across a corridor,
            huge along it. None when not asked for.
    """

    pose: np.ndarray
    score: float
    grid_pose: np.ndarray
    expanded: int
    covariance: np.ndarray | None = None

    def sigmas(self) -> np.ndarray:
        """Std devs ``(major m, minor m, theta rad)`` of the covariance (NaN without one)."""
        if self.covariance is None:
            return np.full(3, np.nan)
        values = np.linalg.eigvalsh(self.covariance[:2, :2])
        return np.sqrt(np.array([values[1], values[0], self.covariance[2, 2]]))


def match_scan(
    field: LikelihoodField,
    points: np.ndarray,
    guess: np.ndarray,
    *,
    linear_window: float = 0.4,
    angular_window: float = np.radians(12.0),
    angular_step: float = np.radians(0.5),
    refine: bool = True,
    prior: tuple[float, float] | None = None,
    prior_weight: float = 0.05,
    covariance: bool = False,
) -> MatchResult:
    """Find the sensor pose that best aligns scan points with a likelihood field.

    Args:
        field: The map to match against.
        points: Scan points ``(N, 2)`` in the sensor frame (m).
        guess: Initial sensor pose ``(x, y, theta)`` in the field's frame.
        linear_window: Half-width of the square translation window (m).
        angular_window: Half-width of the rotation window (rad).
        angular_step: Rotation step (rad).
        refine: Run the sub-cell Gauss-Newton refinement.
        prior: Standard deviations ``(linear m, angular rad)`` of the guess (the odometry
            prior); the objective is then the mean likelihood minus
            ``prior_weight * 0.5 * mahalanobis²`` of the offset from the guess, which keeps
            matches in featureless corridors near the odometry. None: no prior.
        prior_weight: Weight of the prior term, in mean-likelihood units.
        covariance: Also estimate the covariance of the result from the score surface.

    Returns:
        The best pose and its score.
    """
    guess = np.asarray(guess, dtype=float)
    n_ang = int(np.ceil(angular_window / angular_step))
    thetas = guess[2] + angular_step * np.arange(-n_ang, n_ang + 1)
    rotated = rotated_points(points, thetas) + guess[:2]
    u, v = field.cells(rotated)
    iu = np.floor(u).astype(np.int64)
    iv = np.floor(v).astype(np.int64)
    rows, cols = field.shape
    f = field.factor
    w = int(np.ceil(linear_window / field.resolution))
    n_blocks = int(np.ceil((2 * w + 1) / f))
    starts = -((n_blocks * f - 1) // 2) + f * np.arange(n_blocks)

    n = max(len(points), 1)
    res = field.resolution
    if prior is None:
        lin_w = ang_w = 0.0
    else:
        lin_w = prior_weight * 0.5 * (res / prior[0]) ** 2  # per squared cell offset
        ang_w = prior_weight * 0.5 * (angular_step / prior[1]) ** 2  # per squared step
    ang_pen = ang_w * np.arange(-n_ang, n_ang + 1) ** 2  # (K,)

    # Coarse scores for every (rotation, block-u, block-v), minus the least prior penalty.
    bu, bv = np.meshgrid(starts, starts, indexing="ij")
    bu, bv = bu.reshape(-1), bv.reshape(-1)
    # Pad the fields with zeros so that no index needs clipping: points whose cell lies
    # outside the field are parked in the middle of the padding, where every offset reads 0.
    # The padded fields are read through flat indices (row * width + column).
    reach = int(max(abs(starts[0]), abs(starts[-1]) + f)) + 1
    pad = 2 * reach
    width = cols + 2 * pad
    fine = np.pad(field.fine, pad).reshape(-1)
    coarse_field = np.pad(field.coarse, pad).reshape(-1)
    outside = (iu < 0) | (iu >= cols) | (iv < 0) | (iv >= rows)
    cell = np.where(outside, reach * width + reach, (iv + pad) * width + (iu + pad))  # (K, N)
    near_u = np.where((bu <= 0) & (bu + f - 1 >= 0), 0, np.minimum(abs(bu), abs(bu + f - 1)))
    near_v = np.where((bv <= 0) & (bv + f - 1 >= 0), 0, np.minimum(abs(bv), abs(bv + f - 1)))
    block = bv * width + bu  # (B,)
    coarse = coarse_field[cell[:, None, :] + block[None, :, None]].sum(axis=2) / n  # (K, B)
    coarse -= ang_pen[:, None] + lin_w * (near_u**2 + near_v**2)[None, :]
    order = np.argsort(coarse, axis=None)[::-1]
    fine_du, fine_dv = np.meshgrid(np.arange(f), np.arange(f), indexing="ij")
    fine_du, fine_dv = fine_du.reshape(-1), fine_dv.reshape(-1)
    fine_step = fine_dv * width + fine_du
    best = (-np.inf, 0, 0, 0)
    expanded = 0
    flat_coarse = coarse.reshape(-1)
    n_b = len(bu)
    for index in order:
        if flat_coarse[index] <= best[0]:
            break
        k, b = divmod(int(index), n_b)
        du = bu[b] + fine_du
        dv = bv[b] + fine_dv
        scores = fine[cell[k][None, :] + (block[b] + fine_step)[:, None]].sum(axis=1) / n
        scores -= ang_pen[k] + lin_w * (du**2 + dv**2)
        j = int(np.argmax(scores))
        expanded += 1
        if scores[j] > best[0]:
            best = (float(scores[j]), k, int(du[j]), int(dv[j]))
    _, k, du, dv = best
    grid_pose = np.array(
        [guess[0] + du * field.resolution, guess[1] + dv * field.resolution, thetas[k]]
    )
    grid_pose[2] = wrap_angle(grid_pose[2])
    pose = grid_pose.copy()
    if refine and len(points):
        pose = refine_pose(field, points, grid_pose, field.resolution, angular_step)
        pose = refine_to_points(field, points, pose, 2.0 * field.resolution, angular_step)
    score = smooth_score(field, points, pose)
    cov = score_surface_covariance(field, points, pose) if covariance and len(points) else None
    return MatchResult(pose, score, grid_pose, expanded, cov)


def refine_to_points(
    field: LikelihoodField,
    points: np.ndarray,
    pose: np.ndarray,
    max_shift: float,
    max_turn: float,
    iterations: int = 6,
) -> np.ndarray:
    """Robust point-to-point alignment with the field's exact map points (sub-cell accuracy).

    Each scan point is paired with its nearest map point within ``3 sigma``
    and weighted by the Gaussian of that distance; the weighted rigid fit is
    solved in closed form. Moves beyond ``max_shift`` / ``max_turn`` of the
    start are refused (the lattice search already chose the basin).
    """
    start = np.asarray(pose, dtype=float)
    x = start.copy()
    tree = field.tree()
    gate = 3.0 * field.sigma
    for _ in range(iterations):
        world = transform_points(x, points)
        dist, nearest = tree.query(world, distance_upper_bound=gate)
        ok = np.isfinite(dist)
        if ok.sum() < 3:
            break
        w = np.exp(-0.5 * (dist[ok] / field.sigma) ** 2)
        src, dst = world[ok], field.points[nearest[ok]]
        mu_s = (w[:, None] * src).sum(0) / w.sum()
        mu_d = (w[:, None] * dst).sum(0) / w.sum()
        a, b = src - mu_s, dst - mu_d
        cross = (w * (a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])).sum()
        dot = (w * (a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])).sum()
        dtheta = np.arctan2(cross, dot)
        c, s = np.cos(dtheta), np.sin(dtheta)
        rotated_mu = np.array([c * mu_s[0] - s * mu_s[1], s * mu_s[0] + c * mu_s[1]])
        t = mu_d - rotated_mu
        # Compose the increment (rotation about the map origin, then t) with x.
        new = np.array([c * x[0] - s * x[1] + t[0], s * x[0] + c * x[1] + t[1], x[2] + dtheta])
        if (
            np.hypot(*(new[:2] - start[:2])) > max_shift
            or abs(wrap_angle(new[2] - start[2])) > max_turn
        ):
            break
        done = np.hypot(*(new[:2] - x[:2])) < 1e-4 and abs(dtheta) < 1e-5
        x = new
        if done:
            break
    x[2] = wrap_angle(x[2])
    return x


def smooth_score(field: LikelihoodField, points: np.ndarray, pose: np.ndarray) -> float:
    """Mean bilinear likelihood of sensor-frame points ``(N, 2)`` placed at ``pose``."""
    if len(points) == 0:
        return 0.0
    value, _ = field.interpolate(transform_points(pose, points))
    return float(value.mean())


def refine_pose(
    field: LikelihoodField,
    points: np.ndarray,
    pose: np.ndarray,
    max_shift: float,
    max_turn: float,
    iterations: int = 8,
) -> np.ndarray:
    """Gauss-Newton on ``sum (1 - L(T p))²`` with the bilinear field, staying near ``pose``.

    Steps that would leave ``max_shift`` (m) / ``max_turn`` (rad) of the start
    are clipped, so the refinement cannot jump to another optimum.
    """
    start = np.asarray(pose, dtype=float)

    sx, sy = np.ascontiguousarray(points[:, 0]), np.ascontiguousarray(points[:, 1])

    def evaluate(x: np.ndarray):
        c, s = np.cos(x[2]), np.sin(x[2])
        px = c * sx - s * sy
        py = s * sx + c * sy
        value, gx, gy = field.interpolate_xy(px + x[0], py + x[1])
        return value, (gx, gy), px, py

    x = start.copy()
    value, grad, px, py = evaluate(x)
    cost = float(((1.0 - value) ** 2).sum())
    for _ in range(iterations):
        residual = 1.0 - value
        jac = np.empty((len(points), 3))
        jac[:, 0] = -grad[0]
        jac[:, 1] = -grad[1]
        jac[:, 2] = -(grad[0] * -py + grad[1] * px)
        h = jac.T @ jac
        h += np.diag(np.maximum(np.diag(h), 1e-6)) * 1e-3
        try:
            step = -np.linalg.solve(h, jac.T @ residual)
        except np.linalg.LinAlgError:
            break
        improved = False
        for _halving in range(6):  # backtrack until the cost drops
            trial = x + step
            trial[:2] = start[:2] + np.clip(trial[:2] - start[:2], -max_shift, max_shift)
            trial[2] = start[2] + np.clip(wrap_angle(trial[2] - start[2]), -max_turn, max_turn)
            t_value, t_grad, t_px, t_py = evaluate(trial)
            t_cost = float(((1.0 - t_value) ** 2).sum())
            if t_cost < cost:
                improved = True
                break
            step = 0.5 * step
        if not improved:
            break
        moved = np.abs(trial - x)
        x, value, grad, px, py, cost = trial, t_value, t_grad, t_px, t_py, t_cost
        if moved[:2].max() < 1e-4 and moved[2] < 1e-5:
            break
    x[2] = wrap_angle(x[2])
    return x
