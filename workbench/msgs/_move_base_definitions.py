"""The ``move_base_msgs`` types of ROS 1 Noetic (move_base_msgs 1.14), as fields and constants.

``MoveBase.action`` (goal ``target_pose``, empty result, feedback ``base_position``)
expands, as actionlib's generator expands every action, into the goal/result/feedback
messages, their ``Action*`` envelopes and ``MoveBaseAction``; ``RecoveryStatus`` is the
package's own message. As in :mod:`workbench.msgs._gazebo_definitions` each entry lists
constants and fields in their original order, which is all a ROS 1 md5sum depends on;
``tests/msgs/test_move_base_msgs.py`` checks the md5sums. Messages come before the types
that contain them.
"""

from __future__ import annotations

#: "move_base_msgs/Name" -> .msg fields
MESSAGES: dict[str, str] = {
    "move_base_msgs/MoveBaseGoal": """\
geometry_msgs/PoseStamped target_pose
""",
    "move_base_msgs/MoveBaseResult": """\
""",
    "move_base_msgs/MoveBaseFeedback": """\
geometry_msgs/PoseStamped base_position
""",
    "move_base_msgs/MoveBaseActionGoal": """\
Header header
actionlib_msgs/GoalID goal_id
MoveBaseGoal goal
""",
    "move_base_msgs/MoveBaseActionResult": """\
Header header
actionlib_msgs/GoalStatus status
MoveBaseResult result
""",
    "move_base_msgs/MoveBaseActionFeedback": """\
Header header
actionlib_msgs/GoalStatus status
MoveBaseFeedback feedback
""",
    "move_base_msgs/MoveBaseAction": """\
MoveBaseActionGoal action_goal
MoveBaseActionResult action_result
MoveBaseActionFeedback action_feedback
""",
    "move_base_msgs/RecoveryStatus": """\
geometry_msgs/PoseStamped pose_stamped
uint16 current_recovery_number
uint16 total_number_of_recoveries
string recovery_behavior_name
""",
}
