"""Simulated planar laser scans of a world made of line segments (for tests and examples)."""

from __future__ import annotations

import numpy as np

from workbench.mapping.geometry import between, compose
from workbench.mapping.scan import Scan


def box_segments(x0: float, y0: float, x1: float, y1: float) -> np.ndarray:
    """The four walls of an axis-aligned rectangle as segments ``(4, 2, 2)``."""
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=float)
    return np.stack([corners, np.roll(corners, -1, axis=0)], axis=1)


def demo_world() -> np.ndarray:
    """An 8 m x 6 m room with a dividing wall, a pillar and a cabinet: segments ``(N, 2, 2)``."""
    parts = [
        box_segments(0.0, 0.0, 8.0, 6.0),
        np.array([[[4.0, 0.0], [4.0, 2.5]], [[4.0, 3.7], [4.0, 6.0]]]),
        box_segments(1.5, 4.0, 2.0, 4.5),
        box_segments(6.0, 1.0, 7.2, 1.6),
        np.array([[[0.0, 2.0], [0.8, 2.6]]]),
    ]
    return np.concatenate(parts)


def raycast(
    segments: np.ndarray, pose: np.ndarray, angles: np.ndarray, max_range: float
) -> np.ndarray:
    """Ranges from a sensor at ``pose`` along ``angles`` to the nearest segment.

    Beams that hit nothing within ``max_range`` return ``max_range`` (a
    "no return" reading, as real lasers report).
    """
    direction = angles + pose[2]
    d = np.stack([np.cos(direction), np.sin(direction)], axis=1)  # (B, 2)
    a = segments[:, 0]  # (S, 2)
    e = segments[:, 1] - a
    w = a - pose[:2]
    denom = d[:, None, 0] * e[None, :, 1] - d[:, None, 1] * e[None, :, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (w[None, :, 0] * e[None, :, 1] - w[None, :, 1] * e[None, :, 0]) / denom
        s = (w[None, :, 0] * d[:, None, 1] - w[None, :, 1] * d[:, None, 0]) / denom
    hit = (np.abs(denom) > 1e-12) & (t > 0) & (s >= 0) & (s <= 1)
    t = np.where(hit, t, np.inf)
    ranges = t.min(axis=1)
    return np.where(ranges < max_range, ranges, max_range)


def simulate_scans(
    segments: np.ndarray,
    poses: np.ndarray,
    *,
    beams: int = 181,
    fov: float = np.pi,
    max_range: float = 10.0,
    range_noise: float = 0.01,
    odometry_noise: tuple[float, float] = (0.0, 0.0),
    dt: float = 0.5,
    seed: int = 0,
) -> list[Scan]:
    """Scans along a trajectory, with Gaussian range noise and drifting odometry.

    Args:
        segments: The world, ``(N, 2, 2)`` segments (m).
        poses: True sensor poses ``(K, 3)``.
        beams: Beams per scan, spread evenly over ``fov`` centred ahead.
        fov: Field of view (rad).
        max_range: Sensor range (m); misses read exactly this.
        range_noise: Std dev of range noise (m).
        odometry_noise: Std devs (m per step, rad per step) added to each odometry increment.
        dt: Time between scans (s).
        seed: Random seed.

    Returns:
        Scans whose ``reference`` is the true pose and ``odom`` the noisy odometry.
    """
    rng = np.random.default_rng(seed)
    angles = np.linspace(-fov / 2, fov / 2, beams)
    scans: list[Scan] = []
    odom = np.asarray(poses[0], dtype=float)
    for k, pose in enumerate(np.asarray(poses, dtype=float)):
        if k > 0:
            step = between(poses[k - 1], pose)
            step = step + rng.normal(0.0, 1.0, 3) * np.array(
                [odometry_noise[0], odometry_noise[0], odometry_noise[1]]
            )
            odom = compose(odom, step)
        ranges = raycast(segments, pose, angles, max_range)
        noisy = ranges + rng.normal(0.0, range_noise, beams)
        ranges = np.where(ranges >= max_range, max_range, noisy)
        scans.append(
            Scan(
                stamp=k * dt,
                ranges=ranges,
                angles=angles.copy(),
                odom=odom.copy(),
                max_range=max_range,
                reference=pose.copy(),
                source=f"simulated[{k}]",
            )
        )
    return scans


def loop_trajectory(step: float = 0.25) -> np.ndarray:
    """A closed tour of :func:`demo_world` through both rooms, poses every ``step`` m."""
    waypoints = np.array(
        [
            [1.0, 1.0],
            [3.0, 1.2],
            [3.0, 3.1],
            [5.0, 3.1],
            [7.0, 3.0],
            [7.0, 5.0],
            [5.0, 5.2],
            [5.0, 3.1],
            [3.0, 3.1],
            [1.0, 3.2],
            [1.0, 1.0],
        ]
    )
    points = [waypoints[0]]
    for a, b in zip(waypoints[:-1], waypoints[1:], strict=True):
        n = max(int(np.ceil(np.hypot(*(b - a)) / step)), 1)
        for t in np.arange(1, n + 1) / n:
            points.append(a + t * (b - a))
    points = np.array(points)
    heading = np.arctan2(np.diff(points[:, 1]), np.diff(points[:, 0]))
    heading = np.append(heading, heading[-1])
    return np.column_stack([points, heading])
