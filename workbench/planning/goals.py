"""Planning goals: a named state, joint values, a random valid state, or a point for the tip.

On the command line a goal is written ``home`` (any named state of the
group), ``random``, ``q=J1,J2,...`` (one value per group joint, rad or m) or
``xyz=X,Y,Z`` (metres, world frame; add ``,rpy=R,P,Y`` for an orientation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from workbench.planning.errors import GoalError


@dataclass(frozen=True)
class NamedGoal:
    """A named group state from the SRDF (``home``)."""

    name: str


@dataclass(frozen=True)
class JointGoal:
    """Joint values for every joint of the group, in group order (rad or m)."""

    values: tuple[float, ...]


@dataclass(frozen=True)
class RandomGoal:
    """A random collision-free state within the limits (seeded by the request)."""


@dataclass(frozen=True)
class PositionGoal:
    """The tip link's origin at ``xyz`` (world frame, m); optionally oriented by ``rpy`` (rad)."""

    xyz: tuple[float, float, float]
    rpy: tuple[float, float, float] | None = None


Goal = NamedGoal | JointGoal | RandomGoal | PositionGoal


def _numbers(text: str, what: str, count: int | None = None) -> tuple[float, ...]:
    parts = [p for p in text.replace(" ", "").split(",") if p != ""]
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise GoalError(
            f"{what} must be comma-separated numbers, got '{text}'", hint="e.g. q=0,0.5,-0.3"
        ) from None
    if not values or not all(math.isfinite(v) for v in values):
        raise GoalError(f"{what} needs finite numbers, got '{text}'")
    if count is not None and len(values) != count:
        raise GoalError(f"{what} needs {count} numbers, got {len(values)} ('{text}')")
    return values


def parse_goal(text: str) -> Goal:
    """A goal from its command-line form (see the module docstring).

    Raises:
        GoalError: The text is malformed.
    """
    text = text.strip()
    if not text:
        raise GoalError("empty goal", hint="use a named state, random, q=... or xyz=...")
    if text == "random":
        return RandomGoal()
    if text.startswith("q="):
        return JointGoal(_numbers(text[2:], "q"))
    if text.startswith("xyz="):
        body = text[4:]
        rpy = None
        if ",rpy=" in body:
            body, rpy_text = body.split(",rpy=", 1)
            rpy = _numbers(rpy_text, "rpy", 3)
        xyz = _numbers(body, "xyz", 3)
        return PositionGoal(xyz, rpy)  # type: ignore[arg-type]
    if "=" in text or "," in text:
        raise GoalError(
            f"cannot read goal '{text}'", hint="use a named state, random, q=J1,J2,... or xyz=X,Y,Z"
        )
    return NamedGoal(text)


def check_limits(
    names: list[str],
    q: np.ndarray,
    lower: np.ndarray,
    upper: np.ndarray,
    what: str,
    tol: float = 1e-9,
) -> None:
    """Raise :class:`GoalError` naming the first joint of ``q`` outside [lower, upper]."""
    for name, value, lo, hi in zip(names, q, lower, upper, strict=True):
        if value < lo - tol or value > hi + tol:
            raise GoalError(
                f"{what}: joint '{name}' = {value:.4f} is outside its limits [{lo:.4f}, {hi:.4f}]",
                hint="choose a value within the limits",
            )


def random_valid_state(
    lower: np.ndarray, upper: np.ndarray, is_free, seed: int, attempts: int = 10000
) -> np.ndarray:
    """A uniformly random configuration within the bounds that ``is_free`` accepts.

    Raises:
        GoalError: None of ``attempts`` samples was free.
    """
    rng = np.random.default_rng(seed)
    for _ in range(attempts):
        q = rng.uniform(lower, upper)
        if is_free(q):
            return q
    raise GoalError(
        f"no collision-free random state in {attempts} samples", hint="remove obstacles"
    )
