"""The bus: the graph's registry, parameter server, clock, executor and transport.

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
import time
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from workbench.bus.clock import Clock
from workbench.bus.entities import Client, Publisher, ServiceServer, Subscription, Timer
from workbench.bus.errors import BusError, CoreError, ServiceError, TopicTypeError
from workbench.bus.graph import Endpoint, Graph
from workbench.bus.params import ParameterServer

if TYPE_CHECKING:
    from workbench.bus.node import Node

DEFAULT_MASTER_URI = "tcp/127.0.0.1:11311"


def master_uri() -> str:
    """``WORKBENCH_MASTER_URI``, or the default ``tcp/127.0.0.1:11311``."""
    return os.environ.get("WORKBENCH_MASTER_URI") or DEFAULT_MASTER_URI


class Bus:
    """An in-process graph, optionally joined to a core.

    Args:
        threaded: Run callbacks on worker threads (default). ``False``: callbacks run only
            inside :meth:`spin_once`/:meth:`spin_until`/:meth:`spin`.
        workers: Number of worker threads when threaded. Callbacks of one subscription
            never run concurrently; different subscriptions may.
    """

    def __init__(self, threaded: bool = True, workers: int = 4) -> None:
        self.threaded = threaded
        self.clock = Clock()
        self.params: Any = ParameterServer()
        self.uri: str | None = None
        self._workers_wanted = max(1, workers)
        self._lock = threading.RLock()
        self._graph_cond = threading.Condition(self._lock)
        self._nodes: dict[str, Node] = {}
        self._publishers: dict[str, list[Publisher]] = {}
        self._subscriptions: dict[str, tuple[Subscription, ...]] = {}
        self._services: dict[str, ServiceServer] = {}
        self._timers: list[Timer] = []
        self._ready: deque[Any] = deque()
        self._exec_cond = threading.Condition(threading.Lock())
        self._workers: list[threading.Thread] = []
        self._stop_event = threading.Event()
        self._link: Any = None
        self._sim_time_enabled = False

    # --- construction -------------------------------------------------------------------

    @classmethod
    def connect(cls, uri: str | None = None, threaded: bool = True) -> Bus:
        """Join the core at ``uri`` (default :func:`master_uri`).

        Raises:
            CoreError: No core answers at ``uri``.
        """
        bus = cls(threaded=threaded)
        bus._join(uri or master_uri())
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
                    f"no workbench core at {uri}"
                    if isinstance(error, CoreError)
                    else f"cannot join {uri}: {error}"
                )
                _say_once(
                    f"[INFO] {reason}; running in-process "
                    "(start 'workbench core' to connect several processes)"
                )
            return cls(threaded=threaded)

    def _join(self, uri: str) -> None:
        from workbench.bus.transport import ZenohLink

        self._link = ZenohLink(self, uri)
        self.params = self._link.params
        self.uri = uri

    @property
    def is_connected(self) -> bool:
        """Whether this bus is joined to a core."""
        return self._link is not None

    # --- registry -----------------------------------------------------------------------

    def _register_node(self, node: Node) -> None:
        with self._lock:
            old = self._nodes.get(node.name)
            self._nodes[node.name] = node
        if old is not None and old is not node:
            _replace(old)
        if self._link is not None:
            self._link.announce_node(node)
        self._graph_changed()

    def _unregister_node(self, node: Node) -> None:
        with self._lock:
            if self._nodes.get(node.name) is node:
                del self._nodes[node.name]
        if self._link is not None:
            self._link.retract_node(node)
        self._graph_changed()

    def nodes(self) -> list[Node]:
        """The nodes living in this process on this bus."""
        with self._lock:
            return list(self._nodes.values())

    def get_node(self, name: str) -> Node | None:
        with self._lock:
            return self._nodes.get(name)

    def _check_topic_type(self, topic: str, type_: str, md5: str) -> None:
        if md5 == "*":
            return
        ends: list[tuple[str, str, str]] = []
        with self._lock:
            ends += [(p.node.name, p.type, p.md5) for p in self._publishers.get(topic, [])]
            ends += [(s.node.name, s.type, s.md5) for s in self._subscriptions.get(topic, ())]
        if self._link is not None:
            ends += [
                (e.node, e.type, e.md5)
                for e in self._link.remote_endpoints()
                if e.name == topic and e.kind in ("pub", "sub")
            ]
        for node, other_type, other_md5 in ends:
            if other_md5 not in ("*", md5):
                raise TopicTypeError(
                    f"topic {topic} already carries {other_type} (md5 {other_md5}, from {node}); "
                    f"refusing {type_} (md5 {md5})",
                    hint="use the same message type on both ends, or another topic name",
                )

    def _add_publisher(self, pub: Publisher) -> None:
        self._check_topic_type(pub.topic, pub.type, pub.md5)
        with self._lock:
            self._publishers.setdefault(pub.topic, []).append(pub)
        if self._link is not None:
            self._link.advertise(pub)
        self._graph_changed()

    def _remove_publisher(self, pub: Publisher) -> None:
        with self._lock:
            pubs = self._publishers.get(pub.topic, [])
            if pub in pubs:
                pubs.remove(pub)
            if not pubs:
                self._publishers.pop(pub.topic, None)
        if self._link is not None:
            self._link.unadvertise(pub)
        self._graph_changed()

    def _add_subscription(self, sub: Subscription) -> None:
        self._check_topic_type(sub.topic, sub.type, sub.md5)
        with self._lock:
            self._subscriptions[sub.topic] = (*self._subscriptions.get(sub.topic, ()), sub)
            latched = [
                (p, p.last_message)
                for p in self._publishers.get(sub.topic, [])
                if p.latch and p.last_message is not None and sub.md5 in ("*", p.md5)
            ]
        for pub, msg in latched:
            sub._enqueue(pub._raw(msg, self) if sub.raw else msg, pub.node.name)
        if self._link is not None:
            self._link.subscribe(sub)
        self._graph_changed()

    def _remove_subscription(self, sub: Subscription) -> None:
        with self._lock:
            subs = tuple(s for s in self._subscriptions.get(sub.topic, ()) if s is not sub)
            if subs:
                self._subscriptions[sub.topic] = subs
            else:
                self._subscriptions.pop(sub.topic, None)
        if self._link is not None:
            self._link.unsubscribe(sub)
        self._graph_changed()

    def _subscribers_of(self, topic: str) -> tuple[Subscription, ...]:
        return self._subscriptions.get(topic, ())

    def _add_service(self, server: ServiceServer) -> None:
        with self._lock:
            existing = self._services.get(server.name)
            if existing is not None and not existing.closed:
                raise BusError(
                    f"service {server.name} is already offered by {existing.node.name} "
                    "in this process",
                    hint="shut the other server down first, or pick another name",
                )
            self._services[server.name] = server
        if self._link is not None:
            self._link.offer(server)
        self._graph_changed()

    def _remove_service(self, server: ServiceServer) -> None:
        with self._lock:
            if self._services.get(server.name) is server:
                del self._services[server.name]
        if self._link is not None:
            self._link.withdraw(server)
        self._graph_changed()

    def _add_timer(self, timer: Timer) -> None:
        with self._lock:
            self._timers.append(timer)

    def _remove_timer(self, timer: Timer) -> None:
        with self._lock:
            if timer in self._timers:
                self._timers.remove(timer)

    def _graph_changed(self) -> None:
        with self._graph_cond:
            self._graph_cond.notify_all()

    # --- services -----------------------------------------------------------------------

    def _service_available(self, name: str) -> bool:
        with self._lock:
            if name in self._services:
                return True
        return self._link is not None and self._link.has_service(name)

    def _wait_for_service(self, name: str, timeout: float | None) -> bool:
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._graph_cond:
            while not self._service_available(name):
                if self._stop_event.is_set():
                    return False
                remaining = None if deadline is None else deadline - time.monotonic()
                if remaining is not None and remaining <= 0:
                    return False
                self._graph_cond.wait(0.2 if remaining is None else min(remaining, 0.2))
        return True

    def _call_service(self, client: Client, request: Any, timeout: float | None) -> Any:
        with self._lock:
            server = self._services.get(client.name)
        if server is not None and not server.closed:
            if server.md5 != client.md5:
                raise ServiceError(
                    f"service {client.name} is {server.type} (md5 {server.md5}) but the client "
                    f"calls it as {client.type} (md5 {client.md5})"
                )
            return server.handle(request)
        if self._link is not None:
            return self._link.call(client, request, timeout)
        raise ServiceError(
            f"service [{client.name}] unavailable",
            hint="nobody offers it; 'workbench service list' shows the offered services",
        )

    # --- simulated time -----------------------------------------------------------------

    def enable_sim_time(self, node: Node | None = None) -> None:
        """Follow ``/clock`` (rosgraph_msgs/Clock) instead of the wall clock."""
        with self._lock:
            if self._sim_time_enabled:
                return
            self._sim_time_enabled = True
        self.clock.use_sim_time(True)
        owner = node or next(iter(self.nodes()), None)
        if owner is None:
            return
        from workbench.msgs import get_type

        sub = Subscription(
            owner,
            "/clock",
            get_type("rosgraph_msgs/Clock"),
            lambda msg: self.clock.set_time(msg.clock),
            queue_size=1,
            direct=True,
        )
        self._add_subscription(sub)
        owner._subscriptions.append(sub)

    # --- executor -----------------------------------------------------------------------

    def _schedule(self, entity: Any) -> None:
        cond = self._exec_cond
        with cond:
            if entity._scheduled:
                return
            entity._scheduled = True
            self._ready.append(entity)
            cond.notify()
        if self.threaded and len(self._workers) < self._workers_wanted:
            self._start_workers()

    def _start_workers(self) -> None:
        with self._lock:
            while len(self._workers) < self._workers_wanted and not self._stop_event.is_set():
                worker = threading.Thread(
                    target=self._work, name=f"workbench-executor-{len(self._workers)}", daemon=True
                )
                self._workers.append(worker)
                worker.start()

    def _work(self) -> None:
        cond, ready, stop = self._exec_cond, self._ready, self._stop_event
        while True:
            with cond:
                while not ready and not stop.is_set():
                    cond.wait()
                if stop.is_set():
                    return
                entity = ready.popleft()
            self._run(entity, 8)

    def _run(self, entity: Any, budget: int) -> None:
        try:
            entity._execute(budget)
        finally:
            with self._exec_cond:
                if entity._pending():
                    self._ready.append(entity)
                    self._exec_cond.notify()
                else:
                    entity._scheduled = False

    def _poll_timers(self) -> float | None:
        """Stepped mode: schedule due timers; returns seconds until the next one."""
        if self.threaded:
            return None
        with self._lock:
            timers = list(self._timers)
        soonest = None
        now = self.clock.now_ns()
        for timer in timers:
            if timer._poll():
                self._schedule(timer)
            else:
                wait = (timer._next_ns - now) / 1e9
                soonest = wait if soonest is None else min(soonest, wait)
        return soonest

    def spin_once(self, timeout: float = 0.0) -> bool:
        """Run at most one callback, waiting up to ``timeout`` seconds for one.

        Returns:
            Whether a callback ran.
        """
        deadline = time.monotonic() + max(0.0, timeout)
        while True:
            next_timer = self._poll_timers()
            with self._exec_cond:
                if not self._ready:
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        return False
                    wait = remaining if next_timer is None else min(remaining, max(next_timer, 0))
                    if self.clock.is_simulated and self._timers:
                        wait = min(wait, 0.01)
                    self._exec_cond.wait(wait)
                    if not self._ready:
                        continue
                entity = self._ready.popleft()
            self._run(entity, 1)
            return True

    def spin_until(self, predicate: Callable[[], bool], timeout: float | None = None) -> bool:
        """Run callbacks until ``predicate()`` is true.

        Args:
            predicate: Checked before and after every callback.
            timeout: Give up after this many wall seconds (None: never).

        Returns:
            Whether the predicate became true.
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        while not predicate():
            if self._stop_event.is_set():
                return False
            remaining = 0.05 if deadline is None else deadline - time.monotonic()
            if remaining <= 0:
                return bool(predicate())
            self.spin_once(min(remaining, 0.05))
        return True

    def spin(self) -> None:
        """Run callbacks until the bus shuts down (Ctrl-C shuts it down)."""
        try:
            while not self._stop_event.is_set():
                if self.threaded:
                    self._stop_event.wait(0.2)
                else:
                    self.spin_once(0.1)
        except KeyboardInterrupt:
            self.shutdown("keyboard interrupt")

    @property
    def is_shutdown(self) -> bool:
        return self._stop_event.is_set()

    def shutdown(self, reason: str = "bus shut down") -> None:
        """Shut down every node, stop the executor and leave the core.

        What was published is flushed to other processes first (bounded wait); the
        same happens when the interpreter exits without calling this.
        """
        for node in self.nodes():
            node.shutdown(reason)
        self._stop_event.set()
        with self._exec_cond:
            self._exec_cond.notify_all()
        self._graph_changed()
        current = threading.current_thread()
        for worker in self._workers:
            if worker is not current:
                worker.join(timeout=2.0)
        if self._link is not None:
            self._link.close()

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
            _replace(node, reason)
            return
        if self._link is None or name not in self._link.remote_nodes():
            raise BusError(f"unknown node {name}", hint="'workbench node list' shows the nodes")
        self._link.kill(name, reason)

    # --- introspection ------------------------------------------------------------------

    def local_endpoints(self) -> list[Endpoint]:
        with self._lock:
            pubs = [p for ps in self._publishers.values() for p in ps]
            subs = [s for ss in self._subscriptions.values() for s in ss]
            services = list(self._services.values())
        return (
            [Endpoint(p.node.name, "pub", p.topic, p.type, p.md5) for p in pubs]
            + [Endpoint(s.node.name, "sub", s.topic, s.type, s.md5) for s in subs]
            + [Endpoint(s.node.name, "srv", s.name, s.type, s.md5) for s in services]
        )

    def graph(self) -> Graph:
        """Every node, topic and service this bus can see (all processes when joined)."""
        nodes: dict[str, tuple[bool, int | None]] = {
            name: (True, os.getpid()) for name in list(self._nodes)
        }
        endpoints = self.local_endpoints()
        if self._link is not None:
            for name, pid in self._link.remote_nodes().items():
                nodes.setdefault(name, (False, pid))
            endpoints += self._link.remote_endpoints()
        return Graph.from_endpoints(nodes, endpoints)


def _replace(old: Node, reason: str = "new node registered with same name") -> None:
    old.get_logger().warn(f"shutdown request: [{old.name}] Reason: {reason}")
    old.shutdown(reason)


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
