"""The interface between a bus and what carries its messages: :class:`Transport`.

A :class:`~workbench.bus.Bus` keeps the graph of its own endpoints and runs
callbacks; transports move messages, service calls and graph changes. Every
bus has the in-process transport
(:class:`~workbench.bus.inprocess.InProcessTransport`: delivery between the
nodes of this process, latched replay, local services); ``Bus.connect`` adds
the Zenoh transport (:class:`~workbench.bus.zenoh_transport.ZenohTransport`)
for other processes and machines. A transport of your own implements this
protocol and is added with :meth:`Bus.attach <workbench.bus.Bus.attach>`.

Rules a transport follows:

- It hands incoming messages to subscriptions with ``Subscription.deliver(msg,
  callerid)`` (a :class:`~workbench.bus.RawMessage` for ``sub.raw``), reading
  the subscriptions of a topic from ``bus.local.subscribers_of(topic)``; the
  executor does the rest.
- It tells the bus about remote graph changes with ``bus.graph_changed()``.
- It never lets an exception escape a thread it owns: it logs a line naming the
  topic, service or node, and keeps going.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

if TYPE_CHECKING:
    from workbench.bus.entities import Client, Publisher, ServiceServer, Subscription
    from workbench.bus.graph import Endpoint
    from workbench.bus.node import Node
    from workbench.msgs import Message

#: What :meth:`Transport.advertise` returns: called once per published message.
Sender = Callable[["Message"], None]


@runtime_checkable
class Transport(Protocol):
    """What a bus needs from a transport.

    Attributes:
        params: The parameter server reached through this transport (``get``, ``set``,
            ``has``, ``delete``, ``names``, ``search``, ``snapshot``, as
            :class:`~workbench.bus.params.ParameterServer`). The bus uses the one of
            the last transport attached.
    """

    params: Any

    def announce_node(self, node: Node) -> None:
        """A node joined the bus."""
        ...

    def retract_node(self, node: Node) -> None:
        """A node left the bus."""
        ...

    def advertise(self, pub: Publisher) -> Sender | None:
        """A publisher appeared; return the function that sends its messages (or ``None``).

        The sender runs in the publishing thread for every message: keep it lean.
        """
        ...

    def unadvertise(self, pub: Publisher) -> None:
        """A publisher closed (its sender is no longer called)."""
        ...

    def subscribe(self, sub: Subscription) -> None:
        """A subscription appeared: deliver its topic's messages, and latched ones now."""
        ...

    def unsubscribe(self, sub: Subscription) -> None:
        """A subscription closed."""
        ...

    def offer(self, server: ServiceServer) -> None:
        """A service server appeared: route calls of its name to ``server.handle``."""
        ...

    def withdraw(self, server: ServiceServer) -> None:
        """A service server closed."""
        ...

    def has_service(self, name: str) -> bool:
        """Whether a call of ``name`` through this transport would find a server."""
        ...

    def call(self, client: Client, request: Any, timeout: float | None) -> Any:
        """Call ``client.name`` with ``request``; returns the response.

        Raises:
            ServiceError: No server, type mismatch, or the handler failed.
            ServiceTimeout: No response within ``timeout`` seconds.
        """
        ...

    def remote_nodes(self) -> dict[str, int]:
        """Nodes reached through this transport that are not on this bus: name -> pid."""
        ...

    def remote_endpoints(self) -> list[Endpoint]:
        """Publishers, subscribers and servers reached through this transport, not on this bus."""
        ...

    def kill(self, name: str, reason: str) -> None:
        """Ask the remote node ``name`` to shut down."""
        ...

    def flush(self, topics: Iterable[str] | None = None, timeout: float | None = None) -> bool:
        """Wait (bounded) until what was published on ``topics`` has reached its subscribers.

        Returns:
            Whether every subscriber confirmed in time.
        """
        ...

    def close(self) -> None:
        """Flush, then release everything (idempotent)."""
        ...
