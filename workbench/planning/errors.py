"""The specific errors of planning: each names what is wrong and what to do about it."""

from __future__ import annotations

from workbench.errors import PlanningError


class SceneError(PlanningError):
    """A planning scene (YAML or Python) is malformed: bad type, size or pose."""


class UnknownPlannerError(PlanningError):
    """The planner name is not one OMPL offers."""


class GoalError(PlanningError):
    """A goal is malformed: unknown named state, wrong number of joints, outside the limits."""


class StartInCollisionError(PlanningError):
    """The start state collides; the message names the two bodies."""


class GoalInCollisionError(GoalError):
    """The goal state collides; the message names the two bodies."""


class IKError(GoalError):
    """Inverse kinematics found no collision-free solution within the joint limits."""


class NoPathError(PlanningError):
    """The planner found no path within the time limit."""


class TrajectoryError(PlanningError):
    """A timed trajectory breaks a limit or collides in the final check (never returned)."""
