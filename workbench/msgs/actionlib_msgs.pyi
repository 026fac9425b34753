"""Types of the actionlib_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, Final

from workbench.msgs import actionlib_msgs as msg
from workbench.msgs import actionlib_msgs as srv
from workbench.msgs import builtin_interfaces, std_msgs
from workbench.msgs._classes import Message

__all__ = [
    "GoalID",
    "GoalStatus",
    "GoalStatusArray",
    "msg",
    "srv",
]

class GoalID(Message):
    """``actionlib_msgs/GoalID``."""

    @property
    def stamp(self) -> builtin_interfaces.Time: ...
    @stamp.setter
    def stamp(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    id: str
    def __init__(
        self,
        stamp: builtin_interfaces.Time | Mapping[str, Any] = ...,
        id: str = ...,
    ) -> None: ...

class GoalStatus(Message):
    """``actionlib_msgs/GoalStatus``."""

    PENDING: Final = 0
    ACTIVE: Final = 1
    PREEMPTED: Final = 2
    SUCCEEDED: Final = 3
    ABORTED: Final = 4
    REJECTED: Final = 5
    PREEMPTING: Final = 6
    RECALLING: Final = 7
    RECALLED: Final = 8
    LOST: Final = 9

    @property
    def goal_id(self) -> GoalID: ...
    @goal_id.setter
    def goal_id(self, value: GoalID | Mapping[str, Any]) -> None: ...
    status: int
    text: str
    def __init__(
        self,
        goal_id: GoalID | Mapping[str, Any] = ...,
        status: int = ...,
        text: str = ...,
    ) -> None: ...

class GoalStatusArray(Message):
    """``actionlib_msgs/GoalStatusArray``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status_list(self) -> list[GoalStatus]: ...
    @status_list.setter
    def status_list(self, value: Iterable[GoalStatus | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status_list: Iterable[GoalStatus | Mapping[str, Any]] = ...,
    ) -> None: ...
