"""The in-process transport: delivery, latched replay and services between local nodes.

Messages are handed over as objects (no serialization unless a subscription
asks for raw bytes); delivery queues them on the subscriptions, and the
executor runs the callbacks.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from workbench.bus.errors import ServiceError
from workbench.bus.params import ParameterServer

if TYPE_CHECKING:
    from workbench.bus.entities import Client, Publisher, ServiceServer, Subscription
    from workbench.bus.graph import Endpoint
    from workbench.bus.local_graph import LocalGraph
    from workbench.bus.node import Node
    from workbench.bus.transport import Sender
    from workbench.msgs import Message


class InProcessTransport:
    """The embedded default :class:`~workbench.bus.transport.Transport` of every bus.

    Args:
        graph: The bus's local graph (who subscribes, who publishes latched, who serves).
    """

    def __init__(self, graph: LocalGraph) -> None:
        self.params: Any = ParameterServer()
        self._graph = graph

    # --- topics -------------------------------------------------------------------------

    def advertise(self, pub: Publisher) -> Sender:
        get = self._graph.subscription_table().get
        topic, md5, callerid = pub.topic, pub.md5, pub.node.name
        to_raw = pub.to_raw

        def deliver(msg: Message) -> None:
            subs = get(topic)
            if subs:
                raw = None
                for sub in subs:
                    if sub.md5 == md5 or sub.md5 == "*":
                        if sub.raw:  # messages here are objects: serialize once for all
                            if raw is None:
                                raw = to_raw(msg)
                            sub.deliver(raw, callerid)
                        else:
                            sub.deliver(msg, callerid)

        return deliver

    def unadvertise(self, pub: Publisher) -> None:
        """Nothing to release: the bus stops calling the sender."""

    def subscribe(self, sub: Subscription) -> None:
        """Replay the last message of every latched local publisher of the topic."""
        for pub in self._graph.publishers_of(sub.topic):
            msg = pub.last_message
            if pub.latch and msg is not None and sub.md5 in ("*", pub.md5):
                sub.deliver(pub.to_raw(msg) if sub.raw else msg, pub.node.name)

    def unsubscribe(self, sub: Subscription) -> None:
        """Nothing to release: the local graph no longer lists it."""

    # --- services -----------------------------------------------------------------------

    def offer(self, server: ServiceServer) -> None:
        """Nothing to declare: calls find the server in the local graph."""

    def withdraw(self, server: ServiceServer) -> None:
        """Nothing to release."""

    def has_service(self, name: str) -> bool:
        server = self._graph.get_service(name)
        return server is not None and not server.closed

    def call(self, client: Client, request: Any, timeout: float | None) -> Any:
        server = self._graph.get_service(client.name)
        if server is None or server.closed:
            raise ServiceError(
                f"service [{client.name}] unavailable",
                hint="nobody offers it; 'workbench service list' shows the offered services",
            )
        if server.md5 != client.md5:
            raise ServiceError(
                f"service {client.name} is {server.type} (md5 {server.md5}) but the client "
                f"calls it as {client.type} (md5 {client.md5})"
            )
        return server.handle(request)

    # --- graph --------------------------------------------------------------------------

    def announce_node(self, node: Node) -> None:
        """Nothing to announce beyond the local graph."""

    def retract_node(self, node: Node) -> None:
        """Nothing to retract beyond the local graph."""

    def remote_nodes(self) -> dict[str, int]:
        return {}

    def remote_endpoints(self) -> list[Endpoint]:
        return []

    def kill(self, name: str, reason: str) -> None:
        """No remote nodes here (the bus shuts local nodes down itself)."""

    def flush(self, topics: Iterable[str] | None = None, timeout: float | None = None) -> bool:
        return True  # delivery here is immediate

    def close(self) -> None:
        """Nothing to release."""
