"""ROS 1 Noetic types the typestore lacks: tf2_msgs' error, frame graph and lookup action,
the map and plan services of nav_msgs, sensor_msgs/SetCameraInfo and diagnostic_msgs' services.

As in :mod:`workbench.msgs._gazebo_definitions`, each entry lists constants and fields
(type, name, value) in their original order, which is all a ROS 1 md5sum depends on;
``tests/msgs/test_msgs_ros_differential.py`` checks every md5 against ROS's own packages.
Messages come before the types that contain them.
"""

from __future__ import annotations

#: "package/Name" -> .msg fields
MESSAGES: dict[str, str] = {
    "tf2_msgs/TF2Error": """\
uint8 NO_ERROR = 0
uint8 LOOKUP_ERROR = 1
uint8 CONNECTIVITY_ERROR = 2
uint8 EXTRAPOLATION_ERROR = 3
uint8 INVALID_ARGUMENT_ERROR = 4
uint8 TIMEOUT_ERROR = 5
uint8 TRANSFORM_ERROR = 6
uint8 error
string error_string
""",
    "tf2_msgs/LookupTransformGoal": """\
string target_frame
string source_frame
time source_time
duration timeout
time target_time
string fixed_frame
bool advanced
""",
    "tf2_msgs/LookupTransformResult": """\
geometry_msgs/TransformStamped transform
tf2_msgs/TF2Error error
""",
    "tf2_msgs/LookupTransformFeedback": """\
""",
    "tf2_msgs/LookupTransformActionGoal": """\
Header header
actionlib_msgs/GoalID goal_id
LookupTransformGoal goal
""",
    "tf2_msgs/LookupTransformActionResult": """\
Header header
actionlib_msgs/GoalStatus status
LookupTransformResult result
""",
    "tf2_msgs/LookupTransformActionFeedback": """\
Header header
actionlib_msgs/GoalStatus status
LookupTransformFeedback feedback
""",
    "tf2_msgs/LookupTransformAction": """\
LookupTransformActionGoal action_goal
LookupTransformActionResult action_result
LookupTransformActionFeedback action_feedback
""",
}

#: "package/Name" -> .srv fields (request ``---`` response)
SERVICES: dict[str, str] = {
    "diagnostic_msgs/AddDiagnostics": """\
string load_namespace
---
bool success
string message
""",
    "diagnostic_msgs/SelfTest": """\
---
string id
byte passed
DiagnosticStatus[] status
""",
    "nav_msgs/GetMap": """\
---
nav_msgs/OccupancyGrid map
""",
    "nav_msgs/GetPlan": """\
geometry_msgs/PoseStamped start
geometry_msgs/PoseStamped goal
float32 tolerance
---
nav_msgs/Path plan
""",
    "nav_msgs/LoadMap": """\
string map_url
---
uint8 RESULT_SUCCESS=0
uint8 RESULT_MAP_DOES_NOT_EXIST=1
uint8 RESULT_INVALID_MAP_DATA=2
uint8 RESULT_INVALID_MAP_METADATA=3
uint8 RESULT_UNDEFINED_FAILURE=255
nav_msgs/OccupancyGrid map
uint8 result
""",
    "nav_msgs/SetMap": """\
nav_msgs/OccupancyGrid map
geometry_msgs/PoseWithCovarianceStamped initial_pose
---
bool success
""",
    "sensor_msgs/SetCameraInfo": """\
sensor_msgs/CameraInfo camera_info
---
bool success
string status_message
""",
    "tf2_msgs/FrameGraph": """\
---
string frame_yaml
""",
}
