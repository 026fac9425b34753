"""Types of the rosgraph_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, Final

from workbench.msgs import builtin_interfaces, std_msgs
from workbench.msgs import rosgraph_msgs as msg
from workbench.msgs import rosgraph_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "Clock",
    "Log",
    "TopicStatistics",
    "msg",
    "srv",
]

class Clock(Message):
    """``rosgraph_msgs/Clock``."""

    @property
    def clock(self) -> builtin_interfaces.Time: ...
    @clock.setter
    def clock(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        clock: builtin_interfaces.Time | Mapping[str, Any] = ...,
    ) -> None: ...

class Log(Message):
    """``rosgraph_msgs/Log``."""

    DEBUG: Final = 1
    INFO: Final = 2
    WARN: Final = 4
    ERROR: Final = 8
    FATAL: Final = 16

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    level: int
    name: str
    msg: str
    file: str
    function: str
    line: int
    @property
    def topics(self) -> list[str]: ...
    @topics.setter
    def topics(self, value: Iterable[str]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        level: int = ...,
        name: str = ...,
        msg: str = ...,
        file: str = ...,
        function: str = ...,
        line: int = ...,
        topics: Iterable[str] = ...,
    ) -> None: ...

class TopicStatistics(Message):
    """``rosgraph_msgs/TopicStatistics``."""

    topic: str
    node_pub: str
    node_sub: str
    @property
    def window_start(self) -> builtin_interfaces.Time: ...
    @window_start.setter
    def window_start(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    @property
    def window_stop(self) -> builtin_interfaces.Time: ...
    @window_stop.setter
    def window_stop(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    delivered_msgs: int
    dropped_msgs: int
    traffic: int
    @property
    def period_mean(self) -> builtin_interfaces.Duration: ...
    @period_mean.setter
    def period_mean(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def period_stddev(self) -> builtin_interfaces.Duration: ...
    @period_stddev.setter
    def period_stddev(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def period_max(self) -> builtin_interfaces.Duration: ...
    @period_max.setter
    def period_max(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def stamp_age_mean(self) -> builtin_interfaces.Duration: ...
    @stamp_age_mean.setter
    def stamp_age_mean(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def stamp_age_stddev(self) -> builtin_interfaces.Duration: ...
    @stamp_age_stddev.setter
    def stamp_age_stddev(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def stamp_age_max(self) -> builtin_interfaces.Duration: ...
    @stamp_age_max.setter
    def stamp_age_max(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        topic: str = ...,
        node_pub: str = ...,
        node_sub: str = ...,
        window_start: builtin_interfaces.Time | Mapping[str, Any] = ...,
        window_stop: builtin_interfaces.Time | Mapping[str, Any] = ...,
        delivered_msgs: int = ...,
        dropped_msgs: int = ...,
        traffic: int = ...,
        period_mean: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        period_stddev: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        period_max: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        stamp_age_mean: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        stamp_age_stddev: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        stamp_age_max: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...
