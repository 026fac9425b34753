"""Types of the controller_manager_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

from workbench.msgs import controller_manager_msgs as msg
from workbench.msgs import controller_manager_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "ControllerState",
    "HardwareInterfaceResources",
    "ListControllerTypes",
    "ListControllerTypesRequest",
    "ListControllerTypesResponse",
    "ListControllers",
    "ListControllersRequest",
    "ListControllersResponse",
    "LoadController",
    "LoadControllerRequest",
    "LoadControllerResponse",
    "ReloadControllerLibraries",
    "ReloadControllerLibrariesRequest",
    "ReloadControllerLibrariesResponse",
    "SwitchController",
    "SwitchControllerRequest",
    "SwitchControllerResponse",
    "UnloadController",
    "UnloadControllerRequest",
    "UnloadControllerResponse",
    "msg",
    "srv",
]

class ControllerState(Message):
    """``controller_manager_msgs/ControllerState``."""

    name: str
    state: str
    type: str
    @property
    def claimed_resources(self) -> list[HardwareInterfaceResources]: ...
    @claimed_resources.setter
    def claimed_resources(
        self, value: Iterable[HardwareInterfaceResources | Mapping[str, Any]]
    ) -> None: ...
    def __init__(
        self,
        name: str = ...,
        state: str = ...,
        type: str = ...,
        claimed_resources: Iterable[HardwareInterfaceResources | Mapping[str, Any]] = ...,
    ) -> None: ...

class HardwareInterfaceResources(Message):
    """``controller_manager_msgs/HardwareInterfaceResources``."""

    hardware_interface: str
    @property
    def resources(self) -> list[str]: ...
    @resources.setter
    def resources(self, value: Iterable[str]) -> None: ...
    def __init__(
        self,
        hardware_interface: str = ...,
        resources: Iterable[str] = ...,
    ) -> None: ...

class ListControllerTypesRequest(Message):
    """``controller_manager_msgs/ListControllerTypesRequest``."""

    def __init__(self) -> None: ...

class ListControllerTypesResponse(Message):
    """``controller_manager_msgs/ListControllerTypesResponse``."""

    @property
    def types(self) -> list[str]: ...
    @types.setter
    def types(self, value: Iterable[str]) -> None: ...
    @property
    def base_classes(self) -> list[str]: ...
    @base_classes.setter
    def base_classes(self, value: Iterable[str]) -> None: ...
    def __init__(
        self,
        types: Iterable[str] = ...,
        base_classes: Iterable[str] = ...,
    ) -> None: ...

class ListControllersRequest(Message):
    """``controller_manager_msgs/ListControllersRequest``."""

    def __init__(self) -> None: ...

class ListControllersResponse(Message):
    """``controller_manager_msgs/ListControllersResponse``."""

    @property
    def controller(self) -> list[ControllerState]: ...
    @controller.setter
    def controller(self, value: Iterable[ControllerState | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        controller: Iterable[ControllerState | Mapping[str, Any]] = ...,
    ) -> None: ...

class LoadControllerRequest(Message):
    """``controller_manager_msgs/LoadControllerRequest``."""

    name: str
    def __init__(
        self,
        name: str = ...,
    ) -> None: ...

class LoadControllerResponse(Message):
    """``controller_manager_msgs/LoadControllerResponse``."""

    ok: bool
    def __init__(
        self,
        ok: bool = ...,
    ) -> None: ...

class ReloadControllerLibrariesRequest(Message):
    """``controller_manager_msgs/ReloadControllerLibrariesRequest``."""

    force_kill: bool
    def __init__(
        self,
        force_kill: bool = ...,
    ) -> None: ...

class ReloadControllerLibrariesResponse(Message):
    """``controller_manager_msgs/ReloadControllerLibrariesResponse``."""

    ok: bool
    def __init__(
        self,
        ok: bool = ...,
    ) -> None: ...

class SwitchControllerRequest(Message):
    """``controller_manager_msgs/SwitchControllerRequest``."""

    BEST_EFFORT: Final = 1
    STRICT: Final = 2

    @property
    def start_controllers(self) -> list[str]: ...
    @start_controllers.setter
    def start_controllers(self, value: Iterable[str]) -> None: ...
    @property
    def stop_controllers(self) -> list[str]: ...
    @stop_controllers.setter
    def stop_controllers(self, value: Iterable[str]) -> None: ...
    strictness: int
    start_asap: bool
    timeout: float
    def __init__(
        self,
        start_controllers: Iterable[str] = ...,
        stop_controllers: Iterable[str] = ...,
        strictness: int = ...,
        start_asap: bool = ...,
        timeout: float = ...,
    ) -> None: ...

class SwitchControllerResponse(Message):
    """``controller_manager_msgs/SwitchControllerResponse``."""

    ok: bool
    def __init__(
        self,
        ok: bool = ...,
    ) -> None: ...

class UnloadControllerRequest(Message):
    """``controller_manager_msgs/UnloadControllerRequest``."""

    name: str
    def __init__(
        self,
        name: str = ...,
    ) -> None: ...

class UnloadControllerResponse(Message):
    """``controller_manager_msgs/UnloadControllerResponse``."""

    ok: bool
    def __init__(
        self,
        ok: bool = ...,
    ) -> None: ...

class ListControllerTypes(ServiceType):
    """``controller_manager_msgs/ListControllerTypes``: ``ListControllerTypes.Request(...)``, ``ListControllerTypes.Response(...)``."""

    Request: ClassVar[type[ListControllerTypesRequest]]
    Response: ClassVar[type[ListControllerTypesResponse]]

class ListControllers(ServiceType):
    """``controller_manager_msgs/ListControllers``: ``ListControllers.Request(...)``, ``ListControllers.Response(...)``."""

    Request: ClassVar[type[ListControllersRequest]]
    Response: ClassVar[type[ListControllersResponse]]

class LoadController(ServiceType):
    """``controller_manager_msgs/LoadController``: ``LoadController.Request(...)``, ``LoadController.Response(...)``."""

    Request: ClassVar[type[LoadControllerRequest]]
    Response: ClassVar[type[LoadControllerResponse]]

class ReloadControllerLibraries(ServiceType):
    """``controller_manager_msgs/ReloadControllerLibraries``: ``ReloadControllerLibraries.Request(...)``, ``ReloadControllerLibraries.Response(...)``."""

    Request: ClassVar[type[ReloadControllerLibrariesRequest]]
    Response: ClassVar[type[ReloadControllerLibrariesResponse]]

class SwitchController(ServiceType):
    """``controller_manager_msgs/SwitchController``: ``SwitchController.Request(...)``, ``SwitchController.Response(...)``."""

    Request: ClassVar[type[SwitchControllerRequest]]
    Response: ClassVar[type[SwitchControllerResponse]]

class UnloadController(ServiceType):
    """``controller_manager_msgs/UnloadController``: ``UnloadController.Request(...)``, ``UnloadController.Response(...)``."""

    Request: ClassVar[type[UnloadControllerRequest]]
    Response: ClassVar[type[UnloadControllerResponse]]
