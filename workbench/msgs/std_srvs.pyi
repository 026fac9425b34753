"""Types of the std_srvs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from typing import ClassVar

from workbench.msgs import std_srvs as msg
from workbench.msgs import std_srvs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "Empty",
    "EmptyRequest",
    "EmptyResponse",
    "SetBool",
    "SetBoolRequest",
    "SetBoolResponse",
    "Trigger",
    "TriggerRequest",
    "TriggerResponse",
    "msg",
    "srv",
]

class EmptyRequest(Message):
    """``std_srvs/EmptyRequest``."""

    def __init__(self) -> None: ...

class EmptyResponse(Message):
    """``std_srvs/EmptyResponse``."""

    def __init__(self) -> None: ...

class SetBoolRequest(Message):
    """``std_srvs/SetBoolRequest``."""

    data: bool
    def __init__(
        self,
        data: bool = ...,
    ) -> None: ...

class SetBoolResponse(Message):
    """``std_srvs/SetBoolResponse``."""

    success: bool
    message: str
    def __init__(
        self,
        success: bool = ...,
        message: str = ...,
    ) -> None: ...

class TriggerRequest(Message):
    """``std_srvs/TriggerRequest``."""

    def __init__(self) -> None: ...

class TriggerResponse(Message):
    """``std_srvs/TriggerResponse``."""

    success: bool
    message: str
    def __init__(
        self,
        success: bool = ...,
        message: str = ...,
    ) -> None: ...

class Empty(ServiceType):
    """``std_srvs/Empty``: ``Empty.Request(...)``, ``Empty.Response(...)``."""

    Request: ClassVar[type[EmptyRequest]]
    Response: ClassVar[type[EmptyResponse]]

class SetBool(ServiceType):
    """``std_srvs/SetBool``: ``SetBool.Request(...)``, ``SetBool.Response(...)``."""

    Request: ClassVar[type[SetBoolRequest]]
    Response: ClassVar[type[SetBoolResponse]]

class Trigger(ServiceType):
    """``std_srvs/Trigger``: ``Trigger.Request(...)``, ``Trigger.Response(...)``."""

    Request: ClassVar[type[TriggerRequest]]
    Response: ClassVar[type[TriggerResponse]]
