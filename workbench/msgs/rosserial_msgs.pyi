"""Types of the rosserial_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable
from typing import ClassVar, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import rosserial_msgs as msg
from workbench.msgs import rosserial_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "Log",
    "RequestParam",
    "RequestParamRequest",
    "RequestParamResponse",
    "TopicInfo",
    "msg",
    "srv",
]

class Log(Message):
    """``rosserial_msgs/Log``."""

    ROSDEBUG: Final = 0
    INFO: Final = 1
    WARN: Final = 2
    ERROR: Final = 3
    FATAL: Final = 4

    level: int
    msg: str
    def __init__(
        self,
        level: int = ...,
        msg: str = ...,
    ) -> None: ...

class RequestParamRequest(Message):
    """``rosserial_msgs/RequestParamRequest``."""

    name: str
    def __init__(
        self,
        name: str = ...,
    ) -> None: ...

class RequestParamResponse(Message):
    """``rosserial_msgs/RequestParamResponse``."""

    @property
    def ints(self) -> NDArray[np.int32]: ...
    @ints.setter
    def ints(self, value: ArrayLike) -> None: ...
    @property
    def floats(self) -> NDArray[np.float32]: ...
    @floats.setter
    def floats(self, value: ArrayLike) -> None: ...
    @property
    def strings(self) -> list[str]: ...
    @strings.setter
    def strings(self, value: Iterable[str]) -> None: ...
    def __init__(
        self,
        ints: ArrayLike = ...,
        floats: ArrayLike = ...,
        strings: Iterable[str] = ...,
    ) -> None: ...

class TopicInfo(Message):
    """``rosserial_msgs/TopicInfo``."""

    ID_PUBLISHER: Final = 0
    ID_SUBSCRIBER: Final = 1
    ID_SERVICE_SERVER: Final = 2
    ID_SERVICE_CLIENT: Final = 4
    ID_PARAMETER_REQUEST: Final = 6
    ID_LOG: Final = 7
    ID_TIME: Final = 10
    ID_TX_STOP: Final = 11

    topic_id: int
    topic_name: str
    message_type: str
    md5sum: str
    buffer_size: int
    def __init__(
        self,
        topic_id: int = ...,
        topic_name: str = ...,
        message_type: str = ...,
        md5sum: str = ...,
        buffer_size: int = ...,
    ) -> None: ...

class RequestParam(ServiceType):
    """``rosserial_msgs/RequestParam``: ``RequestParam.Request(...)``, ``RequestParam.Response(...)``."""

    Request: ClassVar[type[RequestParamRequest]]
    Response: ClassVar[type[RequestParamResponse]]
