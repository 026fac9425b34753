"""Types of the tf2_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

from workbench.msgs import actionlib_msgs, builtin_interfaces, geometry_msgs, std_msgs
from workbench.msgs import tf2_msgs as msg
from workbench.msgs import tf2_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "FrameGraph",
    "FrameGraphRequest",
    "FrameGraphResponse",
    "LookupTransformAction",
    "LookupTransformActionFeedback",
    "LookupTransformActionGoal",
    "LookupTransformActionResult",
    "LookupTransformFeedback",
    "LookupTransformGoal",
    "LookupTransformResult",
    "TF2Error",
    "TFMessage",
    "msg",
    "srv",
]

class FrameGraphRequest(Message):
    """``tf2_msgs/FrameGraphRequest``."""

    def __init__(self) -> None: ...

class FrameGraphResponse(Message):
    """``tf2_msgs/FrameGraphResponse``."""

    frame_yaml: str
    def __init__(
        self,
        frame_yaml: str = ...,
    ) -> None: ...

class LookupTransformAction(Message):
    """``tf2_msgs/LookupTransformAction``."""

    @property
    def action_goal(self) -> LookupTransformActionGoal: ...
    @action_goal.setter
    def action_goal(self, value: LookupTransformActionGoal | Mapping[str, Any]) -> None: ...
    @property
    def action_result(self) -> LookupTransformActionResult: ...
    @action_result.setter
    def action_result(self, value: LookupTransformActionResult | Mapping[str, Any]) -> None: ...
    @property
    def action_feedback(self) -> LookupTransformActionFeedback: ...
    @action_feedback.setter
    def action_feedback(self, value: LookupTransformActionFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        action_goal: LookupTransformActionGoal | Mapping[str, Any] = ...,
        action_result: LookupTransformActionResult | Mapping[str, Any] = ...,
        action_feedback: LookupTransformActionFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class LookupTransformActionFeedback(Message):
    """``tf2_msgs/LookupTransformActionFeedback``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def feedback(self) -> LookupTransformFeedback: ...
    @feedback.setter
    def feedback(self, value: LookupTransformFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        feedback: LookupTransformFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class LookupTransformActionGoal(Message):
    """``tf2_msgs/LookupTransformActionGoal``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def goal_id(self) -> actionlib_msgs.GoalID: ...
    @goal_id.setter
    def goal_id(self, value: actionlib_msgs.GoalID | Mapping[str, Any]) -> None: ...
    @property
    def goal(self) -> LookupTransformGoal: ...
    @goal.setter
    def goal(self, value: LookupTransformGoal | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        goal_id: actionlib_msgs.GoalID | Mapping[str, Any] = ...,
        goal: LookupTransformGoal | Mapping[str, Any] = ...,
    ) -> None: ...

class LookupTransformActionResult(Message):
    """``tf2_msgs/LookupTransformActionResult``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def result(self) -> LookupTransformResult: ...
    @result.setter
    def result(self, value: LookupTransformResult | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        result: LookupTransformResult | Mapping[str, Any] = ...,
    ) -> None: ...

class LookupTransformFeedback(Message):
    """``tf2_msgs/LookupTransformFeedback``."""

    def __init__(self) -> None: ...

class LookupTransformGoal(Message):
    """``tf2_msgs/LookupTransformGoal``."""

    target_frame: str
    source_frame: str
    @property
    def source_time(self) -> builtin_interfaces.Time: ...
    @source_time.setter
    def source_time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    @property
    def timeout(self) -> builtin_interfaces.Duration: ...
    @timeout.setter
    def timeout(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def target_time(self) -> builtin_interfaces.Time: ...
    @target_time.setter
    def target_time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    fixed_frame: str
    advanced: bool
    def __init__(
        self,
        target_frame: str = ...,
        source_frame: str = ...,
        source_time: builtin_interfaces.Time | Mapping[str, Any] = ...,
        timeout: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        target_time: builtin_interfaces.Time | Mapping[str, Any] = ...,
        fixed_frame: str = ...,
        advanced: bool = ...,
    ) -> None: ...

class LookupTransformResult(Message):
    """``tf2_msgs/LookupTransformResult``."""

    @property
    def transform(self) -> geometry_msgs.TransformStamped: ...
    @transform.setter
    def transform(self, value: geometry_msgs.TransformStamped | Mapping[str, Any]) -> None: ...
    @property
    def error(self) -> TF2Error: ...
    @error.setter
    def error(self, value: TF2Error | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        transform: geometry_msgs.TransformStamped | Mapping[str, Any] = ...,
        error: TF2Error | Mapping[str, Any] = ...,
    ) -> None: ...

class TF2Error(Message):
    """``tf2_msgs/TF2Error``."""

    NO_ERROR: Final = 0
    LOOKUP_ERROR: Final = 1
    CONNECTIVITY_ERROR: Final = 2
    EXTRAPOLATION_ERROR: Final = 3
    INVALID_ARGUMENT_ERROR: Final = 4
    TIMEOUT_ERROR: Final = 5
    TRANSFORM_ERROR: Final = 6

    error: int
    error_string: str
    def __init__(
        self,
        error: int = ...,
        error_string: str = ...,
    ) -> None: ...

class TFMessage(Message):
    """``tf2_msgs/TFMessage``."""

    @property
    def transforms(self) -> list[geometry_msgs.TransformStamped]: ...
    @transforms.setter
    def transforms(
        self, value: Iterable[geometry_msgs.TransformStamped | Mapping[str, Any]]
    ) -> None: ...
    def __init__(
        self,
        transforms: Iterable[geometry_msgs.TransformStamped | Mapping[str, Any]] = ...,
    ) -> None: ...

class FrameGraph(ServiceType):
    """``tf2_msgs/FrameGraph``: ``FrameGraph.Request(...)``, ``FrameGraph.Response(...)``."""

    Request: ClassVar[type[FrameGraphRequest]]
    Response: ClassVar[type[FrameGraphResponse]]
