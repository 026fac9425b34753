"""A robot to localise: seeded odometry with a scale error and scans ray-cast in a map.

For tests, benchmarks and notebooks: :func:`noisy_odometry` turns a true trajectory
into what wheel odometry would report, :func:`simulated_ranges` reads a laser in the
mapped world (only occupied cells stop a beam; a beam that meets none reads inf).
"""

from __future__ import annotations

import numpy as np

from workbench.mapping.geometry import between, compose
from workbench.navigation.amcl_map import AmclMap


def noisy_odometry(truth: np.ndarray, seed: int = 0, scale: float = 1.03) -> np.ndarray:
    """Odometry poses ``(K, 3)`` of true poses ``truth`` (``(K, 3)``; m, rad).

    Each step is ``scale`` too long, with Gaussian noise in proportion to it: 5 % of
    the distance in x and y, 2 % of the turn plus 0.02 rad per metre in heading.
    """
    rng = np.random.default_rng(seed)
    odom = [np.asarray(truth[0], dtype=float).copy()]
    for a, b in zip(truth[:-1], truth[1:], strict=True):
        step = between(a, b)
        distance = float(np.hypot(step[0], step[1]))
        step[:2] *= scale
        sd = np.array([0.05 * distance, 0.05 * distance, 0.02 * abs(step[2]) + 0.02 * distance])
        odom.append(compose(odom[-1], step + rng.normal(0.0, 1.0, 3) * sd))
    return np.array(odom)


def simulated_ranges(
    amcl_map: AmclMap,
    sensor_pose: np.ndarray,
    angles: np.ndarray,
    range_max: float,
    rng: np.random.Generator,
    noise: float = 0.01,
) -> np.ndarray:
    """Readings (m) of a laser at ``sensor_pose`` in the map, with Gaussian ``noise`` (m).

    A beam that meets no occupied cell within ``range_max`` reads inf (no return).
    """
    ranges = amcl_map.calc_ranges(sensor_pose, angles, range_max, unknown_blocks=False)
    noisy = ranges + rng.normal(0.0, noise, len(ranges))
    return np.where(ranges >= range_max, np.inf, noisy)


__all__ = ["noisy_odometry", "simulated_ranges"]
