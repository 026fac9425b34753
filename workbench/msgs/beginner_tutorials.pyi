"""Types of the beginner_tutorials messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from typing import ClassVar

from workbench.msgs import beginner_tutorials as msg
from workbench.msgs import beginner_tutorials as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "AddTwoInts",
    "AddTwoIntsRequest",
    "AddTwoIntsResponse",
    "msg",
    "srv",
]

class AddTwoIntsRequest(Message):
    """``beginner_tutorials/AddTwoIntsRequest``."""

    a: int
    b: int
    def __init__(
        self,
        a: int = ...,
        b: int = ...,
    ) -> None: ...

class AddTwoIntsResponse(Message):
    """``beginner_tutorials/AddTwoIntsResponse``."""

    sum: int
    def __init__(
        self,
        sum: int = ...,
    ) -> None: ...

class AddTwoInts(ServiceType):
    """``beginner_tutorials/AddTwoInts``: ``AddTwoInts.Request(...)``, ``AddTwoInts.Response(...)``."""

    Request: ClassVar[type[AddTwoIntsRequest]]
    Response: ClassVar[type[AddTwoIntsResponse]]
