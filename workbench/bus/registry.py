"""The registry of runnable nodes: ``pkg/type`` -> an entry point, for launch and run.

Capabilities register their nodes here (``workbench.turtlesim`` registers
``turtlesim/turtlesim_node``); ``workbench run PKG TYPE`` and ``<node pkg=
type=>`` in launch files look them up. An entry point is
``"module.path:function"``; the function is called as ``function(argv)``
with the node's command-line arguments (remappings included) and returns an
exit status (or None). Modules listed in :data:`PROVIDERS` are imported on
lookup so that their registrations happen without importing everything up
front.
"""

from __future__ import annotations

import importlib
import threading

from workbench.errors import BusError

_ENTRIES: dict[str, str] = {}
_LOCK = threading.Lock()

#: Modules imported (if they exist) before a lookup, so they can register their nodes.
PROVIDERS: list[str] = [
    "workbench.turtlesim",
    "workbench.tf",
    "workbench.sim",
    "workbench.serial",
    "workbench.planning",
    "workbench.mapping",
]


class UnknownNodeError(BusError):
    """No node is registered under that package/type."""


def register_node(name: str, entry_point: str) -> None:
    """Register a runnable node.

    Args:
        name: ``package/type`` as launch files write it (``turtlesim/turtlesim_node``).
        entry_point: ``"module.path:function"``; ``function(argv: list[str]) -> int | None``.
    """
    if name.count("/") != 1 or ":" not in entry_point:
        raise BusError(
            f"cannot register node '{name}' -> '{entry_point}'",
            hint="use register_node('package/type', 'module.path:function')",
        )
    with _LOCK:
        _ENTRIES[name] = entry_point


def _load_providers() -> None:
    for module in PROVIDERS:
        try:
            importlib.import_module(module)
        except ImportError:
            continue


def registered_nodes() -> dict[str, str]:
    """Every registered ``package/type`` -> entry point."""
    _load_providers()
    with _LOCK:
        return dict(_ENTRIES)


def entry_point(package: str, node_type: str) -> str:
    """The entry point registered for ``package/node_type``.

    Raises:
        UnknownNodeError: Nothing is registered (the message lists what is).
    """
    name = f"{package}/{node_type.removesuffix('.py')}"
    entries = registered_nodes()
    found = entries.get(name) or entries.get(f"{package}/{node_type}")
    if found is None:
        known = ", ".join(sorted(entries)) or "none"
        raise UnknownNodeError(
            f"no node '{node_type}' in package '{package}'",
            hint=f"registered nodes: {known}; or give a script path",
        )
    return found


def load(entry: str):
    """Import and return the function named by ``"module:function"``."""
    module_name, _, function = entry.partition(":")
    try:
        module = importlib.import_module(module_name)
        return getattr(module, function)
    except (ImportError, AttributeError) as error:
        raise UnknownNodeError(f"cannot load node entry point '{entry}': {error}") from None
