"""The bus side of what a device negotiated: its publishers, subscribers and services.

Each class is built from one ``rosserial_msgs/TopicInfo`` the device sent and
checks, as rosserial_python does, that the device's md5sum is the md5sum of the
type workbench knows under that name ("Checksum does not match: ours,theirs").

* :class:`DevicePublisher` publishes what the device sends on the bus;
* :class:`DeviceSubscriber` forwards what the bus publishes to the device (the
  serialized bytes as they are, nothing decoded);
* :class:`DeviceServiceServer` offers the device's service on the bus: a call sends
  the request to the device and waits for its response;
* :class:`DeviceServiceClient` calls a bus service for the device and sends back the
  response (on the :class:`CallQueue`'s one thread, never a thread per request).
"""

from __future__ import annotations

import queue
import threading
from collections.abc import Callable
from typing import Any

from workbench.errors import MessageError, SerialError, WorkbenchError
from workbench.msgs import deserialize, get_service, get_type, md5sum, serialize

#: ``send(topic_id, payload)``: queue a frame for the device.
Send = Callable[[int, bytes], None]


class ChecksumMismatch(SerialError):
    """The device's md5sum differs from workbench's for the same type name."""


def check_md5(ours: str, theirs: str) -> None:
    """Raise :class:`ChecksumMismatch` with rosserial_python's text when the sums differ."""
    if ours != theirs:
        raise ChecksumMismatch(f"Checksum does not match: {ours},{theirs}")


class DevicePublisher:
    """A device's publisher: frames on ``topic_id`` become messages on the bus.

    Args:
        node: The host's bus node.
        info: The device's TopicInfo.

    Raises:
        MessageError: Unknown type.
        ChecksumMismatch: Different md5sum.
        TopicTypeError: The topic already carries another type on the bus.
    """

    def __init__(self, node: Any, info: Any) -> None:
        self.topic = info.topic_name
        self.type = info.message_type
        self.message_class = get_type(self.type)
        check_md5(md5sum(self.type), info.md5sum)
        self.log = node.get_logger()
        self.publisher = node.create_publisher(self.topic, self.message_class, queue_size=10)
        self.forwarded = 0

    def handle(self, payload: bytes) -> None:
        """Publish the message in ``payload``; a payload that is not one is an error line."""
        try:
            msg = deserialize(payload, self.type)
        except MessageError as error:
            self.log.error(
                f"Cannot deliver message on {self.topic} from the device: {error.message}"
            )
            return
        self.publisher.publish(msg)
        self.forwarded += 1

    def same(self, info: Any) -> bool:
        return bool(info.topic_name == self.topic and info.message_type == self.type)

    def close(self) -> None:
        self.publisher.unregister()


class DeviceSubscriber:
    """A device's subscriber: messages on the bus topic go to the device as frames.

    Args:
        node: The host's bus node.
        info: The device's TopicInfo.
        send: Queues a frame for the device.
        fits: ``fits(size, topic)``: whether a message of ``size`` bytes fits the device's
            input buffer (it logs and returns False when not).
    """

    def __init__(self, node: Any, info: Any, send: Send, fits: Callable[[int, str], bool]) -> None:
        self.topic = info.topic_name
        self.type = info.message_type
        self.id = int(info.topic_id)
        check_md5(md5sum(self.type), info.md5sum)
        self.log = node.get_logger()
        self._send = send
        self._fits = fits
        self.forwarded = 0
        self.subscription = node.create_subscription(
            self.topic, get_type(self.type), self._forward, queue_size=None, inline=True, raw=True
        )

    def _forward(self, raw: Any) -> None:
        data = raw.data
        if self._fits(len(data), self.topic):
            self._send(self.id, data)
            self.forwarded += 1

    def close(self) -> None:
        self.log.info("Removing subscriber: %s", self.topic)
        self.subscription.unregister()


class _DeviceService:
    """What both kinds of device service share: the type, the device's id, md5sums."""

    def __init__(self, node: Any, info: Any, send: Send, timeout: float) -> None:
        self.topic = info.topic_name
        self.type = info.message_type
        self.service_class = get_service(self.type)
        self.log = node.get_logger()
        self._send = send
        self.timeout = timeout
        self.id = -1  # the device's subscriber (requests or responses), known once negotiated

    def request_md5(self) -> str:
        return md5sum(self.service_class.Request._type)

    def response_md5(self) -> str:
        return md5sum(self.service_class.Response._type)


class DeviceServiceServer(_DeviceService):
    """A service the device offers, offered on the bus (its two TopicInfos share the name).

    A bus call sends the request on the device's subscriber id and waits (up to
    ``timeout`` seconds) for the frame its publisher id answers with.
    """

    def __init__(self, node: Any, info: Any, send: Send, timeout: float) -> None:
        super().__init__(node, info, send, timeout)
        self._lock = threading.Lock()
        self._answered = threading.Event()
        self._response: bytes | None = None
        self.server = node.create_service(self.topic, self.service_class, self._call)

    def handle(self, payload: bytes) -> None:
        """The device's response frame."""
        self._response = payload
        self._answered.set()

    def _call(self, request: Any) -> Any:
        if self.id < 0:
            raise SerialError(f"the device has not finished setting up service {self.topic}")
        with self._lock:
            self._answered.clear()
            self._send(self.id, serialize(request))
            if not self._answered.wait(self.timeout):
                raise SerialError(
                    f"the device did not answer service {self.topic} within {self.timeout:g} s"
                )
            assert self._response is not None
            return deserialize(self._response, self.service_class.Response._type)

    def close(self) -> None:
        self.log.info("Removing service: %s", self.topic)
        self.server.shutdown()


class CallQueue:
    """The device's service calls, made one after another on one thread of their own.

    The thread starts with the first call and ends at :meth:`close`; calls beyond
    ``limit`` waiting are refused (a device that floods requests cannot pile up work).

    Args:
        log: The host's logger (refusals are logged on it).
        limit: Most calls waiting at once.
    """

    def __init__(self, log: Any, limit: int = 16) -> None:
        self.log = log
        self.limit = limit
        self._calls: queue.Queue[Callable[[], None] | None] = queue.Queue(limit)
        self._thread: threading.Thread | None = None
        self._lock = threading.Lock()

    def submit(self, call: Callable[[], None], what: str) -> bool:
        """Queue ``call``; False (and one log line) when ``limit`` calls already wait."""
        with self._lock:
            if self._thread is None:
                self._thread = threading.Thread(
                    target=self._run,
                    args=(self._calls, self.log),
                    name="rosserial-calls",
                    daemon=True,
                )
                self._thread.start()
            try:
                self._calls.put_nowait(call)
            except queue.Full:
                self.log.error(
                    f"Service call {what} for the device dropped: {self.limit} calls are "
                    "already waiting"
                )
                return False
        return True

    @staticmethod
    def _run(calls: queue.Queue[Callable[[], None] | None], log: Any) -> None:
        while True:
            call = calls.get()
            if call is None:
                return
            try:
                call()
            except Exception as error:  # the next call must still be made
                log.error(f"A service call for the device failed: {type(error).__name__}: {error}")

    def close(self, timeout: float = 2.0) -> None:
        """End the thread once the call it runs ends (calls still waiting are dropped)."""
        with self._lock:
            thread, calls = self._thread, self._calls
            self._thread = None
            self._calls = queue.Queue(self.limit)
        if thread is None:
            return
        while True:  # make room for the end marker
            try:
                calls.get_nowait()
            except queue.Empty:
                break
        calls.put(None)
        thread.join(timeout)


class DeviceServiceClient(_DeviceService):
    """A service the device calls: its requests go to the bus service, responses come back.

    Args:
        calls: Where the calls are made (None: a queue of its own).
    """

    def __init__(
        self, node: Any, info: Any, send: Send, timeout: float, calls: CallQueue | None = None
    ) -> None:
        super().__init__(node, info, send, timeout)
        self.log.info("Starting service client, waiting for service '%s'", self.topic)
        self.client = node.create_client(self.topic, self.service_class)
        self._own_calls = calls is None
        self.calls = calls if calls is not None else CallQueue(self.log)

    def handle(self, payload: bytes) -> None:
        """A request frame from the device: call the bus service on the call thread."""
        self.calls.submit(lambda: self._call(payload), self.topic)

    def _call(self, payload: bytes) -> None:
        try:
            request = deserialize(payload, self.service_class.Request._type)
            self.client.wait_for_service(self.timeout)
            response = self.client.call(request, timeout=self.timeout)
        except WorkbenchError as error:
            self.log.error(f"Service call {self.topic} for the device failed: {error.one_line()}")
            return
        if self.id >= 0:
            self._send(self.id, serialize(response))

    def close(self) -> None:
        """End its own call thread (a shared :class:`CallQueue` is its owner's to close)."""
        if self._own_calls:
            self.calls.close()
