"""Reading a local planner's parameters as base_local_planner reads them, with one-line errors.

``TrajectoryPlannerROS`` reads ``~<name>/...`` (``/move_base/TrajectoryPlannerROS/max_vel_x``):
the names and defaults of ``trajectory_planner_ros.cpp`` (Noetic), including the older names
it still accepts (``pdist_scale``/``gdist_scale`` when the ``*_bias`` names are unset,
``max_rotational_vel``, ``min_in_place_rotational_vel``, ``acc_lim_th``, ``backup_vel``), and
``controller_frequency`` found by searching upwards from its namespace (20 Hz if absent).
"""

from __future__ import annotations

import math
from typing import Any

from workbench.errors import WorkbenchError
from workbench.navigation.trajectory_rollout import RolloutParams


class PlannerParameterError(WorkbenchError):
    """A planner parameter has the wrong type or value (names the parameter)."""


class ParamReader:
    """Typed reads of ``<prefix>/<key>`` with the parameter named in errors."""

    def __init__(self, node: Any, prefix: str) -> None:
        self.node = node
        self.prefix = prefix if prefix == "~" else prefix.rstrip("/")

    def key(self, name: str) -> str:
        return f"~{name}" if self.prefix == "~" else f"{self.prefix}/{name}"

    def has(self, name: str) -> bool:
        return bool(self.node.has_param(self.key(name)))

    def number(self, name: str, default: float, *, positive: bool = False) -> float:
        value = self.node.get_param(self.key(name), default)
        if (
            isinstance(value, bool)
            or not isinstance(value, (int, float))
            or not math.isfinite(value)
        ):
            raise PlannerParameterError(
                f"parameter {self.node.resolve_name(self.key(name))} must be a number, got {value!r}"
            )
        if positive and value <= 0:
            raise PlannerParameterError(
                f"parameter {self.node.resolve_name(self.key(name))} must be positive, got {value!r}"
            )
        return float(value)

    def integer(self, name: str, default: int, *, minimum: int = 1) -> int:
        value = self.node.get_param(self.key(name), default)
        if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
            raise PlannerParameterError(
                f"parameter {self.node.resolve_name(self.key(name))} must be an integer >= {minimum}, "
                f"got {value!r}"
            )
        return value

    def flag(self, name: str, default: bool) -> bool:
        value = self.node.get_param(self.key(name), default)
        if not isinstance(value, bool):
            raise PlannerParameterError(
                f"parameter {self.node.resolve_name(self.key(name))} must be true or false, got {value!r}"
            )
        return value

    def number_either(self, new: str, old: str, default: float) -> float:
        """``new``, else the older name ``old``, else ``default``."""
        if not self.has(new) and self.has(old):
            return self.number(old, default)
        return self.number(new, default)


def controller_frequency(node: Any, prefix: str) -> float:
    """The nearest ``controller_frequency`` above ``prefix`` (20 Hz if none or not positive)."""
    found = node.bus.params.search(node.resolve_name(prefix), "controller_frequency")
    if found is None:
        return 20.0
    value = node.get_param(found, 20.0)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise PlannerParameterError(f"parameter {found} must be a number, got {value!r}")
    if value <= 0:
        node.get_logger().warn(
            "A controller_frequency less than 0 has been set. Ignoring the parameter, assuming a rate of 20Hz"
        )
        return 20.0
    return float(value)


def y_vels(reader: ParamReader) -> tuple[float, ...]:
    """``y_vels`` as a list or ``"[-0.3, -0.1, 0.1, 0.3]"`` text (the default)."""
    value = reader.node.get_param(reader.key("y_vels"), None)
    if value is None:
        return (-0.3, -0.1, 0.1, 0.3)
    try:
        if isinstance(value, str):
            return tuple(
                float(v)
                for v in value.replace("[", " ").replace("]", " ").replace(",", " ").split()
            )
        return tuple(float(v) for v in value)
    except (TypeError, ValueError):
        raise PlannerParameterError(
            f"parameter {reader.node.resolve_name(reader.key('y_vels'))} must be a list of numbers, got {value!r}"
        ) from None


def trajectory_planner_params(node: Any, prefix: str) -> tuple[RolloutParams, dict[str, Any]]:
    """TrajectoryPlannerROS's parameters under ``prefix`` (e.g. ``~TrajectoryPlannerROS``).

    Returns:
        The rollout parameters and the host's own settings (``xy_goal_tolerance``,
        ``yaw_goal_tolerance``, ``latch_xy_goal_tolerance``, ``meter_scoring``,
        ``prune_plan``, ``occdist_scale``).

    Raises:
        PlannerParameterError: A parameter of the wrong type, naming it.
    """
    r = ParamReader(node, prefix)
    for wrong, right in (
        ("acc_limit_x", "acc_lim_x"),
        ("acc_limit_y", "acc_lim_y"),
        ("acc_limit_th", "acc_lim_th"),
    ):
        if r.has(wrong):
            node.get_logger().error(
                f"You are using {wrong} where you should be using {right}. Please change your configuration "
                "files appropriately. The documentation used to be wrong on this, sorry for any confusion."
            )
    max_vel_theta = r.number_either("max_vel_theta", "max_rotational_vel", 1.0)
    escape = r.number("backup_vel", -0.1) if r.has("backup_vel") else -0.1
    if r.has("backup_vel"):
        node.get_logger().warn(
            "The backup_vel parameter has been deprecated in favor of the escape_vel parameter. To switch, "
            "just change the parameter name in your configuration files."
        )
    escape = r.number("escape_vel", escape)
    if escape >= 0.0:
        node.get_logger().warn(
            "You've specified a positive escape velocity. This is probably not what you want and will cause "
            "the robot to move forward instead of backward. You should probably change your escape_vel "
            "parameter to be negative"
        )
    sim_granularity = r.number("sim_granularity", 0.025, positive=True)
    params = RolloutParams(
        max_vel_x=r.number("max_vel_x", 0.5),
        min_vel_x=r.number("min_vel_x", 0.1),
        max_vel_theta=max_vel_theta,
        min_vel_theta=r.number("min_vel_theta", -1.0),
        min_in_place_vel_theta=r.number_either(
            "min_in_place_vel_theta", "min_in_place_rotational_vel", 0.4
        ),
        acc_lim_x=r.number("acc_lim_x", 2.5),
        acc_lim_y=r.number("acc_lim_y", 2.5),
        acc_lim_theta=r.number_either("acc_lim_theta", "acc_lim_th", 3.2),
        sim_time=r.number("sim_time", 1.0, positive=True),
        sim_granularity=sim_granularity,
        angular_sim_granularity=r.number("angular_sim_granularity", sim_granularity, positive=True),
        vx_samples=r.integer("vx_samples", 3),
        vtheta_samples=r.integer("vtheta_samples", 20),
        path_distance_bias=r.number_either("path_distance_bias", "pdist_scale", 0.6),
        goal_distance_bias=r.number_either("goal_distance_bias", "gdist_scale", 0.8),
        occdist_scale=r.number("occdist_scale", 0.01),
        heading_lookahead=r.number("heading_lookahead", 0.325),
        oscillation_reset_dist=r.number("oscillation_reset_dist", 0.05),
        escape_reset_dist=r.number("escape_reset_dist", 0.10),
        escape_reset_theta=r.number("escape_reset_theta", math.pi / 4),
        holonomic_robot=r.flag("holonomic_robot", True),
        escape_vel=escape,
        dwa=r.flag("dwa", True),
        y_vels=y_vels(r),
        sim_period=1.0 / controller_frequency(node, prefix),
    )
    host = {
        "xy_goal_tolerance": r.number("xy_goal_tolerance", 0.10),
        "yaw_goal_tolerance": r.number("yaw_goal_tolerance", 0.05),
        "latch_xy_goal_tolerance": r.flag("latch_xy_goal_tolerance", False),
        "meter_scoring": r.flag("meter_scoring", False),
        "meter_scoring_set": r.has("meter_scoring"),
        "prune_plan": r.flag("prune_plan", True),
    }
    return params, host
