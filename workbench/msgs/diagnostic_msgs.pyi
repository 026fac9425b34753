"""Types of the diagnostic_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

from workbench.msgs import diagnostic_msgs as msg
from workbench.msgs import diagnostic_msgs as srv
from workbench.msgs import std_msgs
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "AddDiagnostics",
    "AddDiagnosticsRequest",
    "AddDiagnosticsResponse",
    "DiagnosticArray",
    "DiagnosticStatus",
    "KeyValue",
    "SelfTest",
    "SelfTestRequest",
    "SelfTestResponse",
    "msg",
    "srv",
]

class AddDiagnosticsRequest(Message):
    """``diagnostic_msgs/AddDiagnosticsRequest``."""

    load_namespace: str
    def __init__(
        self,
        load_namespace: str = ...,
    ) -> None: ...

class AddDiagnosticsResponse(Message):
    """``diagnostic_msgs/AddDiagnosticsResponse``."""

    success: bool
    message: str
    def __init__(
        self,
        success: bool = ...,
        message: str = ...,
    ) -> None: ...

class DiagnosticArray(Message):
    """``diagnostic_msgs/DiagnosticArray``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> list[DiagnosticStatus]: ...
    @status.setter
    def status(self, value: Iterable[DiagnosticStatus | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: Iterable[DiagnosticStatus | Mapping[str, Any]] = ...,
    ) -> None: ...

class DiagnosticStatus(Message):
    """``diagnostic_msgs/DiagnosticStatus``."""

    OK: Final = 0
    WARN: Final = 1
    ERROR: Final = 2
    STALE: Final = 3

    level: int
    name: str
    message: str
    hardware_id: str
    @property
    def values(self) -> list[KeyValue]: ...
    @values.setter
    def values(self, value: Iterable[KeyValue | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        level: int = ...,
        name: str = ...,
        message: str = ...,
        hardware_id: str = ...,
        values: Iterable[KeyValue | Mapping[str, Any]] = ...,
    ) -> None: ...

class KeyValue(Message):
    """``diagnostic_msgs/KeyValue``."""

    key: str
    value: str
    def __init__(
        self,
        key: str = ...,
        value: str = ...,
    ) -> None: ...

class SelfTestRequest(Message):
    """``diagnostic_msgs/SelfTestRequest``."""

    def __init__(self) -> None: ...

class SelfTestResponse(Message):
    """``diagnostic_msgs/SelfTestResponse``."""

    id: str
    passed: int
    @property
    def status(self) -> list[DiagnosticStatus]: ...
    @status.setter
    def status(self, value: Iterable[DiagnosticStatus | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        id: str = ...,
        passed: int = ...,
        status: Iterable[DiagnosticStatus | Mapping[str, Any]] = ...,
    ) -> None: ...

class AddDiagnostics(ServiceType):
    """``diagnostic_msgs/AddDiagnostics``: ``AddDiagnostics.Request(...)``, ``AddDiagnostics.Response(...)``."""

    Request: ClassVar[type[AddDiagnosticsRequest]]
    Response: ClassVar[type[AddDiagnosticsResponse]]

class SelfTest(ServiceType):
    """``diagnostic_msgs/SelfTest``: ``SelfTest.Request(...)``, ``SelfTest.Response(...)``."""

    Request: ClassVar[type[SelfTestRequest]]
    Response: ClassVar[type[SelfTestResponse]]
