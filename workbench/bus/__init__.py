"""Nodes, topics, services and parameters, in one process or across several.

ROS 1 semantics with ROS 2-like ergonomics::

    from workbench.bus import Bus, Node
    from workbench.msgs.std_msgs import String

    bus = Bus()                                   # in-process; Bus.connect() joins a core
    talker, listener = Node("talker", bus=bus), Node("listener", bus=bus)
    pub = talker.create_publisher("chatter", String)
    listener.create_subscription("chatter", String, lambda m: print(m.data))
    pub.publish(String(data="hello world"))

Nothing is created at import time; :func:`default_bus` builds the process-wide
bus on first use (joining a ``workbench core`` when one is reachable).
"""

from __future__ import annotations

from typing import Any

from workbench.bus.bus import DEFAULT_MASTER_URI, Bus, default_bus, master_uri, set_default_bus
from workbench.bus.entities import (
    AnyMsg,
    Client,
    Publisher,
    Rate,
    RawMessage,
    ServiceServer,
    Subscription,
    Timer,
    TimerEvent,
    connection_header,
)
from workbench.bus.errors import (
    BusError,
    CoreError,
    InvalidNameError,
    ParameterError,
    ServiceError,
    ServiceTimeout,
    ShutdownError,
    ShutdownInterrupt,
    TopicTypeError,
)
from workbench.bus.graph import Endpoint, Graph, NodeRecord, ServiceRecord, TopicRecord
from workbench.bus.node import Node

__all__ = [
    "DEFAULT_MASTER_URI",
    "AnyMsg",
    "Bus",
    "BusError",
    "Client",
    "CoreError",
    "Duration",
    "Endpoint",
    "Graph",
    "InvalidNameError",
    "Node",
    "NodeRecord",
    "ParameterError",
    "Publisher",
    "Rate",
    "RawMessage",
    "ServiceError",
    "ServiceRecord",
    "ServiceServer",
    "ServiceTimeout",
    "ShutdownError",
    "ShutdownInterrupt",
    "Subscription",
    "Time",
    "Timer",
    "TimerEvent",
    "TopicRecord",
    "TopicTypeError",
    "connection_header",
    "default_bus",
    "master_uri",
    "set_default_bus",
]


def __getattr__(name: str) -> Any:
    if name in ("Time", "Duration"):
        import workbench.msgs

        return getattr(workbench.msgs, name)
    raise AttributeError(f"module 'workbench.bus' has no attribute '{name}'")
