"""The ``control_msgs`` and ``controller_manager_msgs`` types of ROS 1 Noetic, as fields and constants.

What ros_control's controllers and controller manager speak: ``FollowJointTrajectory.action``
(control_msgs 1.5, expanded as actionlib's generator expands every action into its
goal/result/feedback messages, their ``Action*`` envelopes and the ``Action``),
``JointTrajectoryControllerState``, ``JointControllerState`` and ``QueryTrajectoryState``;
and controller_manager_msgs 0.19's ``ControllerState`` and its services. As in
:mod:`workbench.msgs._gazebo_definitions` each entry lists constants and fields in their
original order, which is all a ROS 1 md5sum depends on; ``tests/msgs/test_control_msgs.py``
checks the md5sums. Messages come before the types that contain them.
"""

from __future__ import annotations

#: "package/Name" -> .msg fields
MESSAGES: dict[str, str] = {
    "control_msgs/JointTolerance": """\
string name
float64 position
float64 velocity
float64 acceleration
""",
    "control_msgs/FollowJointTrajectoryGoal": """\
trajectory_msgs/JointTrajectory trajectory
control_msgs/JointTolerance[] path_tolerance
control_msgs/JointTolerance[] goal_tolerance
duration goal_time_tolerance
""",
    "control_msgs/FollowJointTrajectoryResult": """\
int32 SUCCESSFUL=0
int32 INVALID_GOAL=-1
int32 INVALID_JOINTS=-2
int32 OLD_HEADER_TIMESTAMP=-3
int32 PATH_TOLERANCE_VIOLATED=-4
int32 GOAL_TOLERANCE_VIOLATED=-5
int32 error_code
string error_string
""",
    "control_msgs/FollowJointTrajectoryFeedback": """\
Header header
string[] joint_names
trajectory_msgs/JointTrajectoryPoint desired
trajectory_msgs/JointTrajectoryPoint actual
trajectory_msgs/JointTrajectoryPoint error
""",
    "control_msgs/FollowJointTrajectoryActionGoal": """\
Header header
actionlib_msgs/GoalID goal_id
control_msgs/FollowJointTrajectoryGoal goal
""",
    "control_msgs/FollowJointTrajectoryActionResult": """\
Header header
actionlib_msgs/GoalStatus status
control_msgs/FollowJointTrajectoryResult result
""",
    "control_msgs/FollowJointTrajectoryActionFeedback": """\
Header header
actionlib_msgs/GoalStatus status
control_msgs/FollowJointTrajectoryFeedback feedback
""",
    "control_msgs/FollowJointTrajectoryAction": """\
control_msgs/FollowJointTrajectoryActionGoal action_goal
control_msgs/FollowJointTrajectoryActionResult action_result
control_msgs/FollowJointTrajectoryActionFeedback action_feedback
""",
    "control_msgs/JointTrajectoryControllerState": """\
Header header
string[] joint_names
trajectory_msgs/JointTrajectoryPoint desired
trajectory_msgs/JointTrajectoryPoint actual
trajectory_msgs/JointTrajectoryPoint error
""",
    "control_msgs/JointControllerState": """\
Header header
float64 set_point
float64 process_value
float64 process_value_dot
float64 error
float64 time_step
float64 command
float64 p
float64 i
float64 d
float64 i_clamp
bool antiwindup
""",
    "controller_manager_msgs/HardwareInterfaceResources": """\
string hardware_interface
string[] resources
""",
    "controller_manager_msgs/ControllerState": """\
string name
string state
string type
controller_manager_msgs/HardwareInterfaceResources[] claimed_resources
""",
}

#: "package/Name" -> .srv fields (request, ``---``, response)
SERVICES: dict[str, str] = {
    "control_msgs/QueryTrajectoryState": """\
time time
---
string[] name
float64[] position
float64[] velocity
float64[] acceleration
""",
    "controller_manager_msgs/ListControllers": """\
---
controller_manager_msgs/ControllerState[] controller
""",
    "controller_manager_msgs/ListControllerTypes": """\
---
string[] types
string[] base_classes
""",
    "controller_manager_msgs/LoadController": """\
string name
---
bool ok
""",
    "controller_manager_msgs/UnloadController": """\
string name
---
bool ok
""",
    "controller_manager_msgs/ReloadControllerLibraries": """\
bool force_kill
---
bool ok
""",
    "controller_manager_msgs/SwitchController": """\
int32 BEST_EFFORT=1
int32 STRICT=2
string[] start_controllers
string[] stop_controllers
int32 strictness
bool start_asap
float64 timeout
---
bool ok
""",
}
