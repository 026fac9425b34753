"""move_base end to end on the in-process bus with a kinematic robot (tests/navigation/kinematic_robot.py).

The room is 6 x 4 m with a 0.8 x 1.8 m box between the start (0.8, 2.0) and the goal
(5.0, 2.0). Expectations are move_base's (``move_base/src/move_base.cpp``, Noetic): the
goal SUCCEEDED with "Goal reached." and a zero twist last on ``cmd_vel``; an unreachable
goal (inside the box, or off the map) ABORTED with "Failed to find a valid plan. Even after
executing recovery behaviors." after the default recoveries (conservative reset, rotate,
aggressive reset, rotate) and the log line "Aborting because a valid plan could not be
found. Even after executing all recovery behaviors"; a goal in a frame tf does not know
warned about ("Failed to transform the goal pose from ... into the map frame") and
aborted; after each the node takes the next goal.
"""

from __future__ import annotations

import math

import pytest
from move_base_setup import Navigation

from workbench.actionlib import ABORTED, SUCCEEDED


@pytest.fixture
def nav() -> Navigation:
    return Navigation()


def test_reaches_a_goal_around_the_box(nav: Navigation) -> None:
    feedback = []
    nav.client.send_goal(nav.goal(5.0, 2.0, math.pi / 2), feedback_cb=feedback.append)
    assert nav.run_until_done(90.0), nav.text()
    assert nav.client.get_state() == SUCCEEDED, nav.text()
    assert nav.client.get_goal_status_text() == "Goal reached."
    x, y, th = nav.robot.pose
    assert math.hypot(x - 5.0, y - 2.0) <= 0.15 + 0.05
    assert abs(math.remainder(th - math.pi / 2, 2 * math.pi)) <= 0.2 + 0.05
    assert nav.robot.closest > nav.robot.radius  # never touched a wall or the box
    assert nav.robot.cmds[-1] == (0.0, 0.0, 0.0)
    assert feedback and feedback[-1].base_position.header.frame_id == "map"
    # it went around the box, not through it
    assert max(abs(c[0]) for c in nav.robot.cmds) <= 0.4 + 1e-9


def test_goal_inside_an_obstacle_is_aborted_after_the_recoveries(nav: Navigation) -> None:
    recoveries = []
    nav.user.create_subscription(
        "/move_base/recovery_status", "move_base_msgs/RecoveryStatus", recoveries.append, 0
    )
    nav.client.send_goal(nav.goal(3.0, 2.0))
    assert nav.run_until_done(60.0), nav.text()
    assert nav.client.get_state() == ABORTED
    assert (
        nav.client.get_goal_status_text()
        == "Failed to find a valid plan. Even after executing recovery behaviors."
    )
    assert (
        "Aborting because a valid plan could not be found. Even after executing all recovery behaviors"
        in nav.text()
    )
    assert [r.recovery_behavior_name for r in recoveries] == [
        "conservative_reset",
        "rotate_recovery",
        "aggressive_reset",
        "rotate_recovery",
    ]
    assert (
        "Clearing both costmaps outside a square (3.00m) large centered on the robot." in nav.text()
    )
    assert (
        "Clearing both costmaps outside a square (1.84m) large centered on the robot." in nav.text()
    )
    assert "Rotate recovery behavior started." in nav.text()
    assert nav.robot.cmds[-1] == (0.0, 0.0, 0.0)
    # the node keeps running: the next goal is taken and reached
    nav.client.send_goal(nav.goal(1.5, 2.0))
    assert nav.run_until_done(40.0) and nav.client.get_state() == SUCCEEDED, nav.text()


def test_goal_off_the_map_is_aborted(nav: Navigation) -> None:
    nav.bus.params.set("/move_base/recovery_behavior_enabled", False)
    nav.move_base.p.recovery_behavior_enabled = False
    nav.client.send_goal(nav.goal(9.0, 2.0))
    assert nav.run_until_done(20.0), nav.text()
    assert nav.client.get_state() == ABORTED
    assert "The goal sent to the navfn planner is off the global costmap" in nav.text()


def test_goal_in_an_unknown_frame_is_aborted(nav: Navigation) -> None:
    nav.move_base.p.recovery_behavior_enabled = False
    nav.client.send_goal(nav.goal(4.0, 2.0, frame="nowhere"))
    assert nav.run_until_done(20.0), nav.text()
    assert nav.client.get_state() == ABORTED
    assert "Failed to transform the goal pose from nowhere into the map frame" in nav.text()
    assert (
        "The goal pose passed to this planner must be in the map frame.  It is instead in the nowhere frame."
        in nav.text()
    )


def test_invalid_quaternion_is_aborted(nav: Navigation) -> None:
    goal = nav.goal(4.0, 2.0)
    goal.target_pose.pose.orientation.w = 0.0
    nav.client.send_goal(goal)
    assert nav.run_until_done(2.0)
    assert nav.client.get_state() == ABORTED
    assert (
        nav.client.get_goal_status_text()
        == "Aborting on goal because it was sent with an invalid quaternion"
    )
    assert "Quaternion has length close to zero... discarding as navigation goal" in nav.text()


def test_simple_goal_topic_and_preemption(nav: Navigation) -> None:
    from workbench.msgs.geometry_msgs import PoseStamped

    statuses = []
    nav.user.create_subscription(
        "/move_base/result", "move_base_msgs/MoveBaseActionResult", statuses.append, 0
    )
    pub = nav.user.create_publisher("/move_base_simple/goal", PoseStamped)
    first = PoseStamped()
    first.header.frame_id = "map"
    first.pose.position.x, first.pose.position.y, first.pose.orientation.w = 5.0, 1.0, 1.0
    pub.publish(first)
    nav.clock.run(nav.robot, 3.0)
    second = PoseStamped()
    second.header.frame_id = "map"
    second.pose.position.x, second.pose.position.y, second.pose.orientation.w = 1.5, 3.0, 1.0
    pub.publish(second)
    nav.clock.run(nav.robot, 40.0, until=lambda: len(statuses) >= 2)
    assert [int(s.status.status) for s in statuses] == [2, SUCCEEDED]  # PREEMPTED, then reached
    assert math.hypot(nav.robot.pose[0] - 1.5, nav.robot.pose[1] - 3.0) <= 0.2


def test_make_plan_and_clear_costmaps(nav: Navigation) -> None:
    from workbench.msgs.geometry_msgs import PoseStamped
    from workbench.msgs.nav_msgs import GetPlan
    from workbench.msgs.std_srvs import Empty

    make_plan = nav.user.create_client("/move_base/make_plan", GetPlan)
    request = GetPlan.Request()
    request.goal = PoseStamped()
    request.goal.header.frame_id = "map"
    request.goal.pose.position.x, request.goal.pose.position.y, request.goal.pose.orientation.w = (
        5.0,
        2.0,
        1.0,
    )
    plan = make_plan.call(request).plan
    assert plan.header.frame_id == "map" and len(plan.poses) > 10
    ys = [p.pose.position.y for p in plan.poses]
    assert max(ys) > 2.9 or min(ys) < 1.1  # around the box
    request.goal.pose.position.x, request.goal.pose.position.y = 3.0, 2.0  # inside the box
    request.tolerance = 1.0
    near = make_plan.call(request).plan.poses
    assert near and (near[-1].pose.position.x, near[-1].pose.position.y) == (
        3.0,
        2.0,
    )  # goal appended
    nav.user.create_client("/move_base/clear_costmaps", Empty).call(Empty.Request())


DWA = {
    "base_local_planner": "dwa_local_planner/DWAPlannerROS",
    "DWAPlannerROS/max_vel_x": 0.4,
    "DWAPlannerROS/max_vel_trans": 0.4,
    "DWAPlannerROS/max_vel_y": 0.0,
    "DWAPlannerROS/min_vel_y": 0.0,
    "DWAPlannerROS/vy_samples": 1,
    "DWAPlannerROS/vx_samples": 10,
    "DWAPlannerROS/acc_lim_x": 1.0,
    "DWAPlannerROS/acc_lim_theta": 2.0,
    "DWAPlannerROS/xy_goal_tolerance": 0.15,
    "DWAPlannerROS/yaw_goal_tolerance": 0.2,
}


def test_dwa_local_planner_reaches_the_goal() -> None:
    nav = Navigation(**DWA)
    assert type(nav.move_base.controller).__name__ == "DWAPlannerROS"
    nav.client.send_goal(nav.goal(5.0, 2.0, math.pi / 2))
    assert nav.run_until_done(90.0), nav.text()
    assert nav.client.get_state() == SUCCEEDED
    assert "Goal reached" in [m for _, m in nav.lines]
    assert math.hypot(nav.robot.pose[0] - 5.0, nav.robot.pose[1] - 2.0) <= 0.2
    assert nav.robot.closest > nav.robot.radius


def test_dwa_takes_zero_samples_as_one_with_dwa_planners_warning() -> None:
    # turtlebot3_navigation's burger file sets vy_samples: 0; dwa_planner.cpp's reconfigure
    # samples one value then, with this warning
    nav = Navigation(**{**DWA, "DWAPlannerROS/vy_samples": 0})
    assert nav.move_base.controller.vy_samples == 1
    assert (
        "You've specified that you don't want any samples in the y dimension. We'll at least "
        "assume that you want to sample one value... so we're going to set vy_samples to 1 instead"
    ) in nav.text()


def test_robot_boxed_in_by_a_new_obstacle_is_aborted_and_stopped(nav: Navigation) -> None:
    from workbench.mapping.simulate import box_segments

    nav.client.send_goal(nav.goal(5.0, 2.0))
    nav.clock.run(nav.robot, 1.0)
    x, y, _ = nav.robot.pose
    nav.robot.add_segments(
        box_segments(x - 0.3, y - 0.3, x + 0.3, y + 0.3)
    )  # walls appear around it
    assert nav.run_until_done(120.0), nav.text()
    assert nav.client.get_state() == ABORTED
    assert (
        nav.client.get_goal_status_text()
        == "Failed to find a valid control. Even after executing recovery behaviors."
    )
    assert (
        "Aborting because a valid control could not be found. Even after executing all recovery behaviors"
        in nav.text()
    )
    assert nav.robot.cmds[-1] == (0.0, 0.0, 0.0)


def test_oscillation_timeout_aborts(nav: Navigation) -> None:
    nav.move_base.p.oscillation_timeout = 1.0
    nav.move_base.p.oscillation_distance = 50.0  # no progress counts: the timeout must fire
    nav.move_base.p.recovery_behavior_enabled = False
    nav.client.send_goal(nav.goal(5.0, 2.0))
    assert nav.run_until_done(10.0), nav.text()
    assert nav.client.get_state() == ABORTED
    assert (
        nav.client.get_goal_status_text()
        == "Robot is oscillating. Even after executing recovery behaviors."
    )
    assert "Aborting because the robot appears to be oscillating over and over" in nav.text()


def test_dwa_oscillation_flags_hold_a_flip_until_the_robot_moved() -> None:
    # base_local_planner's OscillationCostFunction: forward then backward -> only backward
    # until 0.05 m (oscillation_reset_dist) from where it flipped; a new plan clears it
    import numpy as np

    from workbench.navigation.dwa_planner_ros import OscillationFlags

    flags = OscillationFlags(0.05, 0.2)
    samples = np.array([[0.2, 0.0, 0.0], [-0.2, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    flags.update(np.zeros(3), (0.2, 0.0, 0.0), 0.1)
    assert not flags.refused(samples).any()
    flags.update(np.array([0.01, 0.0, 0.0]), (-0.2, 0.0, 0.0), 0.1)
    assert flags.refused(samples).tolist() == [True, False, False, False]
    flags.update(np.array([0.0, 0.03, 0.0]), (-0.2, 0.0, 0.0), 0.1)
    assert flags.refused(samples)[0]  # 0.03 m from the flip: still held
    flags.update(np.array([0.0, -0.06, 0.0]), (-0.2, 0.0, 0.0), 0.1)
    assert not flags.refused(samples).any()  # moved 0.06 m: free again
    # turning left then right while standing: only right until it turned 0.2 rad
    flags.update(np.zeros(3), (0.0, 0.0, 1.0), 0.1)
    flags.update(np.zeros(3), (0.0, 0.0, -1.0), 0.1)
    assert flags.refused(samples).tolist() == [False, False, True, False]
    flags.reset()
    assert not flags.refused(samples).any()
