"""TrajectoryPlannerROS's goal approach: stop within the acceleration limits, then turn in place.

From ``trajectory_planner_ros.cpp`` (Noetic): within ``xy_goal_tolerance`` a moving base is
slowed by ``acc_lim * sim_period`` per cycle (``stopWithAccLimits``); a stopped one turns
towards the goal's heading at no less than ``min_in_place_vel_theta``, no faster than it
can stop (``sqrt(2 acc_lim_theta |error|)``) (``rotateToGoal``); within
``yaw_goal_tolerance`` it commands zero and ``isGoalReached`` holds once odometry says stopped.
Far from the goal the plan is followed forwards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pytest
from move_base_setup import GridSnapshot, param_node

from workbench.msgs.geometry_msgs import PoseStamped
from workbench.msgs.nav_msgs import Odometry
from workbench.navigation.local_planner_ros import TrajectoryPlannerROS


@dataclass
class LocalCostmap:
    pose: tuple = (0.0, 0.0, 0.0)
    global_frame: str = "odom"
    footprint: list = field(
        default_factory=lambda: [(0.15, 0.15), (-0.15, 0.15), (-0.15, -0.15), (0.15, -0.15)]
    )

    def robot_pose(self):
        return self.pose

    def costmap(self):
        return GridSnapshot(np.zeros((80, 80), dtype=np.uint8))


def plan(points, yaw: float = 0.0) -> list[PoseStamped]:
    out = []
    for x, y in points:
        p = PoseStamped()
        p.header.frame_id = "odom"
        p.pose.position.x, p.pose.position.y = x, y
        p.pose.orientation.z, p.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        out.append(p)
    return out


def planner(costmap: LocalCostmap) -> tuple[TrajectoryPlannerROS, object]:
    node = param_node(
        controller_frequency=10.0,
        **{
            "TrajectoryPlannerROS/acc_lim_x": 1.0,
            "TrajectoryPlannerROS/acc_lim_theta": 2.0,
            "TrajectoryPlannerROS/min_in_place_vel_theta": 0.4,
            "TrajectoryPlannerROS/holonomic_robot": False,
        },
    )
    tp = TrajectoryPlannerROS(node, "TrajectoryPlannerROS", costmap, tf_buffer=None)
    odom = node.create_publisher("/odom", Odometry)
    return tp, odom


def set_velocity(tp, odom, vx: float, w: float) -> None:
    msg = Odometry()
    msg.twist.twist.linear.x, msg.twist.twist.angular.z = vx, w
    odom.publish(msg)
    while tp.node.bus.spin_once(0.0):
        pass


def test_follows_the_plan_forwards() -> None:
    cm = LocalCostmap()
    tp, odom = planner(cm)
    tp.set_plan(plan([(x, 0.0) for x in np.arange(0.0, 1.5, 0.05)]))
    set_velocity(tp, odom, 0.3, 0.0)
    ok, (vx, vy, w) = tp.compute_velocity_commands()
    assert ok and vx > 0.1 and abs(w) < 0.2 and vy == 0.0


def test_stops_then_turns_to_the_goal_heading() -> None:
    cm = LocalCostmap(pose=(1.0, 0.0, 0.0))
    tp, odom = planner(cm)
    tp.set_plan(plan([(0.0, 0.0), (0.5, 0.0), (1.02, 0.0)], yaw=math.pi / 2))
    set_velocity(tp, odom, 0.3, 0.0)
    ok, (vx, _, w) = tp.compute_velocity_commands()
    assert ok and vx == pytest.approx(0.3 - 1.0 * 0.1) and w == 0.0  # slowing down at acc_lim_x
    set_velocity(tp, odom, 0.0, 0.0)
    ok, (vx, _, w) = tp.compute_velocity_commands()
    assert (
        ok and vx == 0.0 and w == pytest.approx(0.2)
    )  # the acceleration limit from rest: 2.0 * 0.1
    set_velocity(tp, odom, 0.0, 1.0)
    ok, (_, _, w) = tp.compute_velocity_commands()
    assert w == pytest.approx(1.0)  # max_vel_theta
    cm.pose = (1.0, 0.0, math.pi / 2 - 0.1)
    ok, (_, _, w) = tp.compute_velocity_commands()
    assert w == pytest.approx(min(0.8, math.sqrt(2 * 2.0 * 0.1)))  # slow enough to stop in time
    assert not tp.is_goal_reached()
    cm.pose = (1.0, 0.0, math.pi / 2 - 0.01)
    ok, cmd = tp.compute_velocity_commands()
    assert ok and cmd == (0.0, 0.0, 0.0)
    set_velocity(tp, odom, 0.0, 0.0)
    assert tp.is_goal_reached()


def test_turns_the_short_way() -> None:
    cm = LocalCostmap(pose=(1.0, 0.0, 0.0))
    tp, odom = planner(cm)
    tp.set_plan(plan([(0.0, 0.0), (1.0, 0.0)], yaw=-2.0))
    set_velocity(tp, odom, 0.0, -0.5)
    ok, (_, _, w) = tp.compute_velocity_commands()
    assert ok and w == pytest.approx(-0.3)  # still turning: slowed first (0.5 - 2.0 * 0.1)
    set_velocity(tp, odom, 0.0, 0.0)
    ok, (_, _, w) = tp.compute_velocity_commands()
    assert ok and w == pytest.approx(-0.2)  # then clockwise, the short way to -2 rad
