"""move_base_msgs: ROS's md5sums and a wire round trip of the action's envelopes.

The expected md5sums are the ones genmsg wrote into ROS's generated code (not computed
here): Debian's ``python3-move-base-msgs`` 1.14.1-2, the Noetic package, holds them as
``_md5sum`` in ``move_base_msgs/msg/_<Name>.py``; MoveBaseActionGoal's also appears in
rosserial's generated ``ros_lib/move_base_msgs/MoveBaseActionGoal.h`` (``getMD5()``).
``MoveBaseResult`` is empty, so its md5 is the md5 of the empty string.
"""

from __future__ import annotations

import hashlib

import pytest

from workbench.msgs import deserialize, md5sum, serialize
from workbench.msgs.move_base_msgs import MoveBaseActionFeedback, MoveBaseActionGoal

MD5 = {
    "MoveBaseAction": "70b6aca7c7f7746d8d1609ad94c80bb8",
    "MoveBaseActionGoal": "660d6895a1b9a16dce51fbdd9a64a56b",
    "MoveBaseActionFeedback": "7d1870ff6e0decea702b943b5af0b42e",
    "MoveBaseActionResult": "1eb06eeff08fa7ea874431638cb52332",
    "MoveBaseGoal": "257d089627d7eb7136c24d3593d05a16",
    "MoveBaseFeedback": "3fb824c456a757373a226f6d08071bf0",
    "MoveBaseResult": "d41d8cd98f00b204e9800998ecf8427e",
    "RecoveryStatus": "a2488e0805e1529a31044786ee1a2623",
}


@pytest.mark.parametrize("name", sorted(MD5))
def test_md5_equals_ros(name: str) -> None:
    assert md5sum(f"move_base_msgs/{name}") == MD5[name]


def test_empty_result_hashes_the_empty_text() -> None:
    assert MD5["MoveBaseResult"] == hashlib.md5(b"").hexdigest()


def test_action_goal_and_feedback_round_trip() -> None:
    goal = MoveBaseActionGoal()
    goal.header.frame_id = "map"
    goal.goal_id.id = "/rviz-1-12.500000000"
    goal.goal.target_pose.header.frame_id = "map"
    goal.goal.target_pose.pose.position.x = 1.5
    goal.goal.target_pose.pose.orientation.w = 1.0
    back = deserialize(serialize(goal), "move_base_msgs/MoveBaseActionGoal")
    assert back == goal
    feedback = MoveBaseActionFeedback()
    feedback.status.status = 1
    feedback.feedback.base_position.pose.position.y = -0.25
    back_fb = deserialize(serialize(feedback), "move_base_msgs/MoveBaseActionFeedback")
    assert back_fb.feedback.base_position.pose.position.y == -0.25
    assert back_fb.status.status == 1
