"""move_base's recovery behaviours: clear_costmap_recovery and rotate_recovery.

* ``clear_costmap_recovery/ClearCostmapRecovery`` (Noetic): reads ``~<name>/reset_distance``
  (3.0 m), ``force_updating`` (false), ``affected_maps`` (``both``; another value is warned
  about and taken as ``both``) and ``layer_names`` (``["obstacles"]``, matched against the
  last part of each layer's name); running it logs ``Clearing both costmaps outside a square
  (3.00m) large centered on the robot.`` and makes the named layers unknown outside the square
  of side ``reset_distance`` centred on the robot.
* ``rotate_recovery/RotateRecovery``: a full turn in place, ``~<name>/sim_granularity``
  (0.017 rad) and ``frequency`` (20 Hz), with ``acc_lim_th`` (3.2), ``max_rotational_vel``
  (1.0), ``min_in_place_rotational_vel`` (0.4) and ``yaw_goal_tolerance`` (0.10) read from
  ``~TrajectoryPlannerROS``: before each command the rest of the turn is checked against the
  footprint (``Rotate recovery can't rotate in place because there is a potential collision.
  Cost: -1.00`` ends it); the speed is ``sqrt(2 acc_lim_th remaining)`` clamped to the limits.

Behaviours run in steps so the host's control loop keeps running (ROS blocks its thread):
:meth:`start` then :meth:`step` every control cycle until it returns True.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from workbench.navigation.costs import LETHAL_OBSTACLE, NO_INFORMATION
from workbench.navigation.local_planner_params import ParamReader
from workbench.navigation.trajectory_rollout import CostGrid, outline_points


class ClearCostmapRecovery:
    """Forget obstacles outside a square around the robot in the chosen costmaps."""

    kind = "clear_costmap_recovery/ClearCostmapRecovery"

    def __init__(self, node: Any, name: str, global_costmap: Any, local_costmap: Any) -> None:
        self.node, self.name = node, name
        self.global_costmap, self.local_costmap = global_costmap, local_costmap
        r = ParamReader(node, f"~{name}")
        self.reset_distance = r.number("reset_distance", 3.0)
        self.force_updating = r.flag("force_updating", False)
        affected = node.get_param(r.key("affected_maps"), "both")
        if affected not in ("local", "global", "both"):
            node.get_logger().warn(
                f"Wrong value for affected_maps parameter: '{affected}'; valid values are 'local', "
                "'global' or 'both'; defaulting to 'both'"
            )
            affected = "both"
        self.affected_maps = affected
        layers = node.get_param(r.key("layer_names"), ["obstacles"])
        if isinstance(layers, str):
            layers = [layers]
        self.layer_names = [str(v) for v in layers]
        for layer in self.layer_names:
            node.get_logger().info(f"Recovery behavior will clear layer '{layer}'")

    def start(self) -> None:
        plural = "s" if self.affected_maps == "both" else ""
        self.node.get_logger().warn(
            f"Clearing {self.affected_maps} costmap{plural} outside a square "
            f"({self.reset_distance:.2f}m) large centered on the robot."
        )
        maps = []
        if self.affected_maps in ("global", "both"):
            maps.append(self.global_costmap)
        if self.affected_maps in ("local", "both"):
            maps.append(self.local_costmap)
        for costmap in maps:
            names = [
                layer.name
                for layer in costmap.layered.layers
                if layer.name.rsplit("/", 1)[-1] in self.layer_names
            ]
            costmap.clear_outside(self.reset_distance / 2.0, names)
            if self.force_updating:
                costmap.update()

    def step(self) -> tuple[bool, tuple[float, float, float] | None]:
        """Done at once; no command."""
        return True, None


class RotateRecovery:
    """A full turn in place, checked against the local costmap."""

    kind = "rotate_recovery/RotateRecovery"

    def __init__(self, node: Any, name: str, global_costmap: Any, local_costmap: Any) -> None:
        self.node, self.name = node, name
        self.local_costmap = local_costmap
        r = ParamReader(node, f"~{name}")
        self.sim_granularity = r.number("sim_granularity", 0.017, positive=True)
        self.frequency = r.number("frequency", 20.0, positive=True)
        blp = ParamReader(node, "~TrajectoryPlannerROS")
        self.acc_lim_th = blp.number("acc_lim_th", 3.2)
        self.max_rotational_vel = blp.number("max_rotational_vel", 1.0)
        self.min_rotational_vel = blp.number("min_in_place_rotational_vel", 0.4)
        self.tolerance = blp.number("yaw_goal_tolerance", 0.10)
        self.last_yaw: float | None = None
        self.turned = 0.0

    def start(self) -> None:
        self.node.get_logger().warn("Rotate recovery behavior started.")
        self.last_yaw = None
        self.turned = 0.0

    def step(self) -> tuple[bool, tuple[float, float, float] | None]:
        """One command of the turn: (done, (vx, vy, vtheta) or None)."""
        pose = self.local_costmap.robot_pose()
        if pose is None:
            return True, None
        x, y, yaw = pose
        if self.last_yaw is not None:
            self.turned += math.remainder(yaw - self.last_yaw, 2 * math.pi)
        self.last_yaw = yaw
        left = 2 * math.pi - self.turned
        if left < self.tolerance:
            return True, (0.0, 0.0, 0.0)
        cost = self._footprint_cost(x, y, yaw, left)
        if cost < 0:
            self.node.get_logger().error(
                f"Rotate recovery can't rotate in place because there is a potential collision. Cost: {cost:.2f}"
            )
            return True, (0.0, 0.0, 0.0)
        vel = math.sqrt(2 * self.acc_lim_th * left)
        vel = min(max(vel, self.min_rotational_vel), self.max_rotational_vel)
        return False, (0.0, 0.0, vel)

    def _footprint_cost(self, x: float, y: float, yaw: float, left: float) -> float:
        """-1 if the footprint outline meets a lethal or unknown cell over the rest of the turn."""
        cm = self.local_costmap.costmap()
        grid = CostGrid(cm.costs, cm.resolution, cm.origin_x, cm.origin_y)
        outline = outline_points(
            np.asarray(self.local_costmap.footprint, dtype=float), cm.resolution * 0.5
        )
        angles = yaw + np.arange(0.0, left + 1e-12, self.sim_granularity)
        c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
        px = x + c * outline[:, 0] - s * outline[:, 1]
        py = y + s * outline[:, 0] + c * outline[:, 1]
        values, inside = grid.lookup(grid.costs, np.stack([px, py], axis=-1), float(NO_INFORMATION))
        bad = ~inside | (values == LETHAL_OBSTACLE) | (values == NO_INFORMATION)
        return -1.0 if bad.any() else float(values.max())


#: recovery type -> class
RECOVERY_TYPES = {cls.kind: cls for cls in (ClearCostmapRecovery, RotateRecovery)}
