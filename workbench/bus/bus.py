"""The bus: the graph of local endpoints, parameter server, clock, executor and transports.

A :class:`Bus` on its own is an in-process graph (no daemon, nothing on the
network). ``Bus.connect(uri)`` joins a ``workbench core`` over Zenoh so nodes
in several processes see each other; ``Bus.auto()`` joins one if reachable and
otherwise stays in-process, saying so once.

Callbacks run on an executor: threaded by default (a few worker threads, so a
script's main loop can publish while callbacks run), or stepped by hand with
``Bus(threaded=False)`` and :meth:`Bus.spin_once` / :meth:`Bus.spin_until`
for deterministic tests and notebooks.
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from workbench.bus.clock import Clock
from workbench.bus.errors import BusError, CoreError, ServiceError, TopicTypeError
from workbench.bus.executor import Executor
from workbench.bus.graph import Endpoint, Graph
from workbench.bus.inprocess import InProcessTransport
from workbench.bus.local_graph import LocalGraph

if TYPE_CHECKING:
    from workbench.bus.entities import Client, Publisher, ServiceServer, Subscription, Timer
    from workbench.bus.node import Node
    from workbench.bus.transport import Transport

DEFAULT_MASTER_URI = "tcp/127.0.0.1:11311"


def master_uri() -> str:
    """``WORKBENCH_MASTER_URI``, or the default ``tcp/127.0.0.1:11311``."""
    return os.environ.get("WORKBENCH_MASTER_URI") or DEFAULT_MASTER_URI


class Bus:
    """An in-process graph, optionally joined to a core.

    A bus is three parts: :attr:`local` (the graph of its own nodes and endpoints),
    :attr:`executor` (runs callbacks) and its :attr:`transports` (the in-process one,
    plus Zenoh when joined to a core; see :class:`~workbench.bus.transport.Transport`).

    Args:
        threaded: Run callbacks on worker threads (default). ``False``: callbacks run only
            inside :meth:`spin_once`/:meth:`spin_until`/:meth:`spin`.
        workers: Number of worker threads when threaded. Callbacks of one subscription
            never run concurrently; different subscriptions may.
    """

    def __init__(self, threaded: bool = True, workers: int = 4) -> None:
        self.threaded = threaded
        self.clock = Clock()
        self.uri: str | None = None
        self.local = LocalGraph()
        inproc = InProcessTransport(self.local)
        self.params: Any = inproc.params
        self.transports: tuple[Transport, ...] = (inproc,)
        self._remote: Transport | None = None
        self._stop = threading.Event()
        self.executor = Executor(threaded, workers, self.clock, self.local.timers, self._stop)
        self._sim_lock = threading.Lock()
        self._sim_time_enabled = False

    # --- construction -------------------------------------------------------------------

    @classmethod
    def connect(cls, uri: str | None = None, threaded: bool = True) -> Bus:
        """Join the core at ``uri`` (default :func:`master_uri`).

        Raises:
            CoreError: No core answers at ``uri``.
        """
        from workbench.bus.zenoh_transport import ZenohTransport

        bus = cls(threaded=threaded)
        uri = uri or master_uri()
        bus.attach(ZenohTransport(bus, uri), uri)
        return bus

    @classmethod
    def auto(cls, uri: str | None = None, threaded: bool = True, quiet: bool = False) -> Bus:
        """Join a core if one is reachable, else run in-process (and say so once).

        ``WORKBENCH_MASTER_URI=inproc`` forces an in-process bus.
        """
        uri = uri or master_uri()
        if uri in ("inproc", "none"):
            return cls(threaded=threaded)
        from workbench.bus.zconfig import parse_uri

        parse_uri(uri)  # a malformed address is an error, not "no core"
        try:
            return cls.connect(uri, threaded=threaded)
        except (CoreError, ImportError) as error:
            if not quiet:
                reason = (
                    error.message  # "no workbench core at URI", or why the one there failed
                    if isinstance(error, CoreError)
                    else f"cannot join {uri}: {error}"
                )
                _say_once(
                    f"[INFO] {reason}; running in-process "
                    "(start 'workbench core' to connect several processes)"
                )
            return cls(threaded=threaded)

    def attach(self, transport: Transport, uri: str | None = None) -> None:
        """Add a transport to other processes (before any node joins); its params win.

        Raises:
            BusError: The bus already has nodes, or already has a remote transport.
        """
        if self._remote is not None or self.local.nodes():
            raise BusError(
                "attach a transport to a fresh bus, before any node joins it",
                hint="create the bus, attach, then create the nodes",
            )
        self._remote = transport
        self.transports = (*self.transports, transport)
        self.params = transport.params
        self.uri = uri

    @property
    def is_connected(self) -> bool:
        """Whether this bus is joined to a core (has a transport to other processes)."""
        return self._remote is not None

    @property
    def remote(self) -> Transport | None:
        """The transport to other processes (Zenoh when joined to a core), or ``None``."""
        return self._remote

    # --- registry (called by nodes and entities) ----------------------------------------

    def register_node(self, node: Node) -> None:
        """Add ``node``; an older node with its name is shut down (as in ROS)."""
        old = self.local.add_node(node)
        if old is not None:
            self.replace_node(old)
        for transport in self.transports:
            transport.announce_node(node)
        self.graph_changed()

    def unregister_node(self, node: Node) -> None:
        self.local.remove_node(node)
        for transport in self.transports:
            transport.retract_node(node)
        self.graph_changed()

    def replace_node(self, node: Node, reason: str = "new node registered with same name") -> None:
        """Shut ``node`` down with ROS's warning (a newer node took its name, or a kill)."""
        node.get_logger().warn(f"shutdown request: [{node.name}] Reason: {reason}")
        node.shutdown(reason)

    def nodes(self) -> list[Node]:
        """The nodes living in this process on this bus."""
        return self.local.nodes()

    def get_node(self, name: str) -> Node | None:
        return self.local.get_node(name)

    def check_topic_type(self, topic: str, type_: str, md5: str) -> None:
        """Refuse a second message type on ``topic``.

        Raises:
            TopicTypeError: Some endpoint (here or remote) uses another type on ``topic``.
        """
        if md5 == "*":
            return
        ends = self.local.topic_ends(topic)
        for transport in self.transports:
            ends += [
                (e.node, e.type, e.md5)
                for e in transport.remote_endpoints()
                if e.name == topic and e.kind in ("pub", "sub")
            ]
        for node, other_type, other_md5 in ends:
            if other_md5 not in ("*", md5):
                raise TopicTypeError(
                    f"topic {topic} already carries {other_type} (md5 {other_md5}, from {node}); "
                    f"refusing {type_} (md5 {md5})",
                    hint="use the same message type on both ends, or another topic name",
                )

    def add_publisher(self, pub: Publisher) -> None:
        """Register ``pub`` and connect it to every transport."""
        self.check_topic_type(pub.topic, pub.type, pub.md5)
        self.local.add_publisher(pub)
        senders = [transport.advertise(pub) for transport in self.transports]
        pub.set_senders(tuple(send for send in senders if send is not None))
        self.graph_changed()

    def remove_publisher(self, pub: Publisher) -> None:
        pub.set_senders(())
        self.local.remove_publisher(pub)
        for transport in self.transports:
            transport.unadvertise(pub)
        self.graph_changed()

    def add_subscription(self, sub: Subscription) -> None:
        """Register ``sub``; latched messages are delivered to it now."""
        self.check_topic_type(sub.topic, sub.type, sub.md5)
        self.local.add_subscription(sub)
        for transport in self.transports:
            transport.subscribe(sub)
        self.graph_changed()

    def remove_subscription(self, sub: Subscription) -> None:
        self.local.remove_subscription(sub)
        for transport in self.transports:
            transport.unsubscribe(sub)
        self.graph_changed()

    def add_service(self, server: ServiceServer) -> None:
        """Register ``server``.

        Raises:
            BusError: This process already offers the name.
        """
        self.local.add_service(server)
        for transport in self.transports:
            transport.offer(server)
        self.graph_changed()

    def remove_service(self, server: ServiceServer) -> None:
        self.local.remove_service(server)
        for transport in self.transports:
            transport.withdraw(server)
        self.graph_changed()

    def add_timer(self, timer: Timer) -> None:
        self.local.add_timer(timer)

    def remove_timer(self, timer: Timer) -> None:
        self.local.remove_timer(timer)

    def graph_changed(self) -> None:
        """Wake waiters on the graph (a transport calls it when remote endpoints change)."""
        self.local.notify_changed()

    # --- services -----------------------------------------------------------------------

    def service_available(self, name: str) -> bool:
        """Whether some transport reaches a server of ``name``."""
        return any(transport.has_service(name) for transport in self.transports)

    def wait_for_service(self, name: str, timeout: float | None = None) -> bool:
        """Wait until ``name`` is offered.

        Returns:
            Whether it is (``False`` after ``timeout`` seconds or on shutdown).
        """
        return self.local.wait_for(lambda: self.service_available(name), timeout, self._stop)

    def call_service(self, client: Client, request: Any, timeout: float | None) -> Any:
        """Call ``client``'s service through the first transport that reaches a server.

        Raises:
            ServiceError: Nobody offers it, the types differ, or the handler raised.
            ServiceTimeout: No response within ``timeout`` seconds.
        """
        for transport in self.transports:
            if transport.has_service(client.name):
                return transport.call(client, request, timeout)
        if self._remote is not None:  # let the remote transport say why (it may know)
            return self._remote.call(client, request, timeout)
        raise ServiceError(
            f"service [{client.name}] unavailable",
            hint="nobody offers it; 'workbench service list' shows the offered services",
        )

    def flush(self, topics: Iterable[str] | None = None) -> bool:
        """Wait (bounded) until subscribers in other processes have what was published.

        Returns:
            Whether every subscriber confirmed in time.
        """
        wanted = None if topics is None else list(topics)
        return all([transport.flush(wanted) for transport in self.transports])

    # --- simulated time -----------------------------------------------------------------

    def enable_sim_time(self, node: Node | None = None) -> None:
        """Follow ``/clock`` (rosgraph_msgs/Clock) instead of the wall clock."""
        with self._sim_lock:
            if self._sim_time_enabled:
                return
            self._sim_time_enabled = True
        self.clock.use_sim_time(True)
        owner = node or next(iter(self.nodes()), None)
        if owner is None:
            return
        clock = self.clock
        owner.create_subscription(
            "/clock",
            "rosgraph_msgs/Clock",
            lambda msg: clock.set_time(msg.clock),
            queue_size=1,
            inline=True,
        )

    # --- executor -----------------------------------------------------------------------

    def spin_once(self, timeout: float = 0.0) -> bool:
        """Run at most one callback, waiting up to ``timeout`` seconds for one.

        Returns:
            Whether a callback ran.
        """
        return self.executor.spin_once(timeout)

    def spin_until(self, predicate: Callable[[], bool], timeout: float | None = None) -> bool:
        """Run callbacks until ``predicate()`` is true.

        Args:
            predicate: Checked before and after every callback.
            timeout: Give up after this many wall seconds (None: never).

        Returns:
            Whether the predicate became true.
        """
        return self.executor.spin_until(predicate, timeout)

    def spin(self) -> None:
        """Run callbacks until the bus shuts down (Ctrl-C shuts it down)."""
        try:
            while not self._stop.is_set():
                if self.threaded:
                    self._stop.wait(0.2)
                else:
                    self.spin_once(0.1)
        except KeyboardInterrupt:
            self.shutdown("keyboard interrupt")

    @property
    def is_shutdown(self) -> bool:
        return self._stop.is_set()

    @property
    def shutdown_event(self) -> threading.Event:
        """Set when the bus shuts down (pass it to ``Clock.sleep`` to be woken)."""
        return self._stop

    def shutdown(self, reason: str = "bus shut down") -> None:
        """Shut down every node, stop the executor and leave the core.

        What was published is flushed to other processes first (bounded wait); the
        same happens when the interpreter exits without calling this.
        """
        for node in self.nodes():
            node.shutdown(reason)
        self._stop.set()
        self.executor.stop()
        self.graph_changed()
        for transport in reversed(self.transports):
            transport.close()

    def __enter__(self) -> Bus:
        return self

    def __exit__(self, *exc: object) -> None:
        self.shutdown()

    def kill_node(self, name: str, reason: str = "user request") -> None:
        """Ask the node called ``name`` (in any process) to shut down (``rosnode kill``).

        Raises:
            BusError: No such node is known.
        """
        node = self.get_node(name)
        if node is not None:
            self.replace_node(node, reason)
            return
        for transport in self.transports:
            if name in transport.remote_nodes():
                transport.kill(name, reason)
                return
        raise BusError(f"unknown node {name}", hint="'workbench node list' shows the nodes")

    # --- introspection ------------------------------------------------------------------

    def local_endpoints(self) -> list[Endpoint]:
        return self.local.endpoints()

    def graph(self) -> Graph:
        """Every node, topic and service this bus can see (all processes when joined)."""
        pid = os.getpid()
        nodes: dict[str, tuple[bool, int | None]] = {
            node.name: (True, pid) for node in self.local.nodes()
        }
        endpoints = self.local.endpoints()
        for transport in self.transports:
            for name, remote_pid in transport.remote_nodes().items():
                nodes.setdefault(name, (False, remote_pid))
            endpoints += transport.remote_endpoints()
        return Graph.from_endpoints(nodes, endpoints)


_SAID: set[str] = set()


def _say_once(text: str) -> None:
    if text not in _SAID:
        _SAID.add(text)
        print(text, file=sys.stderr, flush=True)


_DEFAULT: Bus | None = None
_DEFAULT_LOCK = threading.Lock()


def default_bus() -> Bus:
    """The process-wide bus (created on first use with :meth:`Bus.auto`)."""
    global _DEFAULT
    with _DEFAULT_LOCK:
        if _DEFAULT is None or _DEFAULT.is_shutdown:
            _DEFAULT = Bus.auto()
        return _DEFAULT


def set_default_bus(bus: Bus | None) -> None:
    """Make ``bus`` the process-wide bus (``None``: create a new one on next use)."""
    global _DEFAULT
    with _DEFAULT_LOCK:
        _DEFAULT = bus
