"""Nodes: named participants of the graph that own publishers, services and timers."""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from workbench.bus.bus import default_bus
from workbench.bus.entities import (
    AnyMsg,
    Client,
    Publisher,
    Rate,
    ServiceServer,
    Subscription,
    Timer,
)
from workbench.bus.errors import ShutdownError
from workbench.bus.logger import Logger
from workbench.bus.names import (
    anonymous_name,
    canonical_namespace,
    check_base_name,
    join,
    parse_command_line,
    resolve,
)
from workbench.errors import MessageError
from workbench.msgs import Message, get_type, is_service

if TYPE_CHECKING:
    from workbench.bus.bus import Bus

_UNSET: Any = object()


def _message_class(data_class: Any, what: str) -> Any:
    if isinstance(data_class, str):
        if data_class in ("*", "AnyMsg"):
            return AnyMsg
        data_class = get_type(data_class)
    if data_class is AnyMsg:
        return data_class
    if not (isinstance(data_class, type) and issubclass(data_class, Message)):
        raise MessageError(
            f"{what} needs a message class or type name, not {data_class!r}",
            hint="e.g. workbench.msgs.std_msgs.String or 'std_msgs/String'",
        )
    return data_class


def _keep_open(entities: list[Any]) -> None:
    """Drop the closed ones from a node's list (a node that makes and closes endpoints all
    day, such as a rosserial host serving device after device, keeps only the open ones);
    looked at every 64 additions, so that making many endpoints stays linear."""
    if len(entities) % 64 == 63:
        entities[:] = [entity for entity in entities if not entity.closed]


def _service_class(service_class: Any) -> Any:
    if isinstance(service_class, str):
        service_class = get_type(service_class)
    if not is_service(service_class):
        raise MessageError(
            f"{getattr(service_class, '_type', service_class)!s} is not a service type",
            hint="e.g. workbench.msgs.std_srvs.Trigger or 'std_srvs/Trigger'",
        )
    return service_class


class Node:
    """A node on a bus.

    Args:
        name: Base name (``talker``); no namespace (use ``namespace=`` or ``__ns:=``).
        bus: The bus to join; ``None`` uses :func:`~workbench.bus.default_bus`.
        namespace: The node's namespace (``/``, ``robot1``).
        anonymous: Append ``_<pid>_<ms>`` so several copies can run.
        argv: Command-line arguments to read ROS remappings from (``chatter:=/x``,
            ``__name:=``, ``__ns:=``, ``_param:=value``); ``None`` reads none.
        log_level: Lowest level printed (``debug``, ``info``, ``warn``, ``error``).
        disable_rosout: Do not publish log messages on ``/rosout``.

    A node with the same global name as an existing one replaces it: the older
    node is shut down, as in ROS.
    """

    def __init__(
        self,
        name: str,
        bus: Bus | None = None,
        namespace: str | None = None,
        anonymous: bool = False,
        argv: Sequence[str] | None = None,
        log_level: str = "info",
        disable_rosout: bool = False,
    ) -> None:
        self.bus = bus if bus is not None else default_bus()
        command = parse_command_line(list(argv or []))
        base = check_base_name(command.node_name or name)
        if anonymous and command.node_name is None:
            base = anonymous_name(base)
        self.namespace = canonical_namespace(command.namespace or namespace)
        self.name = join(self.namespace, base)
        self.base_name = base
        self.argv = command.others
        self._remap: dict[str, str] = {}
        for source, target in command.remappings.items():
            self._remap[resolve(source, self.namespace, self.name)] = resolve(
                target, self.namespace, self.name
            )
        self._lock = threading.RLock()
        self._publishers: list[Publisher] = []
        self._subscriptions: list[Subscription] = []
        self._services: list[ServiceServer] = []
        self._timers: list[Timer] = []
        self._shutdown_hooks: list[Callable[..., Any]] = []
        self.is_shutdown = False
        self.shutdown_reason = ""
        self._logger = Logger(self, log_level)
        self.bus.register_node(self)
        for key, value in command.params.items():
            self.set_param("~" + key, value)
        self._rosout: Publisher | None = None
        if not disable_rosout:
            self._rosout = self.create_publisher("/rosout", "rosgraph_msgs/Log", queue_size=100)
        if self.bus.params.has("/use_sim_time") and self.bus.params.get("/use_sim_time") is True:
            self.bus.enable_sim_time(self)

    # --- names --------------------------------------------------------------------------

    def resolve_name(self, name: str, what: str = "name") -> str:
        """Resolve ``name`` (relative, ``~private`` or global) and apply remappings."""
        resolved = resolve(name, self.namespace, self.name, what)
        return self._remap.get(resolved, resolved)

    # --- entities -----------------------------------------------------------------------

    def _check_alive(self) -> None:
        if self.is_shutdown:
            raise ShutdownError(f"node {self.name} has shut down ({self.shutdown_reason})")

    def create_publisher(
        self, topic: str, msg_type: Any, queue_size: int | None = 10, latch: bool = False
    ) -> Publisher:
        """Advertise a topic.

        Args:
            topic: Topic name (resolved against the node's namespace, remapped).
            msg_type: Message class or type name (``"geometry_msgs/Twist"``).
            queue_size: Kept for rospy parity; in-process publishing never blocks.
            latch: Send the last message to subscribers that connect later.

        Raises:
            TopicTypeError: The topic already carries another type.
        """
        self._check_alive()
        cls = _message_class(msg_type, "create_publisher")
        if cls is AnyMsg:
            raise MessageError("a publisher needs a concrete message type")
        pub = Publisher(self, self.resolve_name(topic, "topic name"), cls, queue_size, latch)
        self.bus.add_publisher(pub)
        with self._lock:
            _keep_open(self._publishers)
            self._publishers.append(pub)
        return pub

    def create_subscription(
        self,
        topic: str,
        msg_type: Any,
        callback: Callable[..., Any] | None,
        queue_size: int | None = 10,
        callback_args: Any = None,
        inline: bool = False,
        raw: bool = False,
    ) -> Subscription:
        """Subscribe to a topic.

        Args:
            topic: Topic name.
            msg_type: Message class, type name, or ``AnyMsg``/``"*"`` for any type.
            callback: ``callback(msg)``, or ``callback(msg, callback_args)``.
            queue_size: Messages kept while the callback is busy; the oldest is dropped
                when full (``None`` or 0: unbounded).
            callback_args: Extra argument passed to the callback.
            inline: Run the callback in the thread that delivers the message (the
                publisher's, or the transport's for another process) instead of on the
                executor: lowest latency, no queue. The callback must be quick and must
                not block, or it holds up delivery of everything behind it.
            raw: Give the callback a :class:`~workbench.bus.RawMessage` (the ROS 1
                serialized bytes with type, md5sum, receive time and publishing node)
                instead of a decoded message: nothing is decoded for messages from
                other processes (recorders, relays); in-process messages are
                serialized once per publish.

        Raises:
            TopicTypeError: The topic carries another type.
        """
        self._check_alive()
        cls = _message_class(msg_type, "create_subscription")
        sub = Subscription(
            self,
            self.resolve_name(topic, "topic name"),
            cls,
            callback,
            queue_size,
            callback_args,
            direct=inline,
            raw=raw,
        )
        self.bus.add_subscription(sub)
        with self._lock:
            _keep_open(self._subscriptions)
            self._subscriptions.append(sub)
        return sub

    def create_service(
        self, name: str, service_type: Any, handler: Callable[[Any], Any]
    ) -> ServiceServer:
        """Offer a service; ``handler(request)`` returns the response.

        The handler may also return a dict, a tuple of field values, or a single
        value for a one-field response. If it raises, the caller gets a
        ``ServiceError`` with its message and the server keeps running.
        """
        self._check_alive()
        server = ServiceServer(
            self, self.resolve_name(name, "service name"), _service_class(service_type), handler
        )
        self.bus.add_service(server)
        with self._lock:
            _keep_open(self._services)
            self._services.append(server)
        return server

    def create_client(self, name: str, service_type: Any) -> Client:
        """A client for a service (``client.call(request)``)."""
        self._check_alive()
        return Client(self, self.resolve_name(name, "service name"), _service_class(service_type))

    def create_timer(
        self, period: float, callback: Callable[[Any], Any], oneshot: bool = False
    ) -> Timer:
        """Call ``callback(event)`` every ``period`` seconds of the bus clock."""
        self._check_alive()
        timer = Timer(self, period, callback, oneshot)
        self.bus.add_timer(timer)
        with self._lock:
            _keep_open(self._timers)
            self._timers.append(timer)
        return timer

    def create_rate(self, hz: float) -> Rate:
        return Rate(hz, node=self)

    # --- parameters ---------------------------------------------------------------------

    def get_param(self, name: str, default: Any = _UNSET) -> Any:
        """A parameter's value; ``default`` if it is not set.

        Raises:
            ParameterError: Not set and no default given (it is also a ``KeyError``).
        """
        resolved = self.resolve_name(name, "parameter name")
        if default is _UNSET:
            return self.bus.params.get(resolved)
        try:
            return self.bus.params.get(resolved)
        except KeyError:
            return default

    def set_param(self, name: str, value: Any) -> None:
        self.bus.params.set(self.resolve_name(name, "parameter name"), value)

    def has_param(self, name: str) -> bool:
        return self.bus.params.has(self.resolve_name(name, "parameter name"))

    def delete_param(self, name: str) -> None:
        self.bus.params.delete(self.resolve_name(name, "parameter name"))

    def search_param(self, name: str) -> str | None:
        """The global name of the closest parameter called ``name``, walking up namespaces."""
        return self.bus.params.search(self.namespace, name)

    def get_param_names(self) -> list[str]:
        return self.bus.params.names()

    # --- time and logging ----------------------------------------------------------------

    def now(self) -> Any:
        """The bus clock's current time (``Time``)."""
        return self.bus.clock.now()

    def get_logger(self) -> Logger:
        return self._logger

    def sleep(self, seconds: float) -> None:
        """Sleep in bus-clock seconds (raises ``ShutdownInterrupt`` on shutdown)."""
        self.bus.clock.sleep(seconds, self.bus.shutdown_event)

    # --- lifetime -----------------------------------------------------------------------

    def on_shutdown(self, hook: Callable[..., Any]) -> None:
        """Call ``hook()`` when this node shuts down."""
        self._shutdown_hooks.append(hook)

    def endpoints(self) -> tuple[list[Publisher], list[Subscription], list[ServiceServer]]:
        """The node's open publishers, subscriptions and services."""
        with self._lock:
            return (
                [e for e in self._publishers if not e.closed],
                [e for e in self._subscriptions if not e.closed],
                [e for e in self._services if not e.closed],
            )

    def shutdown(self, reason: str = "") -> None:
        """Close every publisher, subscription, service and timer and leave the graph.

        Messages this node published that are still on their way to subscribers in
        other processes are delivered first (a bounded wait, ``WORKBENCH_FLUSH_TIMEOUT``
        seconds at most, 10 by default).
        """
        with self._lock:
            if self.is_shutdown:
                return
            self.is_shutdown = True
            self.shutdown_reason = reason or "node shut down"
            entities: list[Timer | Subscription | ServiceServer | Publisher] = [
                *self._timers,
                *self._subscriptions,
                *self._services,
                *self._publishers,
            ]
            topics = {pub.topic for pub in self._publishers}
        for hook in self._shutdown_hooks:
            try:
                try:
                    hook(self.shutdown_reason)
                except TypeError:
                    hook()
            except Exception as error:
                print(f"[ERROR] node {self.name}: shutdown hook failed: {error}", file=sys.stderr)
        if topics:
            # What this node published may still be on its way to slower subscribers in
            # other processes: wait (bounded) until they have it before leaving.
            self.bus.flush(topics)
        for entity in entities:
            entity.shutdown()
        self.bus.unregister_node(self)

    def __enter__(self) -> Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.shutdown()

    def __repr__(self) -> str:
        return f"Node({self.name!r})"
