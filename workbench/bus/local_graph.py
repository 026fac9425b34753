"""The graph of one bus's own endpoints: nodes, publishers, subscriptions, services, timers.

A :class:`LocalGraph` only keeps records; it never delivers anything. The bus
consults it to check topic types, transports read it to deliver messages
(:meth:`LocalGraph.subscription_table`), and the executor reads its timers.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from workbench.bus.errors import BusError
from workbench.bus.graph import Endpoint

if TYPE_CHECKING:
    from workbench.bus.entities import Publisher, ServiceServer, Subscription, Timer
    from workbench.bus.node import Node


class LocalGraph:
    """Thread-safe records of the endpoints living on one bus in this process."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self._changed = threading.Condition(self._lock)
        self._nodes: dict[str, Node] = {}
        self._publishers: dict[str, list[Publisher]] = {}
        # Values are replaced, never mutated, so readers may iterate them without the lock.
        self._subscriptions: dict[str, tuple[Subscription, ...]] = {}
        self._services: dict[str, ServiceServer] = {}
        self._timers: list[Timer] = []

    # --- nodes --------------------------------------------------------------------------

    def add_node(self, node: Node) -> Node | None:
        """Record ``node``; returns the node it displaces (same global name), if any."""
        with self._lock:
            old = self._nodes.get(node.name)
            self._nodes[node.name] = node
        return old if old is not node else None

    def remove_node(self, node: Node) -> None:
        with self._lock:
            if self._nodes.get(node.name) is node:
                del self._nodes[node.name]

    def nodes(self) -> list[Node]:
        with self._lock:
            return list(self._nodes.values())

    def get_node(self, name: str) -> Node | None:
        with self._lock:
            return self._nodes.get(name)

    # --- topics -------------------------------------------------------------------------

    def add_publisher(self, pub: Publisher) -> None:
        with self._lock:
            self._publishers.setdefault(pub.topic, []).append(pub)

    def remove_publisher(self, pub: Publisher) -> None:
        with self._lock:
            pubs = self._publishers.get(pub.topic, [])
            if pub in pubs:
                pubs.remove(pub)
            if not pubs:
                self._publishers.pop(pub.topic, None)

    def publishers_of(self, topic: str) -> list[Publisher]:
        with self._lock:
            return list(self._publishers.get(topic, ()))

    def add_subscription(self, sub: Subscription) -> None:
        with self._lock:
            self._subscriptions[sub.topic] = (*self._subscriptions.get(sub.topic, ()), sub)

    def remove_subscription(self, sub: Subscription) -> None:
        with self._lock:
            subs = tuple(s for s in self._subscriptions.get(sub.topic, ()) if s is not sub)
            if subs:
                self._subscriptions[sub.topic] = subs
            else:
                self._subscriptions.pop(sub.topic, None)

    def subscribers_of(self, topic: str) -> tuple[Subscription, ...]:
        """The subscriptions of ``topic`` (a snapshot; no lock needed)."""
        return self._subscriptions.get(topic, ())

    def subscription_table(self) -> dict[str, tuple[Subscription, ...]]:
        """The live topic -> subscriptions mapping, for a transport's delivery hot path.

        Read it only (``table.get(topic, ())``): each value is a tuple that is replaced,
        never changed, when a subscription comes or goes.
        """
        return self._subscriptions

    def topic_ends(self, topic: str) -> list[tuple[str, str, str]]:
        """``(node, type, md5)`` of every local publisher and subscription of ``topic``."""
        with self._lock:
            ends = [(p.node.name, p.type, p.md5) for p in self._publishers.get(topic, [])]
            ends += [(s.node.name, s.type, s.md5) for s in self._subscriptions.get(topic, ())]
        return ends

    # --- services -----------------------------------------------------------------------

    def add_service(self, server: ServiceServer) -> None:
        """Record ``server``.

        Raises:
            BusError: Another open server of this process offers the same name.
        """
        with self._lock:
            existing = self._services.get(server.name)
            if existing is not None and not existing.closed:
                raise BusError(
                    f"service {server.name} is already offered by {existing.node.name} "
                    "in this process",
                    hint="shut the other server down first, or pick another name",
                )
            self._services[server.name] = server

    def remove_service(self, server: ServiceServer) -> None:
        with self._lock:
            if self._services.get(server.name) is server:
                del self._services[server.name]

    def get_service(self, name: str) -> ServiceServer | None:
        with self._lock:
            return self._services.get(name)

    # --- timers -------------------------------------------------------------------------

    def add_timer(self, timer: Timer) -> None:
        with self._lock:
            self._timers.append(timer)

    def remove_timer(self, timer: Timer) -> None:
        with self._lock:
            if timer in self._timers:
                self._timers.remove(timer)

    def timers(self) -> list[Timer]:
        with self._lock:
            return list(self._timers)

    # --- changes ------------------------------------------------------------------------

    def notify_changed(self) -> None:
        """Wake everyone waiting in :meth:`wait_for`."""
        with self._changed:
            self._changed.notify_all()

    def wait_for(
        self, predicate: Callable[[], bool], timeout: float | None, stop: threading.Event
    ) -> bool:
        """Wait until ``predicate()`` holds, re-checking on every graph change.

        Returns:
            Whether it holds (``False`` on timeout or when ``stop`` is set).
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._changed:
            while not predicate():
                if stop.is_set():
                    return False
                remaining = None if deadline is None else deadline - time.monotonic()
                if remaining is not None and remaining <= 0:
                    return False
                self._changed.wait(0.2 if remaining is None else min(remaining, 0.2))
        return True

    # --- introspection ------------------------------------------------------------------

    def endpoints(self) -> list[Endpoint]:
        with self._lock:
            pubs = [p for ps in self._publishers.values() for p in ps]
            subs = [s for ss in self._subscriptions.values() for s in ss]
            services = list(self._services.values())
        return (
            [Endpoint(p.node.name, "pub", p.topic, p.type, p.md5) for p in pubs]
            + [Endpoint(s.node.name, "sub", s.topic, s.type, s.md5) for s in subs]
            + [Endpoint(s.node.name, "srv", s.name, s.type, s.md5) for s in services]
        )
