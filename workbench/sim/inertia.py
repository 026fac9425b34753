"""Inertias Gazebo accepts and Drake refuses, made valid with the smallest change.

Gazebo's ODE simulates an inertia whose principal moments break the triangle
inequality (the manual's simple_box: ixx = izz = 1, iyy = 100); no physical
body has one, and Drake refuses it. The two smaller principal moments are
raised by the same amount until the smaller two add up to the largest, which
keeps the largest moment and the principal axes.
"""

from __future__ import annotations

import numpy as np

from workbench.errors import SimulationError

#: SDFormat's default ``<inertial>``: what Gazebo gives a link that declares none.
DEFAULT_MASS = 1.0
DEFAULT_MOMENT = 1.0
_SLACK = 1e-9


def inertia_matrix(
    ixx: float, iyy: float, izz: float, ixy: float, ixz: float, iyz: float
) -> np.ndarray:
    """The symmetric 3x3 inertia matrix, kg m^2."""
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], dtype=float)


def valid_inertia(matrix: np.ndarray) -> np.ndarray | None:
    """A physically valid inertia close to ``matrix``, or None when it is valid already.

    Raises:
        ValueError: Entries that are not finite.
    """
    if not np.all(np.isfinite(matrix)):
        raise ValueError("inertia entries must be finite")
    symmetric = 0.5 * matrix + 0.5 * matrix.T  # halves first: 1e308 + 1e308 overflows
    with np.errstate(all="ignore"):
        moments, axes = np.linalg.eigh(symmetric)
    if not (np.all(np.isfinite(moments)) and np.all(np.isfinite(axes))):
        raise ValueError("inertia entries too large to find its principal moments")
    fixed = moments.copy()
    if -fixed[0] > max(fixed[2], 0.0):  # more negative than the body's largest moment
        raise ValueError("a negative principal moment larger than the others")
    if np.any(fixed < 0):
        fixed = np.maximum(fixed, 0.0)
    small, middle, large = fixed
    deficit = large - (small + middle)
    if deficit > _SLACK * max(large, 1e-12):
        fixed[0] += deficit / 2 + _SLACK * large
        fixed[1] += deficit / 2 + _SLACK * large
    if np.allclose(fixed, moments, rtol=0, atol=_SLACK * max(abs(large), 1e-12)):
        return None
    result = axes @ np.diag(fixed) @ axes.T
    if not np.all(np.isfinite(result)):
        raise ValueError("inertia entries too large to repair")
    return result


def describe(matrix: np.ndarray) -> str:
    """``ixx=… iyy=… izz=…`` (and the non-zero products) for messages."""
    names = ("ixx", "iyy", "izz")
    parts = [f"{n}={matrix[i, i]:.6g}" for i, n in enumerate(names)]
    for (i, j), n in (((0, 1), "ixy"), ((0, 2), "ixz"), ((1, 2), "iyz")):
        if abs(matrix[i, j]) > 1e-15:
            parts.append(f"{n}={matrix[i, j]:.6g}")
    return " ".join(parts)


ENTRIES = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
_INDEX = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def repaired(values: list[float], link: str, where: str) -> tuple[list[float], str] | None:
    """``(ixx … iyz fixed, warning line)`` when ``values`` break the triangle inequality, else None."""
    matrix = inertia_matrix(*values)
    if not np.all(np.isfinite(matrix)):
        return None  # not finite: the parser reports that itself
    try:
        fixed = valid_inertia(matrix)
    except ValueError:
        raise SimulationError(
            f"{where}: link '{link}': inertia {describe(matrix)} is no body's inertia and "
            "too far from one to repair",
            hint="give moments of inertia >= 0 that a real body can have (kg m^2)",
        ) from None
    if fixed is None:
        return None
    warning = (
        f"{where}: link '{link}': inertia {describe(matrix)} breaks the triangle "
        f"inequality (no real body has it; Drake refuses it); using {describe(fixed)}"
    )
    return [float(fixed[i, j]) for i, j in _INDEX], warning
