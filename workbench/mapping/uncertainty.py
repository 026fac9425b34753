"""How well a scan match is determined: its covariance from the correlative score surface.

Around the matched pose the scan is scored on a lattice of offsets
(translations over a square window at each of a few rotations). Reading the
per-point likelihoods ``L`` as a measurement model with an outlier floor,
the log-likelihood of an offset is ``sum log(L + floor) / points_per_measurement``
(neighbouring beams on one wall are not independent, so several points count as
one measurement). Its normalised exponential is a probability over the
lattice, whose second moment about the matched pose is the covariance (as in
Olson's correlative matcher). A direction in which the surface stays flat to
the edge of the window (along a featureless corridor) is reported as
unconstrained: its variance is set to ``unconstrained_sigma²``, so that
whatever fuses the match (odometry, the pose graph) relies on something else
along it.
"""

from __future__ import annotations

import numpy as np

from workbench.mapping.geometry import rotated_points
from workbench.mapping.likelihood import LikelihoodField


def score_surface_covariance(
    field: LikelihoodField,
    points: np.ndarray,
    pose: np.ndarray,
    *,
    linear_extent: float = 0.4,
    angular_extent: float = np.radians(2.0),
    angular_steps: int = 4,
    points_per_measurement: float = 4.0,
    floor: float = 0.1,
    max_points: int = 240,
    unconstrained_sigma: float = 10.0,
    flat_fraction: float = 0.5,
) -> np.ndarray:
    """Covariance ``(3, 3)`` (m², m·rad, rad²; map frame) of a match at ``pose``.

    Args:
        field: The map the scan was matched against.
        points: Scan points ``(N, 2)`` in the sensor frame (m).
        pose: The matched sensor pose ``(x, y, theta)``.
        linear_extent: Half-width of the translation window (m); its step is one cell.
        angular_extent: Half-width of the rotation window (rad).
        angular_steps: Rotations either side of ``pose`` in the window.
        points_per_measurement: How many points count as one independent measurement.
        floor: Likelihood of a point that the map does not explain (outliers).
        max_points: Points are subsampled evenly to at most this many.
        unconstrained_sigma: Std dev (m) given to a translation direction the surface
            does not constrain.
        flat_fraction: A direction whose std dev exceeds this fraction of that of a
            uniform distribution over the window counts as unconstrained.
    """
    pose = np.asarray(pose, dtype=float)
    res = field.resolution
    if len(points) > max_points:
        points = points[np.linspace(0, len(points) - 1, max_points).astype(np.int64)]
    k = int(np.ceil(linear_extent / res))
    offsets = np.arange(-k, k + 1)
    dthetas = angular_extent * np.arange(-angular_steps, angular_steps + 1) / max(angular_steps, 1)
    rotated = rotated_points(points, pose[2] + dthetas) + pose[:2]
    u, v = field.cells(rotated)
    rows, cols = field.shape
    iu = np.floor(u).astype(np.int64)
    iv = np.floor(v).astype(np.int64)
    # Log-likelihood table over the field padded by more than the window: a point beyond
    # the field is clamped into the padding, where every offset reads the floor.
    pad = 2 * k + 1
    table = np.log(np.pad(field.fine, pad) + np.float32(floor))  # float32: half the reads
    width = table.shape[1]
    iu = np.clip(iu + pad, k, width - 1 - k)
    iv = np.clip(iv + pad, k, table.shape[0] - 1 - k)
    cell = (iv * width + iu)[:, None, :]  # (angles, 1, points)
    grid_u, grid_v = np.meshgrid(offsets, offsets, indexing="ij")
    du, dv = grid_u.reshape(-1), grid_v.reshape(-1)
    # (angles, offsets): summed log-likelihood of the points at each lattice pose.
    lik = table.reshape(-1)[cell + (dv * width + du)[None, :, None]].sum(axis=2, dtype=float)
    lik /= points_per_measurement
    weight = np.exp(lik - lik.max())
    weight /= weight.sum()
    dx = np.broadcast_to(du * res, weight.shape)
    dy = np.broadcast_to(dv * res, weight.shape)
    dt = np.broadcast_to(dthetas[:, None], weight.shape)
    samples = np.stack([dx.ravel(), dy.ravel(), dt.ravel()], axis=1)
    w = weight.ravel()
    cov = (samples * w[:, None]).T @ samples
    # The lattice cannot show a spread below its own step: add the quantisation variance.
    step_theta = dthetas[1] - dthetas[0] if len(dthetas) > 1 else angular_extent
    cov += np.diag([res * res / 12.0, res * res / 12.0, step_theta * step_theta / 12.0])
    # Directions flat to the window's edge: unconstrained.
    uniform = (k * res) / np.sqrt(3.0)
    values, vectors = np.linalg.eigh(cov[:2, :2])
    flat = np.sqrt(values) > flat_fraction * uniform
    if flat.any():
        values = np.where(flat, unconstrained_sigma**2, values)
        xy = (vectors * values) @ vectors.T
        # Decorrelate the unconstrained direction from the rotation.
        keep = vectors[:, ~flat]
        cross = keep @ (keep.T @ cov[:2, 2])
        cov = cov.copy()
        cov[:2, :2] = xy
        cov[:2, 2] = cross
        cov[2, :2] = cross
    return 0.5 * (cov + cov.T)


def to_frame(covariance: np.ndarray, theta: float) -> np.ndarray:
    """A pose covariance ``(3, 3)`` given in the map frame, expressed in a frame turned by ``theta``."""
    c, s = np.cos(theta), np.sin(theta)
    rot = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])  # map -> frame
    return rot @ covariance @ rot.T


def odometry_covariance(delta: np.ndarray, noise: tuple[float, float, float, float]) -> np.ndarray:
    """Covariance ``(3, 3)`` of an odometry increment ``delta`` (in its start frame).

    ``noise`` is ``(m per m, m per rad, rad per m, rad per rad)`` of standard
    deviation along the motion, growing with the distance travelled and the
    angle turned; a small floor keeps it positive definite when standing still.
    """
    dist = float(np.hypot(delta[0], delta[1]))
    turn = abs(float(delta[2]))
    srr, srt, str_, stt = noise
    sigma_t = srr * dist + srt * turn + 0.002
    sigma_r = str_ * dist + stt * turn + np.radians(0.1)
    return np.diag([sigma_t**2, sigma_t**2, sigma_r**2])
