"""Publishers, subscriptions, services, clients, timers and rates.

Create them through a :class:`~workbench.bus.node.Node`
(``node.create_publisher(...)`` ...), not directly. They reach their bus only
through its public methods (``add_publisher``, ``executor.schedule``,
``call_service`` ...); transports hand messages to a subscription with
:meth:`Subscription.deliver`.
"""

from __future__ import annotations

import contextvars
import threading
import traceback
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from workbench.bus.bus import default_bus
from workbench.bus.clock import ShutdownInterrupt
from workbench.bus.errors import ServiceError, ServiceTimeout, ShutdownError, TopicTypeError
from workbench.errors import MessageError, WorkbenchError
from workbench.msgs import Message, is_service, md5sum

if TYPE_CHECKING:
    from collections.abc import Callable

    from workbench.bus.bus import Bus
    from workbench.bus.node import Node


class AnyMsg:
    """Subscribe with ``AnyMsg`` to receive whatever type is published on a topic.

    The callback gets the publisher's message object (decoded from its own type
    when it comes from another process; raw bytes if that type is unknown here).
    """

    _type = "*"
    _md5sum = "*"


class RawMessage:
    """What a ``raw=True`` subscription's callback receives: a message still serialized.

    Attributes:
        data: The ROS 1 serialized bytes (as in a bag).
        type: The publisher's type name (``std_msgs/Int64``).
        md5: The publisher's type md5sum.
        recv_ns: Receive time on the bus clock (wall or simulated), integer nanoseconds.
        callerid: The publishing node's name (ROS's connection header ``callerid``).
        topic: The topic it was published on.
        latching: Whether the publisher latches (ROS's connection header ``latching``).
    """

    __slots__ = ("data", "type", "md5", "recv_ns", "callerid", "topic", "latching")

    def __init__(
        self,
        data: bytes,
        type: str,
        md5: str,
        recv_ns: int,
        callerid: str,
        topic: str,
        latching: bool = False,
    ) -> None:
        self.data = data
        self.type = type
        self.md5 = md5
        self.recv_ns = recv_ns
        self.callerid = callerid
        self.topic = topic
        self.latching = latching

    def deserialize(self) -> Message:
        """Decode into a message object (needs the type to be known here)."""
        from workbench.msgs import deserialize

        return deserialize(self.data, self.type)

    def __repr__(self) -> str:
        return (
            f"RawMessage({self.type}, {len(self.data)} bytes, topic={self.topic!r}, "
            f"callerid={self.callerid!r})"
        )


#: The node whose callback is running in this thread (for rospy's get_caller_id).
current_node: contextvars.ContextVar[Node | None] = contextvars.ContextVar(
    "workbench_current_node", default=None
)

#: (subscription, publishing node) of the message whose callback is running in this thread.
_current_delivery: contextvars.ContextVar[tuple[Subscription, str] | None] = contextvars.ContextVar(
    "workbench_current_delivery", default=None
)


def connection_header() -> dict[str, str] | None:
    """ROS's connection header of the message whose callback is running now.

    ROS gives callbacks ``msg._connection_header``; here messages are shared and
    have fixed fields, so a callback asks for it instead. Keys: ``callerid``
    (the publishing node, ``""`` if unknown), ``topic``, ``type``, ``md5sum``.

    Returns:
        The header, or ``None`` outside a subscription callback.
    """
    delivery = _current_delivery.get()
    if delivery is None:
        return None
    sub, callerid = delivery
    return {"callerid": callerid, "topic": sub.topic, "type": sub.type, "md5sum": sub.md5}


def type_and_md5(data_class: Any) -> tuple[str, str]:
    if data_class is AnyMsg:
        return "*", "*"
    return data_class._type, md5sum(data_class._type)


class Publisher:
    """Publishes messages of one type on one topic (``node.create_publisher``)."""

    def __init__(
        self, node: Node, topic: str, data_class: type[Message], queue_size: int | None, latch: bool
    ):
        self.node = node
        self.topic = topic
        self.data_class = data_class
        self.type, self.md5 = type_and_md5(data_class)
        self.queue_size = queue_size
        self.latch = latch
        self.last_message: Message | None = None
        self.closed = False
        self._senders: tuple[Callable[[Message], None], ...] = ()
        self._clock = node.bus.clock
        self._has_header = bool(getattr(data_class, "_has_header", False))
        self._seq = 0
        #: Number ``header.seq`` of each message as rospy does (False: send it as given,
        #: as ``rosbag play`` does with recorded messages).
        self.number_headers = True

    def publish(self, *args: Any, **kwargs: Any) -> None:
        """Publish a message, or build one from the arguments (``pub.publish("hello")``).

        Raises:
            MessageError: A message of another type, or arguments that do not build one.
            ShutdownError: The publisher or its node was shut down.
        """
        if len(args) == 1 and not kwargs and type(args[0]) is self.data_class:
            msg = args[0]
        else:
            msg = self._coerce(args, kwargs)
        if self.closed:
            raise ShutdownError(f"publisher on {self.topic} is closed (its node shut down)")
        if self._has_header and self.number_headers:  # rospy numbers its messages
            self._seq += 1
            msg.header.seq = self._seq & 0xFFFFFFFF  # type: ignore[attr-defined]
        if self.latch:
            self.last_message = msg
        for send in self._senders:  # one per transport (in-process first)
            send(msg)

    def set_senders(self, senders: tuple[Callable[[Message], None], ...]) -> None:
        """Called by the bus: the transports' send functions for this publisher."""
        self._senders = senders

    def to_raw(self, msg: Message) -> RawMessage:
        """``msg`` serialized, as a raw subscription receives it (stamped now)."""
        from workbench.msgs import serialize

        return RawMessage(
            serialize(msg),
            self.type,
            self.md5,
            self._clock.now_ns(),
            self.node.name,
            self.topic,
            self.latch,
        )

    def _coerce(self, args: tuple, kwargs: dict) -> Message:
        if len(args) == 1 and not kwargs and isinstance(args[0], Message):
            got = args[0]
            if isinstance(got, self.data_class):
                return got
            raise TopicTypeError(
                f"publisher on {self.topic} is {self.type}; cannot publish a {got._type}",
                hint=f"create a publisher of {got._type}, or build a {self.type}",
            )
        if args and isinstance(args[-1], Message) and not isinstance(args[-1], self.data_class):
            raise TopicTypeError(
                f"publisher on {self.topic} is {self.type}; cannot publish a {args[-1]._type}"
            )
        try:
            return self.data_class(*args, **kwargs)
        except MessageError as error:
            raise MessageError(
                f"cannot publish on {self.topic}: {error.message}", hint=error.hint
            ) from None

    def get_num_connections(self) -> int:
        """Number of subscribers on this topic (all processes)."""
        return len(self.node.bus.graph().topics.get(self.topic, _EMPTY).subscribers)

    def unregister(self) -> None:
        """Stop publishing (``rospy.Publisher.unregister``)."""
        if not self.closed:
            self.closed = True
            self.node.bus.remove_publisher(self)

    shutdown = unregister


class _Empty:
    subscribers: list = []
    publishers: list = []


_EMPTY = _Empty()


class Subscription:
    """Delivers the messages of a topic to a callback through the bus's executor.

    The queue holds at most ``queue_size`` messages; when full, the oldest is dropped.
    With ``raw``, the callback gets :class:`RawMessage` (serialized bytes) instead of
    a decoded message.
    """

    def __init__(
        self,
        node: Node,
        topic: str,
        data_class: Any,
        callback: Callable[..., Any] | None,
        queue_size: int | None,
        callback_args: Any = None,
        direct: bool = False,
        raw: bool = False,
    ):
        self.node = node
        self.topic = topic
        self.data_class = data_class
        self.type, self.md5 = type_and_md5(data_class)
        self.callback = callback
        self.callback_args = callback_args
        size = queue_size if queue_size and queue_size > 0 else None
        self._queue: deque[tuple[Any, str]] = deque(maxlen=size)
        self.scheduled = False
        self._schedule = node.bus.executor.schedule
        self._direct = direct
        self.raw = raw
        self.closed = False
        self.received = 0

    def deliver(self, msg: Any, callerid: str = "") -> None:
        """Queue ``msg`` from the node ``callerid`` for the callback (called by transports).

        With ``inline``, the callback runs now, in the calling thread.
        """
        if self.closed:
            return
        self.received += 1
        if self._direct:
            self._call(msg, callerid)
            return
        self._queue.append((msg, callerid))
        self._schedule(self)

    def run_pending(self, budget: int = 8) -> int:
        """Run up to ``budget`` queued callbacks; returns how many ran."""
        ran = 0
        queue = self._queue
        while ran < budget:
            try:
                msg, callerid = queue.popleft()
            except IndexError:
                break
            self._call(msg, callerid)
            ran += 1
        return ran

    def has_pending(self) -> bool:
        return bool(self._queue)

    def _call(self, msg: Any, callerid: str = "") -> None:
        if self.callback is None or self.closed:
            return
        token = current_node.set(self.node)
        delivery = _current_delivery.set((self, callerid))
        try:
            if self.callback_args is None:
                self.callback(msg)
            else:
                self.callback(msg, self.callback_args)
        except ShutdownError as error:
            # a message delivered while the node shuts down (Ctrl-C) whose callback publishes:
            # the stop, not a bug of the callback (rospy drops it the same way)
            self.node.get_logger().debug(f"callback on {self.topic} during shutdown: {error}")
        except Exception as error:  # a user's callback must not kill the executor
            self.node.get_logger().error(
                f"bad callback: {getattr(self.callback, '__name__', self.callback)} on "
                f"{self.topic}: {type(error).__name__}: {error}\n{traceback.format_exc().rstrip()}"
            )
        finally:
            _current_delivery.reset(delivery)
            current_node.reset(token)

    def get_num_connections(self) -> int:
        return len(self.node.bus.graph().topics.get(self.topic, _EMPTY).publishers)

    def unregister(self) -> None:
        """Stop receiving (``rospy.Subscriber.unregister``)."""
        if not self.closed:
            self.closed = True
            self._queue.clear()
            self.node.bus.remove_subscription(self)

    shutdown = unregister


class ServiceServer:
    """Answers calls of one service with ``handler(request) -> response``."""

    def __init__(self, node: Node, name: str, service_class: Any, handler: Callable[[Any], Any]):
        if not is_service(service_class):
            raise MessageError(
                f"{getattr(service_class, '_type', service_class)} is not a service type",
                hint="pass a service class such as workbench.msgs.std_srvs.Trigger",
            )
        self.node = node
        self.name = name
        self.service_class = service_class
        self.type = service_class._type
        self.md5 = service_class._md5sum
        self.handler = handler
        self.closed = False

    def handle(self, request: Any) -> Any:
        """Run the handler; a failure becomes :class:`ServiceError` with the handler's message."""
        token = current_node.set(self.node)
        try:
            result = self.handler(request)
        except WorkbenchError as error:
            # a refusal the handler means (rospy's ServiceException): one line, no traceback
            self.node.get_logger().debug(f"service [{self.name}] refused the request: {error}")
            raise ServiceError(
                f"service [{self.name}] responded with an error: service cannot process "
                f"request: {error}"
            ) from None
        except Exception as error:
            self.node.get_logger().error(
                f"Error processing request: {error}\n{traceback.format_exc().rstrip()}"
            )
            raise ServiceError(
                f"service [{self.name}] responded with an error: error processing request: {error}"
            ) from None
        finally:
            current_node.reset(token)
        try:
            return coerce_response(self.service_class.Response, result)
        except MessageError as error:
            self.node.get_logger().error(f"service [{self.name}] handler: {error.message}")
            raise ServiceError(
                f"service [{self.name}] responded with an error: {error.message}"
            ) from None

    def shutdown(self, reason: str = "") -> None:
        if not self.closed:
            self.closed = True
            self.node.bus.remove_service(self)

    unregister = shutdown


def coerce_response(response_class: type[Message], result: Any) -> Message:
    """Turn what a handler returned into a response, as rospy does."""
    if isinstance(result, response_class):
        return result
    if result is None:
        raise MessageError("service handler returned None")
    if isinstance(result, Message):
        raise MessageError(f"handler returned a {result._type}, not a {response_class._type}")
    if isinstance(result, dict):
        return response_class(**result)
    if isinstance(result, (list, tuple)):
        return response_class(*result)
    return response_class(result)


class Client:
    """Calls one service (``node.create_client``)."""

    def __init__(self, node: Node, name: str, service_class: Any):
        if not is_service(service_class):
            raise MessageError(
                f"{getattr(service_class, '_type', service_class)} is not a service type"
            )
        self.node = node
        self.name = name
        self.service_class = service_class
        self.type = service_class._type
        self.md5 = service_class._md5sum

    def wait_for_service(self, timeout: float | None = None) -> None:
        """Block until someone offers the service.

        Raises:
            ServiceTimeout: ``timeout`` seconds (wall time) passed first.
        """
        if not self.node.bus.wait_for_service(self.name, timeout):
            raise ServiceTimeout(
                f"timeout exceeded while waiting for service {self.name}",
                hint="is its server running? 'workbench service list' shows the offered services",
            )

    def service_is_ready(self) -> bool:
        return self.node.bus.service_available(self.name)

    def call(self, request: Any = None, timeout: float | None = None, **fields: Any) -> Any:
        """Call the service and return its response.

        Args:
            request: A ``Request`` (or ``None`` to build one from ``fields``).
            timeout: Seconds to wait for the response (None: no limit).

        Raises:
            ServiceError: Nobody offers the service, the types differ, or the handler raised.
            ServiceTimeout: No response within ``timeout``.
        """
        request_class = self.service_class.Request
        if request is None:
            request = request_class(**fields)
        elif not isinstance(request, request_class):
            got = getattr(request, "_type", type(request).__name__)
            raise MessageError(f"service {self.name} needs a {request_class._type}, not a {got}")
        return self.node.bus.call_service(self, request, timeout)

    __call__ = call

    def close(self) -> None:
        """Nothing to release (kept for rospy's ``ServiceProxy.close``)."""


@dataclass
class TimerEvent:
    """What a timer callback receives (rospy's ``TimerEvent``), times as ``Time``."""

    last_expected: Any
    last_real: Any
    current_expected: Any
    current_real: Any
    last_duration: float | None


class Timer:
    """Calls ``callback(event)`` every ``period`` seconds of the bus clock.

    Threaded buses give each timer a thread that sleeps until the next period and
    schedules the callback on the executor. If that thread fails (it should not: the
    callback itself runs on the executor, and its errors are logged there), the error
    is logged with the node and timer and the thread starts over, up to
    :attr:`MAX_RESTARTS` times in a row; then the timer stops with a fatal log line.
    When simulated time jumps backwards (a simulation reset), the period starts over from
    the new time, as roscpp's timers do (they would otherwise wait for the old time).
    """

    #: Consecutive failures of the timer thread before the timer gives up.
    MAX_RESTARTS = 5

    def __init__(
        self,
        node: Node,
        period: float,
        callback: Callable[[TimerEvent], Any],
        oneshot: bool = False,
    ):
        if not period > 0:
            raise ValueError(f"timer period must be positive, not {period}")
        self.node = node
        self.period = float(period)
        self.callback = callback
        self.oneshot = oneshot
        self.closed = False
        self.scheduled = False
        self.restarts = 0
        self._due = False
        self._clock = node.bus.clock
        self._schedule = node.bus.executor.schedule
        self.next_ns = self._clock.now_ns() + int(self.period * 1e9)
        self._polled_ns = self.next_ns - int(self.period * 1e9)
        self._last_expected: int | None = None
        self._last_real: int | None = None
        self._last_duration: float | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        if node.bus.threaded:
            self._thread = threading.Thread(
                target=self._supervise, name=f"timer {node.name}", daemon=True
            )
            self._thread.start()

    def __repr__(self) -> str:
        name = getattr(self.callback, "__name__", repr(self.callback))
        return f"Timer({name}, every {self.period} s, node {self.node.name})"

    def _supervise(self) -> None:
        failures = 0
        while not self._stop.is_set():
            try:
                self._tick()
                return
            except ShutdownInterrupt:  # the timer or its bus was shut down while sleeping
                return
            except Exception as error:
                failures += 1
                self.restarts += 1
                if failures > self.MAX_RESTARTS:
                    self.node.get_logger().fatal(
                        f"{self!r}: its thread failed {failures} times in a row "
                        f"({type(error).__name__}: {error}); the timer stops"
                    )
                    self.shutdown()
                    return
                self.node.get_logger().error(
                    f"{self!r}: its thread failed ({type(error).__name__}: {error}); "
                    f"restarting it\n{traceback.format_exc().rstrip()}"
                )

    def _tick(self) -> None:
        clock = self._clock
        while not self._stop.is_set():
            clock.sleep_until_ns(self.next_ns, self._stop, back=True)
            now = clock.now_ns()
            if now < self.next_ns:
                # time jumped backwards (a simulation reset): count the period from now, as
                # roscpp's timers do, instead of waiting for the old time to come back
                self.next_ns = now + int(self.period * 1e9)
                continue
            self._due = True
            self._schedule(self)
            if self.oneshot:
                return
            self.next_ns += int(self.period * 1e9)
            now = clock.now_ns()
            if now > self.next_ns + int(self.period * 1e9):  # fell behind, or time jumped
                self.next_ns = now + int(self.period * 1e9)

    def poll(self) -> bool:
        """Stepped mode: mark the timer due if its time has come."""
        if self.closed or self._due:
            return self._due
        now = self._clock.now_ns()
        if now < self._polled_ns:  # time jumped backwards (a simulation reset)
            self.next_ns = now + int(self.period * 1e9)
        self._polled_ns = now
        if now >= self.next_ns:
            self._due = True
            self.next_ns = self.next_ns + int(self.period * 1e9)
            if now > self.next_ns:
                self.next_ns = now + int(self.period * 1e9)
            return True
        return False

    def has_pending(self) -> bool:
        return self._due and not self.closed

    def run_pending(self, budget: int = 1) -> int:
        if not self._due or self.closed:
            return 0
        self._due = False
        from workbench.msgs import Time

        clock = self._clock
        start = clock.now_ns()
        expected = self.next_ns - int(self.period * 1e9)
        event = TimerEvent(
            None if self._last_expected is None else Time(0, self._last_expected),
            None if self._last_real is None else Time(0, self._last_real),
            Time(0, expected),
            Time(0, start),
            self._last_duration,
        )
        token = current_node.set(self.node)
        try:
            self.callback(event)
        except ShutdownError as error:
            if not getattr(self.node, "is_shutdown", False):
                self._report(error)
            # else: the node is shutting down and closed a publisher the callback used
            # while this tick ran; it was the last one
        except Exception as error:
            self._report(error)
        finally:
            current_node.reset(token)
        self._last_expected, self._last_real = expected, start
        self._last_duration = (clock.now_ns() - start) / 1e9
        if self.oneshot:
            self.shutdown()
        return 1

    def is_alive(self) -> bool:
        return not self.closed

    def _report(self, error: Exception) -> None:
        self.node.get_logger().error(
            f"timer callback raised {type(error).__name__}: {error}\n"
            f"{traceback.format_exc().rstrip()}"
        )

    def shutdown(self) -> None:
        if not self.closed:
            self.closed = True
            self._stop.set()
            self.node.bus.remove_timer(self)

    cancel = shutdown


class Rate:
    """Sleep so that a loop runs ``hz`` times per second of the bus clock."""

    def __init__(self, hz: float, node: Node | None = None, bus: Bus | None = None):
        if not hz > 0:
            raise ValueError(f"rate must be positive, not {hz}")
        if bus is None:
            bus = node.bus if node is not None else default_bus()
        self._bus = bus
        self._period_ns = int(1e9 / hz)
        self._last_ns = bus.clock.now_ns()

    def remaining(self) -> float:
        """Seconds left until the next cycle should start."""
        return (self._last_ns + self._period_ns - self._bus.clock.now_ns()) / 1e9

    def sleep(self) -> None:
        """Sleep until the next cycle.

        Raises:
            ShutdownInterrupt: The bus shut down while sleeping.
        """
        clock = self._bus.clock
        now = clock.now_ns()
        if now < self._last_ns:  # time went backwards (a simulation reset)
            self._last_ns = now
        deadline = self._last_ns + self._period_ns
        clock.sleep_until_ns(deadline, self._bus.shutdown_event)
        now = clock.now_ns()
        self._last_ns = deadline if now - deadline <= self._period_ns else now
