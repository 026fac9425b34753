"""Types of the turtlesim messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from typing import ClassVar

from workbench.msgs import turtlesim as msg
from workbench.msgs import turtlesim as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "Color",
    "Kill",
    "KillRequest",
    "KillResponse",
    "Pose",
    "SetPen",
    "SetPenRequest",
    "SetPenResponse",
    "Spawn",
    "SpawnRequest",
    "SpawnResponse",
    "TeleportAbsolute",
    "TeleportAbsoluteRequest",
    "TeleportAbsoluteResponse",
    "TeleportRelative",
    "TeleportRelativeRequest",
    "TeleportRelativeResponse",
    "msg",
    "srv",
]

class Color(Message):
    """``turtlesim/Color``."""

    r: int
    g: int
    b: int
    def __init__(
        self,
        r: int = ...,
        g: int = ...,
        b: int = ...,
    ) -> None: ...

class KillRequest(Message):
    """``turtlesim/KillRequest``."""

    name: str
    def __init__(
        self,
        name: str = ...,
    ) -> None: ...

class KillResponse(Message):
    """``turtlesim/KillResponse``."""

    def __init__(self) -> None: ...

class Pose(Message):
    """``turtlesim/Pose``."""

    x: float
    y: float
    theta: float
    linear_velocity: float
    angular_velocity: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        theta: float = ...,
        linear_velocity: float = ...,
        angular_velocity: float = ...,
    ) -> None: ...

class SetPenRequest(Message):
    """``turtlesim/SetPenRequest``."""

    r: int
    g: int
    b: int
    width: int
    off: int
    def __init__(
        self,
        r: int = ...,
        g: int = ...,
        b: int = ...,
        width: int = ...,
        off: int = ...,
    ) -> None: ...

class SetPenResponse(Message):
    """``turtlesim/SetPenResponse``."""

    def __init__(self) -> None: ...

class SpawnRequest(Message):
    """``turtlesim/SpawnRequest``."""

    x: float
    y: float
    theta: float
    name: str
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        theta: float = ...,
        name: str = ...,
    ) -> None: ...

class SpawnResponse(Message):
    """``turtlesim/SpawnResponse``."""

    name: str
    def __init__(
        self,
        name: str = ...,
    ) -> None: ...

class TeleportAbsoluteRequest(Message):
    """``turtlesim/TeleportAbsoluteRequest``."""

    x: float
    y: float
    theta: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        theta: float = ...,
    ) -> None: ...

class TeleportAbsoluteResponse(Message):
    """``turtlesim/TeleportAbsoluteResponse``."""

    def __init__(self) -> None: ...

class TeleportRelativeRequest(Message):
    """``turtlesim/TeleportRelativeRequest``."""

    linear: float
    angular: float
    def __init__(
        self,
        linear: float = ...,
        angular: float = ...,
    ) -> None: ...

class TeleportRelativeResponse(Message):
    """``turtlesim/TeleportRelativeResponse``."""

    def __init__(self) -> None: ...

class Kill(ServiceType):
    """``turtlesim/Kill``: ``Kill.Request(...)``, ``Kill.Response(...)``."""

    Request: ClassVar[type[KillRequest]]
    Response: ClassVar[type[KillResponse]]

class SetPen(ServiceType):
    """``turtlesim/SetPen``: ``SetPen.Request(...)``, ``SetPen.Response(...)``."""

    Request: ClassVar[type[SetPenRequest]]
    Response: ClassVar[type[SetPenResponse]]

class Spawn(ServiceType):
    """``turtlesim/Spawn``: ``Spawn.Request(...)``, ``Spawn.Response(...)``."""

    Request: ClassVar[type[SpawnRequest]]
    Response: ClassVar[type[SpawnResponse]]

class TeleportAbsolute(ServiceType):
    """``turtlesim/TeleportAbsolute``: ``TeleportAbsolute.Request(...)``, ``TeleportAbsolute.Response(...)``."""

    Request: ClassVar[type[TeleportAbsoluteRequest]]
    Response: ClassVar[type[TeleportAbsoluteResponse]]

class TeleportRelative(ServiceType):
    """``turtlesim/TeleportRelative``: ``TeleportRelative.Request(...)``, ``TeleportRelative.Response(...)``."""

    Request: ClassVar[type[TeleportRelativeRequest]]
    Response: ClassVar[type[TeleportRelativeResponse]]
