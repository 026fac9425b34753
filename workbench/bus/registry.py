"""The bus's view of the runnable nodes: ``package/executable`` -> ``module:function``.

Nodes are declared as entry points of the ``workbench.nodes`` group (see
:mod:`workbench.entry_points`, which reads them with
``importlib.metadata.entry_points(group="workbench.nodes")``; it sits below the
bus so that ``workbench run`` looks a node up without importing the bus). This
module keeps the bus-side names launch code and older scripts use.
"""

from __future__ import annotations

from workbench.entry_points import (
    GROUP,
    NodeMain,
    UnknownNodeError,
    call_node,
    declared_nodes,
    find_node,
    load_node,
    register_node,
    unknown_node,
)


def registered_nodes() -> dict[str, str]:
    """Every declared ``package/executable`` -> ``module:function``."""
    return declared_nodes()


def entry_point(package: str, executable: str) -> str:
    """The ``module:function`` declared for ``package/executable`` (``.py`` optional).

    Raises:
        UnknownNodeError: No such node is declared (the message lists the known ones).
    """
    target = find_node(package, executable)
    if target is None:
        raise unknown_node(package, executable)
    return target


def load(target: str) -> NodeMain:
    """Import and return the function named by ``"module:function"``."""
    return load_node(target)


__all__ = [
    "GROUP",
    "NodeMain",
    "UnknownNodeError",
    "call_node",
    "declared_nodes",
    "entry_point",
    "find_node",
    "load",
    "load_node",
    "register_node",
    "registered_nodes",
    "unknown_node",
]
