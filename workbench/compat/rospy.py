"""rospy on the workbench bus: ``from workbench.compat import rospy``.

The lab's rospy scripts run unchanged apart from their import lines::

    from workbench.compat import rospy
    from workbench.msgs.std_msgs import String

A script's node joins a running ``workbench core`` (``WORKBENCH_MASTER_URI``,
default ``tcp/127.0.0.1:11311``) or, when none is reachable, runs in-process.
Several scripts may also run as threads of one process: ``init_node`` binds
the node to the calling thread, and callbacks see their own node.

The module's functions are a facade over one :class:`RospyContext` (the
process's nodes, shutdown state and hooks), made on first use.
"""

from __future__ import annotations

import contextlib
import functools
import signal
import sys
import threading
import time as _time
from collections.abc import Callable
from typing import Any

from workbench.bus import Bus, Node, default_bus
from workbench.bus import Rate as _Rate
from workbench.bus.entities import AnyMsg, TimerEvent, current_node
from workbench.bus.errors import BusError, ServiceError, ShutdownError, ShutdownInterrupt
from workbench.bus.names import myargv as _myargv
from workbench.errors import MessageError
from workbench.msgs import Duration as _MsgDuration
from workbench.msgs import Time as _MsgTime

__all__ = [
    "AnyMsg",
    "Duration",
    "Publisher",
    "ROSException",
    "ROSInitException",
    "ROSInterruptException",
    "ROSSerializationException",
    "Rate",
    "Service",
    "ServiceException",
    "ServiceProxy",
    "Subscriber",
    "Time",
    "Timer",
    "TimerEvent",
    "delete_param",
    "get_caller_id",
    "get_name",
    "get_namespace",
    "get_param",
    "get_param_names",
    "get_published_topics",
    "get_rostime",
    "get_time",
    "has_param",
    "init_node",
    "is_shutdown",
    "logdebug",
    "logerr",
    "logfatal",
    "loginfo",
    "logdebug_once",
    "logdebug_throttle",
    "logerr_once",
    "logerr_throttle",
    "loginfo_once",
    "logwarn_once",
    "logwarn_throttle",
    "logwarn",
    "myargv",
    "on_shutdown",
    "search_param",
    "set_param",
    "signal_shutdown",
    "sleep",
    "spin",
    "wait_for_message",
    "wait_for_service",
]


# --- exceptions (rospy's names) ---------------------------------------------------------


class ROSException(BusError):
    """Base of rospy's exceptions."""

    def __init__(self, message: str = "", **kwargs: Any) -> None:
        super().__init__(str(message), **kwargs)


class ROSInterruptException(ROSException, KeyboardInterrupt):
    """Raised by sleeps when the node shuts down (Ctrl-C)."""


class ROSInitException(ROSException):
    """``init_node`` failed."""


class ROSSerializationException(ROSException):
    """A message could not be built or serialized."""


class ServiceException(ROSException):
    """A service call failed (unavailable, or the handler raised)."""


# --- time -------------------------------------------------------------------------------


class Time(_MsgTime):
    """``rospy.Time``: ``Time(secs, nsecs)``, ``Time.now()``, ``to_sec()``."""

    __slots__ = ()

    @classmethod
    def now(cls) -> Time:
        """The current time of the node's clock (simulated when ``use_sim_time``)."""
        return cls(0, _bus().clock.now_ns())


class Duration(_MsgDuration):
    """``rospy.Duration``."""

    __slots__ = ()


def get_rostime() -> Time:
    return Time.now()


def get_time() -> float:
    """The current time in float seconds."""
    return _bus().clock.now_ns() / 1e9


# --- the process's rospy state ---------------------------------------------------------------


class RospyContext:
    """What rospy keeps per process: its nodes, the shutdown state and the hooks.

    Attributes:
        main_node: The first live node ``init_node`` started (the process's node).
        shutdown: Set by :func:`signal_shutdown`; sleeps wake on it.
        hooks: Called (without arguments) by :func:`signal_shutdown`.
        pending: Publishers, subscribers and services created before ``init_node``.
        throttle: Last time each ``loginfo_throttle`` call site logged.
    """

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.main_node: Node | None = None
        self.shutdown = threading.Event()
        self.hooks: list[Callable[..., Any]] = []
        self.pending: list[_Deferred] = []
        self.throttle: dict[tuple[str, int], float] = {}
        self._thread = threading.local()

    @property
    def thread_node(self) -> Node | None:
        """The node ``init_node`` started in the calling thread."""
        return getattr(self._thread, "node", None)

    @thread_node.setter
    def thread_node(self, node: Node | None) -> None:
        self._thread.node = node

    def node(self, required: bool = False) -> Node | None:
        """The node of the running callback, else of this thread, else the process's."""
        node = current_node.get() or self.thread_node or self.main_node
        if node is None and required:
            raise ROSInitException(
                "the node is not initialized", hint="call rospy.init_node('name') first"
            )
        return node

    def bus(self) -> Bus:
        """The bus of :meth:`node`, or the process's default bus."""
        node = self.node()
        return node.bus if node is not None else default_bus()

    def adopt(self, node: Node) -> None:
        """Make ``node`` this thread's node (and the process's if it has none alive)."""
        self.thread_node = node
        with self.lock:
            if self.main_node is None or self.main_node.is_shutdown:
                self.main_node = node
            mine = [p for p in self.pending if p._thread is threading.current_thread()]
            for item in mine:
                self.pending.remove(item)
        for item in mine:
            item._bind(node)

    def defer(self, item: _Deferred) -> None:
        with self.lock:
            self.pending.append(item)


_CONTEXT: RospyContext | None = None
_CONTEXT_LOCK = threading.Lock()


def context() -> RospyContext:
    """The process's :class:`RospyContext` (created on first use)."""
    global _CONTEXT
    with _CONTEXT_LOCK:
        if _CONTEXT is None:
            _CONTEXT = RospyContext()
        return _CONTEXT


def _node(required: bool = False) -> Node | None:
    return context().node(required)


def _bus() -> Bus:
    return context().bus()


def init_node(
    name: str,
    argv: list[str] | None = None,
    anonymous: bool = False,
    log_level: Any = None,
    disable_rostime: bool = False,
    disable_rosout: bool = False,
    disable_signals: bool = False,
    xmlrpc_port: int = 0,
    tcpros_port: int = 0,
) -> None:
    """Start this script's node (``rospy.init_node``).

    Reads remappings from ``argv`` (default ``sys.argv``): ``chatter:=/x``,
    ``__name:=``, ``__ns:=``, ``_param:=value``. Ctrl-C shuts the node down.
    """
    ctx = context()
    if ctx.thread_node is not None:
        raise ROSException("rospy.init_node() has already been called with different arguments")
    args = sys.argv[1:] if argv is None else list(argv)
    level = {10: "debug", 20: "info", 30: "warn", 40: "error", 50: "fatal"}.get(log_level, "info")
    if isinstance(log_level, str):
        level = log_level
    if name.startswith("/"):
        name = name[1:]
    try:
        node = Node(
            name,
            bus=default_bus(),
            anonymous=anonymous,
            argv=args,
            log_level=level,
            disable_rosout=disable_rosout,
        )
    except (BusError, MessageError) as error:
        raise ROSInitException(error.message, hint=error.hint) from None
    # A node shut down from outside (rosnode kill, a newer node with its name) ends the script.
    node.on_shutdown(lambda *reason: signal_shutdown(reason[0] if reason else "shutdown"))
    ctx.adopt(node)
    if not disable_signals and threading.current_thread() is threading.main_thread():
        for signum in (signal.SIGINT, signal.SIGTERM):
            signal.signal(signum, functools.partial(_on_signal, signal.getsignal(signum)))


def _on_signal(previous: Any, signum: int, frame: Any) -> None:
    # As rospy: shut down (running the on_shutdown hooks), then chain to the handler that
    # was installed before, but filter its KeyboardInterrupt, so the script ends through
    # is_shutdown() / ROSInterruptException rather than a KeyboardInterrupt mid-statement.
    # Installed even where the signal was ignored (a background job's SIGINT), as rospy does.
    signal_shutdown("keyboard interrupt" if signum == signal.SIGINT else "terminated")
    if callable(previous):
        with contextlib.suppress(KeyboardInterrupt):
            previous(signum, frame)


def get_caller_id() -> str:
    """The node's global name (``/listener_3395_1641920813590``)."""
    node = _node()
    return node.name if node is not None else "/unnamed"


get_name = get_caller_id


def get_namespace() -> str:
    node = _node()
    return node.namespace if node is not None else "/"


def myargv(argv: list[str] | None = None) -> list[str]:
    """``argv`` (default ``sys.argv``) without ROS remapping arguments."""
    return _myargv(sys.argv if argv is None else argv)


def is_shutdown() -> bool:
    ctx = context()
    node = ctx.node()
    return ctx.shutdown.is_set() or (node is not None and node.is_shutdown)


def on_shutdown(hook: Callable[..., Any]) -> None:
    context().hooks.append(hook)


def signal_shutdown(reason: str) -> None:
    """Shut the node(s) of this process down; sleeps raise ``ROSInterruptException``."""
    ctx = context()
    if ctx.shutdown.is_set():
        return
    ctx.shutdown.set()
    for hook in list(ctx.hooks):
        try:
            hook()
        except Exception as error:
            print(
                f"[ERROR] rospy shutdown hook {getattr(hook, '__name__', hook)!s} failed: "
                f"{type(error).__name__}: {error}",
                file=sys.stderr,
            )
    node = ctx.node()
    bus = node.bus if node is not None else None
    if bus is not None:
        bus.shutdown(reason)


def spin() -> None:
    """Block until shutdown (Ctrl-C); callbacks run meanwhile."""
    ctx = context()
    ctx.node(required=True)
    try:
        while not is_shutdown():
            ctx.shutdown.wait(0.2)
    except KeyboardInterrupt:
        signal_shutdown("keyboard interrupt")


def sleep(duration: Any) -> None:
    """Sleep in node-clock seconds (a float or a ``Duration``).

    Raises:
        ROSInterruptException: The node shut down meanwhile.
    """
    seconds = duration.to_sec() if hasattr(duration, "to_sec") else float(duration)
    try:
        ctx = context()
        ctx.bus().clock.sleep(seconds, ctx.shutdown)
    except ShutdownInterrupt:
        raise ROSInterruptException("ROS shutdown request") from None


class Rate:
    """``rospy.Rate(hz)``; ``sleep()`` raises ``ROSInterruptException`` on shutdown."""

    def __init__(self, hz: float, reset: bool = False) -> None:
        self._rate = _Rate(hz, bus=_bus())

    def sleep(self) -> None:
        if is_shutdown():
            raise ROSInterruptException("ROS shutdown request")
        try:
            self._rate.sleep()
        except ShutdownInterrupt:
            raise ROSInterruptException("ROS shutdown request") from None
        if is_shutdown():
            raise ROSInterruptException("ROS shutdown request")

    def remaining(self) -> Duration:
        return Duration(self._rate.remaining())


# --- logging ----------------------------------------------------------------------------


def _log(level: str, msg: Any, *args: Any) -> None:
    node = _node()
    if node is not None:
        getattr(node.get_logger(), level)(msg, *args)
        return
    text = str(msg) % args if args else str(msg)
    stream = sys.stdout if level in ("debug", "info") else sys.stderr
    print(f"[{level.upper()}] [{_time.time():.6f}]: {text}", file=stream, flush=True)


def logdebug(msg: Any, *args: Any) -> None:
    _log("debug", msg, *args)


def loginfo(msg: Any, *args: Any) -> None:
    _log("info", msg, *args)


def logwarn(msg: Any, *args: Any) -> None:
    _log("warn", msg, *args)


def logerr(msg: Any, *args: Any) -> None:
    _log("error", msg, *args)


def logfatal(msg: Any, *args: Any) -> None:
    _log("fatal", msg, *args)


logout = loginfo
logerror = logerr
logwarning = logwarn


def _throttled(level: str, period: float, msg: Any, args: tuple[Any, ...]) -> None:
    """Log at most once per ``period`` seconds (inf: once) from the caller's call site."""
    frame = sys._getframe(2)
    key = (frame.f_code.co_filename, frame.f_lineno)
    now = _time.monotonic()
    throttle = context().throttle
    if key not in throttle or now - throttle[key] >= period:
        throttle[key] = now
        _log(level, msg, *args)


def loginfo_throttle(period: float, msg: Any, *args: Any) -> None:
    """Log at most once per ``period`` seconds from one call site."""
    _throttled("info", period, msg, args)


def logdebug_throttle(period: float, msg: Any, *args: Any) -> None:
    _throttled("debug", period, msg, args)


def logwarn_throttle(period: float, msg: Any, *args: Any) -> None:
    _throttled("warn", period, msg, args)


def logerr_throttle(period: float, msg: Any, *args: Any) -> None:
    _throttled("error", period, msg, args)


def logdebug_once(msg: Any, *args: Any) -> None:
    """Log only the first time this call site runs (rospy's ``*_once``)."""
    _throttled("debug", float("inf"), msg, args)


def loginfo_once(msg: Any, *args: Any) -> None:
    _throttled("info", float("inf"), msg, args)


def logwarn_once(msg: Any, *args: Any) -> None:
    _throttled("warn", float("inf"), msg, args)


def logerr_once(msg: Any, *args: Any) -> None:
    _throttled("error", float("inf"), msg, args)


# --- parameters -------------------------------------------------------------------------

_UNSET: Any = object()


def _param_node() -> Node:
    return _node(required=True)  # type: ignore[return-value]


def get_param(name: str, default: Any = _UNSET) -> Any:
    """A parameter's value; raises ``KeyError`` when unset and no default is given."""
    if default is _UNSET:
        return _param_node().get_param(name)
    return _param_node().get_param(name, default)


def set_param(name: str, value: Any) -> None:
    _param_node().set_param(name, value)


def has_param(name: str) -> bool:
    return _param_node().has_param(name)


def delete_param(name: str) -> None:
    _param_node().delete_param(name)


def search_param(name: str) -> str | None:
    return _param_node().search_param(name)


def get_param_names() -> list[str]:
    return _param_node().get_param_names()


# --- topics -----------------------------------------------------------------------------


class _Deferred:
    """Something created before ``init_node`` (rospy allows it); bound when the node starts."""

    def __init__(self) -> None:
        self._thread = threading.current_thread()
        self._impl: Any = None
        node = _node()
        if node is not None:
            self._bind(node)
        else:
            context().defer(self)

    def _bind(self, node: Node) -> None:  # pragma: no cover - overridden
        raise NotImplementedError


class Publisher(_Deferred):
    """``rospy.Publisher(name, data_class, queue_size=..., latch=...)``."""

    def __init__(
        self,
        name: str,
        data_class: Any,
        subscriber_listener: Any = None,
        tcp_nodelay: bool = False,
        latch: bool = False,
        headers: Any = None,
        queue_size: int | None = None,
    ) -> None:
        self._args = (name, data_class, queue_size, latch)
        self.data_class = data_class
        super().__init__()

    def _bind(self, node: Node) -> None:
        name, data_class, queue_size, latch = self._args
        self._impl = node.create_publisher(name, data_class, queue_size=queue_size, latch=latch)
        self.name = self.resolved_name = self._impl.topic
        self.type = self._impl.type

    def publish(self, *args: Any, **kwargs: Any) -> None:
        """Publish a message, or the message built from ``args``/``kwargs``."""
        if self._impl is None:
            raise ROSException("publish() before init_node()", hint="call rospy.init_node first")
        try:
            self._impl.publish(*args, **kwargs)
        except MessageError as error:
            raise ROSSerializationException(error.message, hint=error.hint) from None
        except ShutdownError:
            # As rospy's _PublisherImpl.publish: shutdown can close the topic between a
            # script's is_shutdown() test and its publish(); that publish is dropped quietly.
            if not is_shutdown():
                raise ROSException(
                    f"publish() to a closed topic ({self._impl.topic})",
                    hint="the publisher was unregistered",
                ) from None

    def get_num_connections(self) -> int:
        return 0 if self._impl is None else self._impl.get_num_connections()

    def unregister(self) -> None:
        if self._impl is not None:
            self._impl.unregister()


class Subscriber(_Deferred):
    """``rospy.Subscriber(name, data_class, callback, callback_args, queue_size)``."""

    def __init__(
        self,
        name: str,
        data_class: Any,
        callback: Callable[..., Any] | None = None,
        callback_args: Any = None,
        queue_size: int | None = None,
        buff_size: int = 65536,
        tcp_nodelay: bool = False,
    ) -> None:
        self._args = (name, data_class, callback, callback_args, queue_size)
        self.data_class = data_class
        self.callback = callback
        super().__init__()

    def _bind(self, node: Node) -> None:
        name, data_class, callback, callback_args, queue_size = self._args
        self._impl = node.create_subscription(
            name, data_class, callback, queue_size=queue_size, callback_args=callback_args
        )
        self.name = self.resolved_name = self._impl.topic

    def get_num_connections(self) -> int:
        return 0 if self._impl is None else self._impl.get_num_connections()

    def unregister(self) -> None:
        if self._impl is not None:
            self._impl.unregister()


def get_published_topics(namespace: str = "/") -> list[list[str]]:
    """``[[topic, type], ...]`` for every published topic under ``namespace``."""
    graph = _bus().graph()
    prefix = namespace.rstrip("/") + "/"
    return [
        [name, record.type]
        for name, record in sorted(graph.topics.items())
        if record.publishers and (namespace == "/" or name.startswith(prefix))
    ]


def wait_for_message(topic: str, topic_type: Any, timeout: float | None = None) -> Any:
    """Block until one message arrives on ``topic``; raises ``ROSException`` on timeout."""
    node = _node(required=True)
    got: list[Any] = []
    event = threading.Event()

    def keep(msg: Any) -> None:
        if not got:
            got.append(msg)
            event.set()

    sub = node.create_subscription(topic, topic_type, keep, queue_size=1)  # type: ignore[union-attr]
    try:
        if node.bus.threaded:  # type: ignore[union-attr]
            ok = event.wait(timeout)
        else:
            ok = node.bus.spin_until(lambda: bool(got), timeout)  # type: ignore[union-attr]
        if not ok:
            raise ROSException(f"timeout exceeded while waiting for a message on topic {topic}")
        return got[0]
    finally:
        sub.unregister()


# --- services ---------------------------------------------------------------------------


class Service(_Deferred):
    """``rospy.Service(name, service_class, handler)``."""

    def __init__(self, name: str, service_class: Any, handler: Callable[[Any], Any], **_: Any):
        self._args = (name, service_class, handler)
        super().__init__()

    def _bind(self, node: Node) -> None:
        name, service_class, handler = self._args
        self._impl = node.create_service(name, service_class, handler)
        self.resolved_name = self._impl.name

    def shutdown(self, reason: str = "") -> None:
        if self._impl is not None:
            self._impl.shutdown(reason)

    def spin(self) -> None:
        spin()


class ServiceProxy:
    """``rospy.ServiceProxy(name, service_class)``; call it like a function."""

    def __init__(
        self, name: str, service_class: Any, persistent: bool = False, headers: Any = None
    ):
        self.service_class = service_class
        self._name = name
        self.resolved_name = _resolve(name)

    def _client(self) -> Any:
        ctx = context()
        node = ctx.node()
        if node is None:
            node = Node("unnamed", bus=default_bus(), anonymous=True)
            ctx.thread_node = node
        return node.create_client(self._name, self.service_class)

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        return self.call(*args, **kwargs)

    def call(self, *args: Any, **kwargs: Any) -> Any:
        """Call with a ``Request``, or with the request's field values."""
        request_class = self.service_class._request_class
        try:
            if len(args) == 1 and not kwargs and isinstance(args[0], request_class):
                request = args[0]
            else:
                request = request_class(*args, **kwargs)
        except MessageError as error:
            raise ServiceException(f"bad request for {self._name}: {error.message}") from None
        try:
            return self._client().call(request)
        except ServiceError as error:
            raise ServiceException(error.message, hint=error.hint) from None

    def wait_for_service(self, timeout: float | None = None) -> None:
        wait_for_service(self._name, timeout)

    def close(self) -> None:
        """Nothing to release."""


def _resolve(name: str) -> str:
    node = _node()
    return node.resolve_name(name) if node is not None else name


def wait_for_service(service: str, timeout: float | None = None) -> None:
    """Block until ``service`` is offered.

    Raises:
        ROSException: ``timeout`` seconds passed first.
    """
    node = _node()
    bus = node.bus if node is not None else default_bus()
    name = node.resolve_name(service, "service name") if node is not None else service
    if not name.startswith("/"):
        name = "/" + name
    if not bus.wait_for_service(name, timeout):
        raise ROSException(f"timeout exceeded while waiting for service {name}")


# --- timers -----------------------------------------------------------------------------


class Timer:
    """``rospy.Timer(period, callback, oneshot=False)``; ``period`` a Duration or seconds."""

    def __init__(self, period: Any, callback: Callable[[TimerEvent], Any], oneshot: bool = False):
        seconds = period.to_sec() if hasattr(period, "to_sec") else float(period)
        self._impl = _node(required=True).create_timer(seconds, callback, oneshot)  # type: ignore[union-attr]

    def shutdown(self) -> None:
        self._impl.shutdown()

    def is_alive(self) -> bool:
        return self._impl.is_alive()
