"""The short-lived node a command-line tool uses to look at the graph."""

from __future__ import annotations

import time
from typing import Any

#: Seconds a tool joined to a core waits for the other processes' endpoints to arrive.
DISCOVERY_SECONDS = 0.5


def cli_node(kind: str) -> Any:
    """An anonymous node (``/rostopic_<pid>_<ms>`` style) on the default bus."""
    from workbench.bus import Node

    return Node(kind, anonymous=True, disable_rosout=True)


def settle(bus: Any, predicate=None, timeout: float = DISCOVERY_SECONDS) -> None:
    """Give a joined bus time to learn the graph (until ``predicate()`` holds, if given)."""
    if not getattr(bus, "is_connected", False):
        return
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate is not None and predicate():
            return
        time.sleep(0.02)


def graph(bus: Any) -> Any:
    """The graph as the tool sees it after discovery."""
    settle(bus)
    return bus.graph()
