"""base_local_planner's ``TrajectoryPlannerROS``: the local planner move_base drives.

Owned by a host node (move_base) with a local costmap (a ``CostmapROS``) and a tf buffer;
reads ``~<name>/...`` (see :mod:`workbench.navigation.local_planner_params`), follows
``odom`` (``nav_msgs/Odometry``) for the base's velocity and publishes ``~<name>/global_plan``
and ``~<name>/local_plan`` (``nav_msgs/Path``). Each :meth:`compute_velocity_commands` does
what ``trajectory_planner_ros.cpp`` (Noetic) does: transform and prune the plan into the
local costmap's frame; when within ``xy_goal_tolerance`` of the goal (or latched there
with ``latch_xy_goal_tolerance``) stop within the acceleration limits and then rotate in
place towards the goal's heading (at least ``min_in_place_vel_theta``, slow enough to stop
in time, the rotation checked against the footprint); otherwise score the trajectories
(:mod:`workbench.navigation.trajectory_rollout`) over path and goal distance maps
(:mod:`workbench.navigation.trajectory_map_grid`) and drive the best.
"""

from __future__ import annotations

import math
import threading
from typing import Any

import numpy as np

from workbench.navigation import local_planner_plan as lp
from workbench.navigation.local_planner_params import trajectory_planner_params
from workbench.navigation.trajectory_map_grid import distance_maps
from workbench.navigation.trajectory_rollout import CostGrid, RolloutParams, TrajectoryPlanner


def heard(pub: Any) -> bool:
    """Whether anyone subscribes ``pub``'s topic: this process's subscriptions first (cheap),
    the whole graph only when the bus reaches other processes."""
    bus = pub.node.bus
    if bus.local.subscribers_of(pub.topic):
        return True
    return bool(bus.is_connected and pub.get_num_connections() > 0)


def _sign(v: float) -> float:
    return -1.0 if v < 0 else 1.0


class LocalPlannerHost:
    """What the ROS wrappers share: plan, odometry, frames, plan publishing."""

    name = "LocalPlanner"

    def __init__(self, node: Any, name: str, costmap_ros: Any, tf_buffer: Any) -> None:
        self.node = node
        self.name = name
        self.costmap_ros = costmap_ros
        self.tf = tf_buffer
        self.lock = threading.Lock()
        self.vel = np.zeros(3)
        self.plan = np.zeros((0, 3))
        self.plan_frame = ""
        self.global_pub = node.create_publisher(f"~{name}/global_plan", "nav_msgs/Path", 1)
        self.local_pub = node.create_publisher(f"~{name}/local_plan", "nav_msgs/Path", 1)
        node.create_subscription("odom", "nav_msgs/Odometry", self._on_odom, 1)

    def _on_odom(self, msg: Any) -> None:
        t = msg.twist.twist
        with self.lock:
            self.vel = np.array([t.linear.x, t.linear.y, t.angular.z], dtype=float)

    def odom_velocity(self) -> np.ndarray:
        with self.lock:
            return self.vel.copy()

    def set_plan(self, plan: list[Any]) -> bool:
        """Take a new global plan (PoseStamped list); clears the goal-tolerance latch."""
        self.plan = lp.poses_array(plan)
        self.plan_frame = plan[0].header.frame_id if plan else ""
        self.on_new_plan()
        return True

    def on_new_plan(self) -> None:
        """Hook for the wrappers (reset latches)."""

    def local_plan(self, pose: np.ndarray, grid: Any) -> tuple[np.ndarray, np.ndarray] | None:
        """(the plan's window in the local frame, the goal pose there), pruning passed points."""
        frame = self.costmap_ros.global_frame
        try:
            tf2d = lp.planar_transform(self.tf, frame, self.plan_frame or frame)
        except Exception as error:  # tf's exceptions: the controller cannot follow this plan
            self.node.get_logger().warn(
                f"Could not transform the global plan to the frame of the controller ({error})"
            )
            return None
        local = lp.apply(tf2d, self.plan)
        if self.prune_plan:
            dropped = lp.prune(local, (pose[0], pose[1]))
            if dropped < len(local):
                self.plan, local = self.plan[dropped:], local[dropped:]
        threshold = max(grid.costs.shape) * grid.resolution / 2.0
        window = lp.local_window(local, (pose[0], pose[1]), threshold)
        if len(window) == 0 or len(local) == 0:
            return None
        return window, local[-1]

    prune_plan = True

    def publish_path(self, pub: Any, poses: np.ndarray) -> None:
        """Publish ``(n, 3)`` poses as a nav_msgs/Path in the local costmap's frame (if heard)."""
        if not heard(pub):
            return
        from workbench.msgs.geometry_msgs import PoseStamped
        from workbench.msgs.nav_msgs import Path

        now = self.node.now()
        frame = self.costmap_ros.global_frame
        path = Path()
        path.header.frame_id = frame
        path.header.stamp = now
        out = []
        for x, y, th in poses:
            p = PoseStamped()
            p.header.frame_id = frame
            p.header.stamp = now
            p.pose.position.x, p.pose.position.y = float(x), float(y)
            p.pose.orientation = lp.quaternion_msg(float(th))
            out.append(p)
        path.poses = out
        pub.publish(path)


class TrajectoryPlannerROS(LocalPlannerHost):
    """``base_local_planner/TrajectoryPlannerROS``.

    Args:
        node: The host node (its private namespace holds ``<name>/...``).
        name: ``TrajectoryPlannerROS``.
        costmap_ros: The local costmap (``CostmapROS``).
        tf_buffer: A tf buffer filled from the bus.

    Raises:
        PlannerParameterError: A parameter of the wrong type (one line naming it).
    """

    def __init__(self, node: Any, name: str, costmap_ros: Any, tf_buffer: Any) -> None:
        params, host = self.read_params(node, name)
        super().__init__(node, name, costmap_ros, tf_buffer)
        self.params: RolloutParams = params
        self.xy_tolerance = host["xy_goal_tolerance"]
        self.yaw_tolerance = host["yaw_goal_tolerance"]
        self.latch_xy = host["latch_xy_goal_tolerance"]
        self.meter_scoring = host["meter_scoring"]
        self.prune_plan = host["prune_plan"]
        self.planner = TrajectoryPlanner(params, np.asarray(costmap_ros.footprint, dtype=float))
        self.xy_latched = False
        self.rotating_to_goal = False
        self.announce(node, host)

    def read_params(self, node: Any, name: str) -> tuple[RolloutParams, dict[str, Any]]:
        """The planner's parameters under ``~<name>``."""
        return trajectory_planner_params(node, f"~{name}")

    def announce(self, node: Any, host: dict[str, Any]) -> None:
        """TrajectoryPlannerROS's start-up lines (control period, ``meter_scoring``)."""
        log = node.get_logger()
        log.info(f"Sim period is set to {self.params.sim_period:.2f}")
        if not host["meter_scoring_set"]:
            log.warn(
                "Trajectory Rollout planner initialized with param meter_scoring not set. Set it to true to "
                "make your settins robust against changes of costmap resolution."
            )
        elif not self.meter_scoring:
            log.warn(
                "Trajectory Rollout planner initialized with param meter_scoring set to false. Set it to true "
                "to make your settins robust against changes of costmap resolution."
            )

    def on_new_plan(self) -> None:
        self.xy_latched = False

    def scales(self, resolution: float) -> tuple[float, float, float]:
        p = self.params
        k = resolution if self.meter_scoring else 1.0
        return (p.path_distance_bias * k, p.goal_distance_bias * k, p.occdist_scale * k)

    def _snapshot(self) -> tuple[CostGrid, np.ndarray] | None:
        pose = self.costmap_ros.robot_pose()
        if pose is None:
            return None
        cm = self.costmap_ros.costmap()
        return CostGrid(cm.costs, cm.resolution, cm.origin_x, cm.origin_y), np.asarray(
            pose, dtype=float
        )

    def _maps(self, grid: CostGrid, pose: np.ndarray, window: np.ndarray) -> Any:
        inside = lp.footprint_cells(
            grid.costs.shape,
            grid.resolution,
            (grid.origin_x, grid.origin_y),
            pose,
            self.planner.footprint,
        )
        return distance_maps(
            grid.costs, grid.resolution, (grid.origin_x, grid.origin_y), window[:, :2], inside
        )

    def compute_velocity_commands(self) -> tuple[bool, tuple[float, float, float]]:
        """(success, (vx, vy, vtheta)) for this control cycle; failure commands zero."""
        snap = self._snapshot()
        if snap is None or len(self.plan) == 0:
            return False, (0.0, 0.0, 0.0)
        grid, pose = snap
        found = self.local_plan(pose, grid)
        if found is None:
            return False, (0.0, 0.0, 0.0)
        window, goal = found
        vel = self.odom_velocity()
        scales = self.scales(grid.resolution)
        if math.hypot(goal[0] - pose[0], goal[1] - pose[1]) <= self.xy_tolerance or self.xy_latched:
            if self.latch_xy:
                self.xy_latched = True
            self.publish_path(self.global_pub, window)
            self.publish_path(self.local_pub, window[:0])
            if abs(lp.angle_diff(pose[2], goal[2])) <= self.yaw_tolerance:
                self.rotating_to_goal = False
                self.xy_latched = False
                return True, (0.0, 0.0, 0.0)
            maps = self._maps(grid, pose, window)
            if not self.rotating_to_goal and not lp.stopped(vel):
                return self._stop_with_acc_limits(grid, maps, pose, vel, scales)
            self.rotating_to_goal = True
            return self._rotate_to_goal(grid, maps, pose, vel, goal[2], scales)
        maps = self._maps(grid, pose, window)
        self.publish_path(self.global_pub, window)
        return self.drive(grid, maps, pose, vel, goal, scales)

    def drive(
        self,
        grid: CostGrid,
        maps: Any,
        pose: np.ndarray,
        vel: np.ndarray,
        goal: np.ndarray,
        scales: tuple,
    ) -> tuple[bool, tuple[float, float, float]]:
        """The best trajectory's command (``findBestPath``); failure when none is legal."""
        dist = math.hypot(goal[0] - pose[0], goal[1] - pose[1])
        choice = self.planner.choose(grid, maps, pose, vel, scales, goal_dist=dist)
        if choice.cost < 0:
            self.publish_path(self.local_pub, choice.poses[:0])
            return False, (0.0, 0.0, 0.0)
        self.publish_path(self.local_pub, choice.poses)
        return True, (choice.vx, choice.vy, choice.vtheta)

    def _legal(
        self, grid: CostGrid, maps: Any, pose: np.ndarray, vel: np.ndarray, v: tuple, scales: tuple
    ) -> bool:
        return bool(self.planner.score(grid, maps, pose, vel, np.array([v]), scales).cost[0] >= 0)

    def _stop_with_acc_limits(
        self, grid, maps, pose, vel, scales
    ) -> tuple[bool, tuple[float, float, float]]:
        p = self.params
        vx = _sign(vel[0]) * max(0.0, abs(vel[0]) - p.acc_lim_x * p.sim_period)
        vy = _sign(vel[1]) * max(0.0, abs(vel[1]) - p.acc_lim_y * p.sim_period)
        vth = _sign(vel[2]) * max(0.0, abs(vel[2]) - p.acc_lim_theta * p.sim_period)
        if self._legal(grid, maps, pose, vel, (vx, vy, vth), scales):
            return True, (vx, vy, vth)
        return False, (0.0, 0.0, 0.0)

    def _rotate_to_goal(
        self, grid, maps, pose, vel, goal_th, scales
    ) -> tuple[bool, tuple[float, float, float]]:
        p = self.params
        diff = lp.angle_diff(pose[2], goal_th)
        if diff > 0:
            v = min(p.max_vel_theta, max(p.min_in_place_vel_theta, diff))
        else:
            v = max(p.min_vel_theta, min(-p.min_in_place_vel_theta, diff))
        fastest = abs(vel[2]) + p.acc_lim_theta * p.sim_period
        slowest = abs(vel[2]) - p.acc_lim_theta * p.sim_period
        v = _sign(v) * min(max(abs(v), slowest), fastest)
        v = _sign(v) * min(math.sqrt(2 * p.acc_lim_theta * abs(diff)), abs(v))
        if self._legal(grid, maps, pose, vel, (0.0, 0.0, v), scales):
            return True, (0.0, 0.0, v)
        return False, (0.0, 0.0, 0.0)

    def is_goal_reached(self) -> bool:
        """Within both tolerances of the plan's goal and stopped."""
        pose = self.costmap_ros.robot_pose()
        if pose is None or len(self.plan) == 0:
            return False
        frame = self.costmap_ros.global_frame
        try:
            tf2d = lp.planar_transform(self.tf, frame, self.plan_frame or frame)
        except Exception:  # tf's exceptions: not reached as far as we can tell
            return False
        goal = lp.apply(tf2d, self.plan[-1:])[0]
        return (
            math.hypot(goal[0] - pose[0], goal[1] - pose[1]) <= self.xy_tolerance
            and abs(lp.angle_diff(pose[2], goal[2])) <= self.yaw_tolerance
            and lp.stopped(self.odom_velocity())
        )
