"""Per-package modules: ``from workbench.msgs.std_msgs import String``.

Each package module is a few lines that hand their attribute lookups to
:func:`package_getattr`, so classes are looked up in the type store on first
use and importing a package module stays cheap.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

#: package -> (the store's identity and size when computed, members): a lookup per
#: attribute access scanned every registered type, which made code that imports a
#: message class inside a loop slow.
_MEMBERS: dict[str, tuple[tuple[int, int, int], dict[str, Any]]] = {}


def package_members(package: str) -> dict[str, Any]:
    """Name -> class for every message and service type of ``package``.

    A service ``Spawn`` also exports ``SpawnRequest`` and ``SpawnResponse``, as rospy's
    generated modules do. Recomputed when types are registered.
    """
    from workbench.msgs._store import store

    types = store()
    key = (id(types), len(types.classes), len(types.services))
    cached = _MEMBERS.get(package)
    if cached is not None and cached[0] == key:
        return cached[1]
    members: dict[str, Any] = {}
    for name, cls in types.classes.items():
        if name.split("/")[0] == package:
            members[cls.__name__] = cls
    for name, service in types.services.items():
        if name.split("/")[0] == package:
            members[service.__name__] = service
    _MEMBERS[package] = (key, members)
    return members


def package_getattr(package: str) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """The ``__getattr__`` and ``__dir__`` of the module ``workbench.msgs.<package>``."""

    def __getattr__(name: str) -> Any:
        if name in ("msg", "srv"):
            # `turtlesim.msg.Pose` / `turtlesim.srv.Spawn`, as in the lab's rospy scripts.
            import sys

            return sys.modules[f"workbench.msgs.{package}"]
        members = package_members(package)
        if name == "__all__":
            return sorted(members)
        if name in members:
            return members[name]
        if name.startswith("__"):
            raise AttributeError(name)
        from workbench.msgs import get_type

        get_type(f"{package}/{name}")  # raises the "unknown type, did you mean" error
        raise AttributeError(name)  # pragma: no cover - get_type raised

    def __dir__() -> list[str]:
        return sorted(package_members(package))

    return __getattr__, __dir__
