"""Message and service definitions the labs need that the Noetic typestore lacks.

The text of each entry is the package's own ``.msg``/``.srv`` file, verbatim;
the ``gazebo_msgs``, ``move_base_msgs``, ``control_msgs`` and ``controller_manager_msgs``
types, written as fields and constants only, are added from
:mod:`workbench.msgs._gazebo_definitions`, :mod:`workbench.msgs._move_base_definitions`
and :mod:`workbench.msgs._control_definitions`.
"""

from __future__ import annotations

from workbench.msgs import (
    _control_definitions,
    _gazebo_definitions,
    _move_base_definitions,
    _noetic_definitions,
)

#: "package/Name" -> .msg text
MESSAGES: dict[str, str] = {
    "rosserial_msgs/Log": """\

#ROS Logging Levels
uint8 ROSDEBUG=0
uint8 INFO=1
uint8 WARN=2
uint8 ERROR=3
uint8 FATAL=4

uint8 level
string msg
""",
    "rosserial_msgs/TopicInfo": """\
# special topic_ids
uint16 ID_PUBLISHER=0
uint16 ID_SUBSCRIBER=1
uint16 ID_SERVICE_SERVER=2
uint16 ID_SERVICE_CLIENT=4
uint16 ID_PARAMETER_REQUEST=6
uint16 ID_LOG=7
uint16 ID_TIME=10
uint16 ID_TX_STOP=11

# The endpoint ID for this topic
uint16 topic_id

string topic_name
string message_type

# MD5 checksum for this message type
string md5sum

# size of the buffer message must fit in
int32 buffer_size
""",
    "tf/tfMessage": """\
geometry_msgs/TransformStamped[] transforms
""",
    "tf2_msgs/TFMessage": """\
geometry_msgs/TransformStamped[] transforms
""",
    "turtlesim/Color": """\
uint8 r
uint8 g
uint8 b
""",
    "turtlesim/Pose": """\
float32 x
float32 y
float32 theta

float32 linear_velocity
float32 angular_velocity
""",
}

#: "package/Name" -> .srv text (request, ``---``, response)
SERVICES: dict[str, str] = {
    "beginner_tutorials/AddTwoInts": """\
int64 a
int64 b
---
int64 sum
""",
    "rospy_tutorials/AddTwoInts": """\
int64 a
int64 b
---
int64 sum
""",
    "rosserial_msgs/RequestParam": """\
string name

---

int32[]   ints
float32[] floats
string[]  strings
""",
    "std_srvs/Empty": """\
---
""",
    "std_srvs/SetBool": """\
bool data # e.g. for hardware enabling / disabling
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
""",
    "std_srvs/Trigger": """\
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
""",
    "turtlesim/Kill": """\
string name
---
""",
    "turtlesim/SetPen": """\
uint8 r
uint8 g
uint8 b
uint8 width
uint8 off
---
""",
    "turtlesim/Spawn": """\
float32 x
float32 y
float32 theta
string name # Optional.  A unique name will be created and returned if this is empty
---
string name
""",
    "turtlesim/TeleportAbsolute": """\
float32 x
float32 y
float32 theta
---
""",
    "turtlesim/TeleportRelative": """\
float32 linear
float32 angular
---
""",
}

MESSAGES.update(_gazebo_definitions.MESSAGES)
SERVICES.update(_gazebo_definitions.SERVICES)
MESSAGES.update(_noetic_definitions.MESSAGES)
MESSAGES.update(_move_base_definitions.MESSAGES)
SERVICES.update(_noetic_definitions.SERVICES)
MESSAGES.update(_control_definitions.MESSAGES)
SERVICES.update(_control_definitions.SERVICES)
