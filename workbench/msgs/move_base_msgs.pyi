"""Types of the move_base_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Mapping
from typing import Any

from workbench.msgs import actionlib_msgs, geometry_msgs, std_msgs
from workbench.msgs import move_base_msgs as msg
from workbench.msgs import move_base_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "MoveBaseAction",
    "MoveBaseActionFeedback",
    "MoveBaseActionGoal",
    "MoveBaseActionResult",
    "MoveBaseFeedback",
    "MoveBaseGoal",
    "MoveBaseResult",
    "RecoveryStatus",
    "msg",
    "srv",
]

class MoveBaseAction(Message):
    """``move_base_msgs/MoveBaseAction``."""

    @property
    def action_goal(self) -> MoveBaseActionGoal: ...
    @action_goal.setter
    def action_goal(self, value: MoveBaseActionGoal | Mapping[str, Any]) -> None: ...
    @property
    def action_result(self) -> MoveBaseActionResult: ...
    @action_result.setter
    def action_result(self, value: MoveBaseActionResult | Mapping[str, Any]) -> None: ...
    @property
    def action_feedback(self) -> MoveBaseActionFeedback: ...
    @action_feedback.setter
    def action_feedback(self, value: MoveBaseActionFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        action_goal: MoveBaseActionGoal | Mapping[str, Any] = ...,
        action_result: MoveBaseActionResult | Mapping[str, Any] = ...,
        action_feedback: MoveBaseActionFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseActionFeedback(Message):
    """``move_base_msgs/MoveBaseActionFeedback``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def feedback(self) -> MoveBaseFeedback: ...
    @feedback.setter
    def feedback(self, value: MoveBaseFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        feedback: MoveBaseFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseActionGoal(Message):
    """``move_base_msgs/MoveBaseActionGoal``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def goal_id(self) -> actionlib_msgs.GoalID: ...
    @goal_id.setter
    def goal_id(self, value: actionlib_msgs.GoalID | Mapping[str, Any]) -> None: ...
    @property
    def goal(self) -> MoveBaseGoal: ...
    @goal.setter
    def goal(self, value: MoveBaseGoal | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        goal_id: actionlib_msgs.GoalID | Mapping[str, Any] = ...,
        goal: MoveBaseGoal | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseActionResult(Message):
    """``move_base_msgs/MoveBaseActionResult``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def result(self) -> MoveBaseResult: ...
    @result.setter
    def result(self, value: MoveBaseResult | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        result: MoveBaseResult | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseFeedback(Message):
    """``move_base_msgs/MoveBaseFeedback``."""

    @property
    def base_position(self) -> geometry_msgs.PoseStamped: ...
    @base_position.setter
    def base_position(self, value: geometry_msgs.PoseStamped | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        base_position: geometry_msgs.PoseStamped | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseGoal(Message):
    """``move_base_msgs/MoveBaseGoal``."""

    @property
    def target_pose(self) -> geometry_msgs.PoseStamped: ...
    @target_pose.setter
    def target_pose(self, value: geometry_msgs.PoseStamped | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        target_pose: geometry_msgs.PoseStamped | Mapping[str, Any] = ...,
    ) -> None: ...

class MoveBaseResult(Message):
    """``move_base_msgs/MoveBaseResult``."""

    def __init__(self) -> None: ...

class RecoveryStatus(Message):
    """``move_base_msgs/RecoveryStatus``."""

    @property
    def pose_stamped(self) -> geometry_msgs.PoseStamped: ...
    @pose_stamped.setter
    def pose_stamped(self, value: geometry_msgs.PoseStamped | Mapping[str, Any]) -> None: ...
    current_recovery_number: int
    total_number_of_recoveries: int
    recovery_behavior_name: str
    def __init__(
        self,
        pose_stamped: geometry_msgs.PoseStamped | Mapping[str, Any] = ...,
        current_recovery_number: int = ...,
        total_number_of_recoveries: int = ...,
        recovery_behavior_name: str = ...,
    ) -> None: ...
