"""move_base on a stepped in-process bus with the kinematic robot: parameters and helpers."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from kinematic_robot import KinematicRobot, SimClock

from workbench.actionlib import SimpleActionClient
from workbench.bus import Bus, Node
from workbench.navigation.move_base import MoveBase
from workbench.tf import Buffer, TransformListener

LAYERS_GLOBAL = [
    {"name": "static_layer", "type": "costmap_2d::StaticLayer"},
    {"name": "inflation_layer", "type": "costmap_2d::InflationLayer"},
]
LAYERS_LOCAL = [
    {"name": "obstacles", "type": "costmap_2d::ObstacleLayer"},
    {"name": "inflation_layer", "type": "costmap_2d::InflationLayer"},
]

PARAMS: dict[str, Any] = {
    "controller_frequency": 10.0,
    "planner_patience": 1.0,
    "controller_patience": 3.0,
    "global_costmap/global_frame": "map",
    "global_costmap/robot_base_frame": "base_footprint",
    "global_costmap/robot_radius": 0.15,
    "global_costmap/update_frequency": 5.0,
    "global_costmap/plugins": LAYERS_GLOBAL,
    "global_costmap/inflation_layer/inflation_radius": 0.45,
    "global_costmap/inflation_layer/cost_scaling_factor": 6.0,
    "local_costmap/global_frame": "odom",
    "local_costmap/robot_base_frame": "base_footprint",
    "local_costmap/robot_radius": 0.15,
    "local_costmap/update_frequency": 5.0,
    "local_costmap/rolling_window": True,
    "local_costmap/width": 3,
    "local_costmap/height": 3,
    "local_costmap/resolution": 0.05,
    "local_costmap/plugins": LAYERS_LOCAL,
    "local_costmap/obstacles/observation_sources": "scan",
    "local_costmap/obstacles/obstacle_range": 2.5,
    "local_costmap/obstacles/raytrace_range": 3.0,
    "local_costmap/obstacles/scan": {
        "data_type": "LaserScan",
        "topic": "/scan",
        "sensor_frame": "base_scan",
        "marking": True,
        "clearing": True,
    },
    "local_costmap/inflation_layer/inflation_radius": 0.45,
    "local_costmap/inflation_layer/cost_scaling_factor": 6.0,
    "TrajectoryPlannerROS/max_vel_x": 0.4,
    "TrajectoryPlannerROS/min_vel_x": 0.1,
    "TrajectoryPlannerROS/max_vel_theta": 1.0,
    "TrajectoryPlannerROS/min_vel_theta": -1.0,
    "TrajectoryPlannerROS/min_in_place_vel_theta": 0.4,
    "TrajectoryPlannerROS/acc_lim_x": 1.0,
    "TrajectoryPlannerROS/acc_lim_theta": 2.0,
    "TrajectoryPlannerROS/holonomic_robot": False,
    "TrajectoryPlannerROS/sim_time": 1.5,
    "TrajectoryPlannerROS/vx_samples": 6,
    "TrajectoryPlannerROS/vtheta_samples": 20,
    "TrajectoryPlannerROS/meter_scoring": True,
    "TrajectoryPlannerROS/path_distance_bias": 32.0,
    "TrajectoryPlannerROS/goal_distance_bias": 24.0,
    "TrajectoryPlannerROS/occdist_scale": 0.01,
    "TrajectoryPlannerROS/xy_goal_tolerance": 0.15,
    "TrajectoryPlannerROS/yaw_goal_tolerance": 0.2,
}


@dataclass
class GridSnapshot:
    """What ``CostmapROS.costmap()`` returns, as far as the planners read it (4 x 4 m at 5 cm)."""

    costs: np.ndarray
    resolution: float = 0.05
    origin_x: float = -2.0
    origin_y: float = -2.0


def param_node(**params: Any) -> Node:
    """A ``/move_base`` node on a fresh stepped bus with ``params`` under ``/move_base``."""
    bus = Bus(threaded=False)
    for key, value in params.items():
        bus.params.set(f"/move_base/{key}", value)
    return Node("move_base", bus=bus)


class Navigation:
    """A stepped bus with the robot, move_base and an action client, plus the log lines."""

    def __init__(self, start=(0.8, 2.0, 0.0), **overrides: Any) -> None:
        self.bus = Bus(threaded=False)
        self.clock = SimClock(self.bus)
        for key, value in {**PARAMS, **overrides}.items():
            self.bus.params.set(f"/move_base/{key}", value)
        self.robot = KinematicRobot(self.bus, start)
        self.node = Node("move_base", bus=self.bus)
        self.lines: list[tuple[str, str]] = []
        self.node.create_subscription("/rosout", "rosgraph_msgs/Log", self._on_log, 0)
        buffer = Buffer(cache_time=10.0)
        TransformListener(buffer, self.node)
        self.clock.drain()
        self.move_base = MoveBase(self.node, buffer)
        self.user = Node("user", bus=self.bus)
        self.client = SimpleActionClient("move_base", "move_base_msgs/MoveBaseAction", self.user)
        self.clock.run(self.robot, 0.5)

    def _on_log(self, msg: Any) -> None:
        if msg.name == "/move_base":
            self.lines.append((int(msg.level), str(msg.msg)))

    def text(self) -> str:
        return "\n".join(m for _, m in self.lines)

    def goal(self, x: float, y: float, yaw: float = 0.0, frame: str = "map"):
        import math

        from workbench.msgs.move_base_msgs import MoveBaseGoal

        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = frame
        goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
        goal.target_pose.pose.orientation.z = math.sin(yaw / 2)
        goal.target_pose.pose.orientation.w = math.cos(yaw / 2)
        return goal

    def run_until_done(self, seconds: float) -> bool:
        from workbench.actionlib.client import SIMPLE_DONE

        return self.clock.run(
            self.robot, seconds, until=lambda: self.client.simple_state == SIMPLE_DONE
        )
