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

#: Farthest an ``xyz=`` goal may be from the world origin, m (an arm reaches a few metres;
#: beyond this, inverse kinematics would only search in vain).
MAX_GOAL_DISTANCE = 1000.0
#: Longest goal text a message quotes in full.
_SHOWN = 60


def _shown(text: str) -> str:
    return text if len(text) <= _SHOWN else text[: _SHOWN - 3] + "..."


def _numbers(text: str, what: str, count: int | None = None) -> tuple[float, ...]:
    parts = [p for p in text.replace(" ", "").split(",") if p != ""]
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise GoalError(
            f"{what} must be comma-separated numbers, got '{_shown(text)}'",
            hint="e.g. q=0,0.5,-0.3",
        ) from None
    if not values or not all(math.isfinite(v) for v in values):
        raise GoalError(f"{what} needs finite numbers, got '{_shown(text)}'")
    if count is not None and len(values) != count:
        raise GoalError(f"{what} needs {count} numbers, got {len(values)} ('{_shown(text)}')")
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
        if max(abs(v) for v in xyz) > MAX_GOAL_DISTANCE:
            raise GoalError(
                f"xyz must be within {MAX_GOAL_DISTANCE:,.0f} m of the world origin on each axis, "
                f"got '{_shown(body)}'",
                hint="give the point in metres, within the robot's reach",
            )
        return PositionGoal(xyz, rpy)  # type: ignore[arg-type]
    if "=" in text or "," in text:
        raise GoalError(
            f"cannot read goal '{_shown(text)}'",
            hint="use a named state, random, q=J1,J2,... or xyz=X,Y,Z",
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


@dataclass(frozen=True)
class GroupOutline:
    """What the cheap goal checks need of a planning group, read without Drake.

    Attributes:
        group: Group name.
        joint_names: The group's movable joints, in the description's order.
        lower, upper: Their position limits (rad or m); infinite where the joint has none.
        state_names: The group's named states (``home`` ...).
    """

    group: str
    joint_names: tuple[str, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    state_names: tuple[str, ...]


def group_outline(config, group: str | None = None) -> GroupOutline | None:
    """The outline of ``group`` (default: the configuration's) from the URDF and SRDF text.

    Reads the description with lxml only (no Drake), so a bad goal is rejected in a
    fraction of the time building a planner takes.

    Args:
        config: A :class:`~workbench.planning.config.PlanningConfig`.
        group: Planning group name.

    Returns:
        The outline, or None for a description only Drake reads (SDF).

    Raises:
        SrdfError: Unknown group, or one naming joints or links the robot lacks.
        ModelError: The description cannot be read.
    """
    from workbench.model.loader import load_document

    if config.robot.suffix == ".sdf":
        return None
    document = load_document(config.robot)
    name = group or config.group
    names = config.srdf.group_joints(name, document)
    joints = {joint.name: joint for joint in document.joints}
    lower = tuple(_limit(joints[n].lower, joints[n].type, -math.inf) for n in names)
    upper = tuple(_limit(joints[n].upper, joints[n].type, math.inf) for n in names)
    return GroupOutline(
        name, tuple(names), lower, upper, tuple(config.srdf.group_state_names(name))
    )


def _limit(value: float | None, joint_type: str, unbounded: float) -> float:
    # A continuous joint ignores any limits it states (as Drake and MoveIt do).
    return unbounded if value is None or joint_type == "continuous" else float(value)


def check_goal(goal: Goal | str, outline: GroupOutline, what: str = "goal") -> Goal:
    """Parse ``goal`` and check it against the group before any planner is built.

    Checks the syntax, that a named state exists, and that joint values are one per
    group joint and within the limits. Random and tip-position goals are checked
    later, against the collision model and by IK.

    Returns:
        The parsed goal.

    Raises:
        GoalError: What is wrong, naming the joints, states or limits.
    """
    if isinstance(goal, str):
        goal = parse_goal(goal)
    if isinstance(goal, NamedGoal) and goal.name not in outline.state_names:
        known = ", ".join(outline.state_names) or "none"
        raise GoalError(
            f"{what}: group '{outline.group}' has no named state '{_shown(goal.name)}'",
            hint=f"known states: {known}; or use random, q=J1,J2,... or xyz=X,Y,Z",
        )
    if isinstance(goal, JointGoal):
        if len(goal.values) != len(outline.joint_names):
            raise GoalError(
                f"{what}: group '{outline.group}' has {len(outline.joint_names)} joints "
                f"({', '.join(outline.joint_names)}), the {what} gives {len(goal.values)} values"
            )
        check_limits(
            list(outline.joint_names),
            np.array(goal.values, float),
            np.array(outline.lower, float),
            np.array(outline.upper, float),
            what,
        )
    return goal
