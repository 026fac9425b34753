"""move_base's parameters (``move_base/src/move_base.cpp``, Noetic) and its plugin names.

Private parameters and defaults: ``base_global_planner`` (``navfn/NavfnROS``),
``base_local_planner`` (``base_local_planner/TrajectoryPlannerROS``), ``planner_frequency``
(0 Hz: plan on new goals and when the controller fails), ``controller_frequency`` (20 Hz),
``planner_patience`` (5 s), ``controller_patience`` (15 s), ``max_planning_retries`` (-1:
unlimited within the patience), ``oscillation_timeout`` (0 s: off), ``oscillation_distance``
(0.5 m), ``recovery_behavior_enabled`` and ``clearing_rotation_allowed`` (true),
``shutdown_costmaps`` (false), ``conservative_reset_dist`` (3 m),
``local_costmap/circumscribed_radius`` (0.46 m; the aggressive reset clears outside 4 times
it), ``make_plan_clear_costmap`` and ``make_plan_add_unreachable_goal`` (true).
``recovery_behaviors`` (a list of ``{name, type}``) replaces the default order
conservative_reset, rotate_recovery, aggressive_reset, rotate_recovery (the rotations only
with ``clearing_rotation_allowed``).

Planner names are ``package/Class``; a bare class name is accepted with move_base's
deprecation warning. An unknown name is a one-line :class:`MoveBaseError`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from workbench.errors import WorkbenchError
from workbench.navigation.local_planner_params import ParamReader

GLOBAL_PLANNERS = ("navfn/NavfnROS",)
LOCAL_PLANNERS = ("base_local_planner/TrajectoryPlannerROS", "dwa_local_planner/DWAPlannerROS")


class MoveBaseError(WorkbenchError):
    """move_base cannot start with this configuration (one line naming the parameter)."""


@dataclass
class MoveBaseParams:
    base_global_planner: str
    base_local_planner: str
    planner_frequency: float
    controller_frequency: float
    planner_patience: float
    controller_patience: float
    max_planning_retries: int
    oscillation_timeout: float
    oscillation_distance: float
    recovery_behavior_enabled: bool
    clearing_rotation_allowed: bool
    shutdown_costmaps: bool
    conservative_reset_dist: float
    circumscribed_radius: float
    make_plan_clear_costmap: bool
    make_plan_add_unreachable_goal: bool
    recovery_behaviors: list[tuple[str, str]]


def plugin_name(node: Any, key: str, value: Any, known: tuple[str, ...], what: str) -> str:
    """A planner's full ``package/Class`` name (a bare class name warns, as move_base does)."""
    if not isinstance(value, str):
        raise MoveBaseError(
            f"parameter {node.resolve_name(key)} must be a planner name, got {value!r}"
        )
    if value in known:
        return value
    for full in known:
        if value == full.split("/", 1)[1]:
            node.get_logger().warn(
                "Planner specifications should now include the package name. You are using a deprecated "
                f"API. Please switch from {value} to {full} in your yaml file."
            )
            return full
    raise MoveBaseError(
        f"Failed to create the {value} {what}: parameter {node.resolve_name(key)} names no known planner",
        hint=f"use one of {', '.join(known)}",
    )


def read_params(node: Any) -> MoveBaseParams:
    """move_base's parameters from the node's private namespace.

    Raises:
        MoveBaseError, PlannerParameterError: A value of the wrong type or an unknown planner.
    """
    r = ParamReader(node, "~")
    clearing_rotation = r.flag("clearing_rotation_allowed", True)
    behaviours = _recovery_list(node, r, clearing_rotation)
    return MoveBaseParams(
        base_global_planner=plugin_name(
            node,
            "~base_global_planner",
            node.get_param("~base_global_planner", "navfn/NavfnROS"),
            GLOBAL_PLANNERS,
            "global planner",
        ),
        base_local_planner=plugin_name(
            node,
            "~base_local_planner",
            node.get_param("~base_local_planner", "base_local_planner/TrajectoryPlannerROS"),
            LOCAL_PLANNERS,
            "local planner",
        ),
        planner_frequency=r.number("planner_frequency", 0.0),
        controller_frequency=r.number("controller_frequency", 20.0, positive=True),
        planner_patience=r.number("planner_patience", 5.0),
        controller_patience=r.number("controller_patience", 15.0),
        max_planning_retries=r.integer("max_planning_retries", -1, minimum=-1),
        oscillation_timeout=r.number("oscillation_timeout", 0.0),
        oscillation_distance=r.number("oscillation_distance", 0.5),
        recovery_behavior_enabled=r.flag("recovery_behavior_enabled", True),
        clearing_rotation_allowed=clearing_rotation,
        shutdown_costmaps=r.flag("shutdown_costmaps", False),
        conservative_reset_dist=r.number("conservative_reset_dist", 3.0),
        circumscribed_radius=r.number("local_costmap/circumscribed_radius", 0.46),
        make_plan_clear_costmap=r.flag("make_plan_clear_costmap", True),
        make_plan_add_unreachable_goal=r.flag("make_plan_add_unreachable_goal", True),
        recovery_behaviors=behaviours,
    )


def _recovery_list(node: Any, r: ParamReader, clearing_rotation: bool) -> list[tuple[str, str]]:
    """``recovery_behaviors`` if given, else move_base's defaults (and their reset distances)."""
    from workbench.navigation.recovery import RECOVERY_TYPES

    given = node.get_param("~recovery_behaviors", None)
    if given is None:
        node.set_param(
            "~conservative_reset/reset_distance", r.number("conservative_reset_dist", 3.0)
        )
        node.set_param(
            "~aggressive_reset/reset_distance",
            4.0 * r.number("local_costmap/circumscribed_radius", 0.46),
        )
        clear, rotate = (
            "clear_costmap_recovery/ClearCostmapRecovery",
            "rotate_recovery/RotateRecovery",
        )
        order = [("conservative_reset", clear)]
        if clearing_rotation:
            order.append(("rotate_recovery", rotate))
        order.append(("aggressive_reset", clear))
        if clearing_rotation:
            order.append(("rotate_recovery", rotate))
        return order
    key = node.resolve_name("~recovery_behaviors")
    if not isinstance(given, list):
        raise MoveBaseError(
            f"parameter {key} must be a list of {{name, type}} entries, got {given!r}"
        )
    order = []
    for i, entry in enumerate(given):
        if (
            not isinstance(entry, dict)
            or not isinstance(entry.get("name"), str)
            or "type" not in entry
        ):
            raise MoveBaseError(f"parameter {key}[{i}] must have a name and a type, got {entry!r}")
        if entry["type"] not in RECOVERY_TYPES:
            raise MoveBaseError(
                f"parameter {key}[{i}]: unknown recovery behavior type {entry['type']!r}",
                hint=f"use one of {', '.join(RECOVERY_TYPES)}",
            )
        order.append((entry["name"], entry["type"]))
    return order
