"""SE(2) helpers on poses ``(x, y, theta)`` (metres, radians), vectorised over leading axes."""

from __future__ import annotations

import numpy as np


def wrap_angle(theta: np.ndarray | float) -> np.ndarray | float:
    """Wrap angles to ``[-pi, pi)``."""
    return (np.asarray(theta) + np.pi) % (2.0 * np.pi) - np.pi


def compose(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a ⊕ b``: the pose ``b`` (given in frame ``a``) expressed in ``a``'s parent frame."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    c, s = np.cos(a[..., 2]), np.sin(a[..., 2])
    x = a[..., 0] + c * b[..., 0] - s * b[..., 1]
    y = a[..., 1] + s * b[..., 0] + c * b[..., 1]
    return np.stack([x, y, wrap_angle(a[..., 2] + b[..., 2])], axis=-1)


def inverse(a: np.ndarray) -> np.ndarray:
    """The inverse pose ``a⁻¹``."""
    a = np.asarray(a, dtype=float)
    c, s = np.cos(a[..., 2]), np.sin(a[..., 2])
    x = -c * a[..., 0] - s * a[..., 1]
    y = s * a[..., 0] - c * a[..., 1]
    return np.stack([x, y, wrap_angle(-a[..., 2])], axis=-1)


def between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a⁻¹ ⊕ b``: the pose of ``b`` in the frame of ``a``."""
    return compose(inverse(a), b)


def transform_points(pose: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Points ``(N, 2)`` given in the frame ``pose`` expressed in its parent frame."""
    c, s = np.cos(pose[2]), np.sin(pose[2])
    out = np.empty_like(points, dtype=float)
    out[:, 0] = pose[0] + c * points[:, 0] - s * points[:, 1]
    out[:, 1] = pose[1] + s * points[:, 0] + c * points[:, 1]
    return out


def rotated_points(points: np.ndarray, thetas: np.ndarray) -> np.ndarray:
    """Points ``(N, 2)`` rotated by each angle: ``(K, N, 2)``."""
    c, s = np.cos(thetas)[:, None], np.sin(thetas)[:, None]
    x, y = points[None, :, 0], points[None, :, 1]
    return np.stack([c * x - s * y, s * x + c * y], axis=-1)
