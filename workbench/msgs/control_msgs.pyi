"""Types of the control_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import actionlib_msgs, builtin_interfaces, std_msgs, trajectory_msgs
from workbench.msgs import control_msgs as msg
from workbench.msgs import control_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "FollowJointTrajectoryAction",
    "FollowJointTrajectoryActionFeedback",
    "FollowJointTrajectoryActionGoal",
    "FollowJointTrajectoryActionResult",
    "FollowJointTrajectoryFeedback",
    "FollowJointTrajectoryGoal",
    "FollowJointTrajectoryResult",
    "JointControllerState",
    "JointTolerance",
    "JointTrajectoryControllerState",
    "QueryTrajectoryState",
    "QueryTrajectoryStateRequest",
    "QueryTrajectoryStateResponse",
    "msg",
    "srv",
]

class FollowJointTrajectoryAction(Message):
    """``control_msgs/FollowJointTrajectoryAction``."""

    @property
    def action_goal(self) -> FollowJointTrajectoryActionGoal: ...
    @action_goal.setter
    def action_goal(self, value: FollowJointTrajectoryActionGoal | Mapping[str, Any]) -> None: ...
    @property
    def action_result(self) -> FollowJointTrajectoryActionResult: ...
    @action_result.setter
    def action_result(
        self, value: FollowJointTrajectoryActionResult | Mapping[str, Any]
    ) -> None: ...
    @property
    def action_feedback(self) -> FollowJointTrajectoryActionFeedback: ...
    @action_feedback.setter
    def action_feedback(
        self, value: FollowJointTrajectoryActionFeedback | Mapping[str, Any]
    ) -> None: ...
    def __init__(
        self,
        action_goal: FollowJointTrajectoryActionGoal | Mapping[str, Any] = ...,
        action_result: FollowJointTrajectoryActionResult | Mapping[str, Any] = ...,
        action_feedback: FollowJointTrajectoryActionFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryActionFeedback(Message):
    """``control_msgs/FollowJointTrajectoryActionFeedback``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def feedback(self) -> FollowJointTrajectoryFeedback: ...
    @feedback.setter
    def feedback(self, value: FollowJointTrajectoryFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        feedback: FollowJointTrajectoryFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryActionGoal(Message):
    """``control_msgs/FollowJointTrajectoryActionGoal``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def goal_id(self) -> actionlib_msgs.GoalID: ...
    @goal_id.setter
    def goal_id(self, value: actionlib_msgs.GoalID | Mapping[str, Any]) -> None: ...
    @property
    def goal(self) -> FollowJointTrajectoryGoal: ...
    @goal.setter
    def goal(self, value: FollowJointTrajectoryGoal | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        goal_id: actionlib_msgs.GoalID | Mapping[str, Any] = ...,
        goal: FollowJointTrajectoryGoal | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryActionResult(Message):
    """``control_msgs/FollowJointTrajectoryActionResult``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def result(self) -> FollowJointTrajectoryResult: ...
    @result.setter
    def result(self, value: FollowJointTrajectoryResult | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        result: FollowJointTrajectoryResult | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryFeedback(Message):
    """``control_msgs/FollowJointTrajectoryFeedback``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def desired(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @desired.setter
    def desired(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    @property
    def actual(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @actual.setter
    def actual(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    @property
    def error(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @error.setter
    def error(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        joint_names: Iterable[str] = ...,
        desired: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
        actual: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
        error: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryGoal(Message):
    """``control_msgs/FollowJointTrajectoryGoal``."""

    @property
    def trajectory(self) -> trajectory_msgs.JointTrajectory: ...
    @trajectory.setter
    def trajectory(self, value: trajectory_msgs.JointTrajectory | Mapping[str, Any]) -> None: ...
    @property
    def path_tolerance(self) -> list[JointTolerance]: ...
    @path_tolerance.setter
    def path_tolerance(self, value: Iterable[JointTolerance | Mapping[str, Any]]) -> None: ...
    @property
    def goal_tolerance(self) -> list[JointTolerance]: ...
    @goal_tolerance.setter
    def goal_tolerance(self, value: Iterable[JointTolerance | Mapping[str, Any]]) -> None: ...
    @property
    def goal_time_tolerance(self) -> builtin_interfaces.Duration: ...
    @goal_time_tolerance.setter
    def goal_time_tolerance(
        self, value: builtin_interfaces.Duration | Mapping[str, Any]
    ) -> None: ...
    def __init__(
        self,
        trajectory: trajectory_msgs.JointTrajectory | Mapping[str, Any] = ...,
        path_tolerance: Iterable[JointTolerance | Mapping[str, Any]] = ...,
        goal_tolerance: Iterable[JointTolerance | Mapping[str, Any]] = ...,
        goal_time_tolerance: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...

class FollowJointTrajectoryResult(Message):
    """``control_msgs/FollowJointTrajectoryResult``."""

    SUCCESSFUL: Final = 0
    INVALID_GOAL: Final = -1
    INVALID_JOINTS: Final = -2
    OLD_HEADER_TIMESTAMP: Final = -3
    PATH_TOLERANCE_VIOLATED: Final = -4
    GOAL_TOLERANCE_VIOLATED: Final = -5

    error_code: int
    error_string: str
    def __init__(
        self,
        error_code: int = ...,
        error_string: str = ...,
    ) -> None: ...

class JointControllerState(Message):
    """``control_msgs/JointControllerState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    set_point: float
    process_value: float
    process_value_dot: float
    error: float
    time_step: float
    command: float
    p: float
    i: float
    d: float
    i_clamp: float
    antiwindup: bool
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        set_point: float = ...,
        process_value: float = ...,
        process_value_dot: float = ...,
        error: float = ...,
        time_step: float = ...,
        command: float = ...,
        p: float = ...,
        i: float = ...,
        d: float = ...,
        i_clamp: float = ...,
        antiwindup: bool = ...,
    ) -> None: ...

class JointTolerance(Message):
    """``control_msgs/JointTolerance``."""

    name: str
    position: float
    velocity: float
    acceleration: float
    def __init__(
        self,
        name: str = ...,
        position: float = ...,
        velocity: float = ...,
        acceleration: float = ...,
    ) -> None: ...

class JointTrajectoryControllerState(Message):
    """``control_msgs/JointTrajectoryControllerState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def desired(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @desired.setter
    def desired(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    @property
    def actual(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @actual.setter
    def actual(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    @property
    def error(self) -> trajectory_msgs.JointTrajectoryPoint: ...
    @error.setter
    def error(self, value: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        joint_names: Iterable[str] = ...,
        desired: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
        actual: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
        error: trajectory_msgs.JointTrajectoryPoint | Mapping[str, Any] = ...,
    ) -> None: ...

class QueryTrajectoryStateRequest(Message):
    """``control_msgs/QueryTrajectoryStateRequest``."""

    @property
    def time(self) -> builtin_interfaces.Time: ...
    @time.setter
    def time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        time: builtin_interfaces.Time | Mapping[str, Any] = ...,
    ) -> None: ...

class QueryTrajectoryStateResponse(Message):
    """``control_msgs/QueryTrajectoryStateResponse``."""

    @property
    def name(self) -> list[str]: ...
    @name.setter
    def name(self, value: Iterable[str]) -> None: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @position.setter
    def position(self, value: ArrayLike) -> None: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...
    @velocity.setter
    def velocity(self, value: ArrayLike) -> None: ...
    @property
    def acceleration(self) -> NDArray[np.float64]: ...
    @acceleration.setter
    def acceleration(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        name: Iterable[str] = ...,
        position: ArrayLike = ...,
        velocity: ArrayLike = ...,
        acceleration: ArrayLike = ...,
    ) -> None: ...

class QueryTrajectoryState(ServiceType):
    """``control_msgs/QueryTrajectoryState``: ``QueryTrajectoryState.Request(...)``, ``QueryTrajectoryState.Response(...)``."""

    Request: ClassVar[type[QueryTrajectoryStateRequest]]
    Response: ClassVar[type[QueryTrajectoryStateResponse]]
