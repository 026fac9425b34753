"""control_msgs and controller_manager_msgs: ROS's md5sums and a wire round trip.

The expected md5sums are the ones genmsg wrote into generated code (not computed here):
rosserial's ``ros_lib`` headers for the Noetic definitions return them from ``getMD5()``
(``control_msgs/JointTolerance.h``, ``FollowJointTrajectoryGoal.h``,
``FollowJointTrajectoryActionGoal.h``, ``JointControllerState.h`` with ``i_clamp`` and
``antiwindup``, and ``controller_manager_msgs/ControllerState.h`` with
``claimed_resources``). ``FollowJointTrajectoryAction``'s is the one actionlib clients
check when they connect (``bc4f9b74...``).
"""

from __future__ import annotations

import pytest

from workbench.msgs import deserialize, md5sum, serialize

MD5 = {
    "control_msgs/JointTolerance": "f544fe9c16cf04547e135dd6063ff5be",
    "control_msgs/FollowJointTrajectoryGoal": "69636787b6ecbde4d61d711979bc7ecb",
    "control_msgs/FollowJointTrajectoryActionGoal": "cff5c1d533bf2f82dd0138d57f4304bb",
    "control_msgs/FollowJointTrajectoryAction": "bc4f9b743838566551c0390c65f1a248",
    "control_msgs/JointControllerState": "987ad85e4756f3aef7f1e5e7fe0595d1",
    "controller_manager_msgs/ControllerState": "aeb6b261d97793ab74099a3740245272",
}


@pytest.mark.parametrize("name", sorted(MD5))
def test_md5_equals_ros(name: str) -> None:
    assert md5sum(name) == MD5[name]


def test_switch_controller_request_has_the_strictness_constants() -> None:
    from workbench.msgs.controller_manager_msgs import SwitchController

    request = SwitchController.Request(start_controllers=["arm"], strictness=2)
    assert (SwitchController.Request.BEST_EFFORT, SwitchController.Request.STRICT) == (1, 2)
    back = deserialize(serialize(request), "controller_manager_msgs/SwitchControllerRequest")
    assert back.start_controllers == ["arm"] and back.strictness == 2


def test_action_goal_round_trip() -> None:
    from workbench.msgs.control_msgs import FollowJointTrajectoryActionGoal, JointTolerance
    from workbench.msgs.trajectory_msgs import JointTrajectoryPoint

    goal = FollowJointTrajectoryActionGoal()
    goal.goal.trajectory.joint_names = ["elbow_joint"]
    point = JointTrajectoryPoint(positions=[0.5])
    point.time_from_start.secs = 2
    goal.goal.trajectory.points = [point]
    goal.goal.goal_tolerance = [JointTolerance(name="elbow_joint", position=0.01)]
    back = deserialize(serialize(goal), "control_msgs/FollowJointTrajectoryActionGoal")
    assert back == goal
