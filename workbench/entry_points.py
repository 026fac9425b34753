"""Runnable nodes, declared as entry points: ``package/executable = module:function``.

A node is a function ``function(argv: list[str]) -> int | None`` called with the
node's command line (remappings included); it returns an exit status (None is 0).
Nodes are declared in a distribution's ``pyproject.toml``::

    [project.entry-points."workbench.nodes"]
    "turtlesim/turtlesim_node" = "workbench.turtlesim.node:main"

so ``workbench run PKG EXE`` and ``<node pkg= type=>`` in launch files find them,
workbench's own and those of any installed third-party package alike, without
importing anything but the one module that defines the node. Executable names
may carry ``.py`` as a student types them (``rosserial_python serial_node.py``):
both forms find the node. Scripts and tests may add nodes at run time with
:func:`register_node`.

This module sits at the bottom of the layers (it imports only the standard
library and :mod:`workbench.errors`) so that looking a node up costs a few
milliseconds.
"""

from __future__ import annotations

import importlib
import threading
from collections.abc import Callable
from importlib.metadata import entry_points

from workbench.errors import BusError

#: The entry-point group nodes are declared in.
GROUP = "workbench.nodes"

#: A node's function: called with its command line, returns an exit status or None.
NodeMain = Callable[[list[str]], "int | None"]

_DECLARED_IN = 'fix the [project.entry-points."workbench.nodes"] table that declares it'
_RUNTIME: dict[str, str] = {}
_LOCK = threading.Lock()


class UnknownNodeError(BusError):
    """No node is declared under that package/executable, or its entry point does not load."""


def register_node(name: str, target: str) -> None:
    """Declare a node at run time, for this process only (scripts and tests).

    Installed packages declare their nodes in ``pyproject.toml`` instead; a node
    registered here takes precedence over an installed one of the same name.

    Args:
        name: ``package/executable`` as launch files write it (``turtlesim/turtlesim_node``).
        target: ``"module.path:function"``; ``function(argv: list[str]) -> int | None``.

    Raises:
        BusError: ``name`` or ``target`` is malformed.
    """
    if name.count("/") != 1 or ":" not in target:
        raise BusError(
            f"cannot register node '{name}' -> '{target}'",
            hint="use register_node('package/executable', 'module.path:function')",
        )
    with _LOCK:
        _RUNTIME[name] = target


def declared_nodes() -> dict[str, str]:
    """Every declared ``package/executable`` -> ``module:function`` (installed, then run-time)."""
    found = {point.name: point.value for point in entry_points(group=GROUP)}
    with _LOCK:
        found.update(_RUNTIME)
    return found


def _spellings(package: str, executable: str) -> list[str]:
    bare = executable.removesuffix(".py")
    return [f"{package}/{executable}", f"{package}/{bare}", f"{package}/{bare}.py"]


def find_node(package: str, executable: str) -> str | None:
    """The ``module:function`` declared for ``package/executable`` (with or without ``.py``).

    Returns:
        The entry point's value, or None when no node of that name is declared.
    """
    names = _spellings(package, executable)
    with _LOCK:
        for name in names:
            if name in _RUNTIME:
                return _RUNTIME[name]
    declared = {point.name: point.value for point in entry_points(group=GROUP)}
    for name in names:
        if name in declared:
            return declared[name]
    return None


def unknown_node(package: str, executable: str, *, scripts: bool = False) -> UnknownNodeError:
    """The one-line error for a node that is not declared, listing the known nodes."""
    known = ", ".join(sorted(declared_nodes())) or "none"
    where = " (neither a declared node nor a script)" if scripts else ""
    hint = f"known nodes: {known}"
    if scripts:
        hint += "; scripts are looked for in ./, ./scripts, the package folder and examples/"
    if not _workbench_declares_nodes():
        hint += (
            "; workbench's installed metadata declares no nodes (installed from an older "
            "checkout, or not installed): run `pip install -e .` in the checkout again"
        )
    return UnknownNodeError(f"no node '{executable}' in package '{package}'{where}", hint=hint)


def _workbench_declares_nodes() -> bool:
    """Whether the installed ``workbench`` distribution itself declares nodes."""
    for point in entry_points(group=GROUP):
        dist = getattr(point, "dist", None)
        if dist is not None and dist.metadata["Name"] == "workbench":
            return True
    return False


def load_node(target: str) -> NodeMain:
    """Import the module of ``"module:function"`` and return the function.

    Raises:
        UnknownNodeError: The module or the function does not exist.
    """
    module_name, _, function = target.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        missing = error.name or ""
        if module_name != missing and not module_name.startswith(missing + "."):
            raise  # a dependency of the node is missing, not the node's module
        raise UnknownNodeError(
            f"cannot load node entry point '{target}': no module '{module_name}'",
            hint=_DECLARED_IN,
        ) from None
    main = getattr(module, function, None)
    if main is None:
        raise UnknownNodeError(
            f"cannot load node entry point '{target}': '{module_name}' has no '{function}'",
            hint=_DECLARED_IN,
        )
    if not callable(main):
        raise UnknownNodeError(f"node entry point '{target}' is not a function")
    return main


def call_node(target: str, argv: list[str]) -> int:
    """Load the node ``"module:function"`` and run it with ``argv``; its exit status."""
    return int(load_node(target)(list(argv)) or 0)
