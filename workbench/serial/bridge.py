"""The rosserial host: one device on one link, bridged to the bus (rosserial_python's SerialClient).

What a :class:`Bridge` does, as ``SerialClient.py`` (noetic-devel) does it, with
the same log lines:

* asks the device for its topics (``Requesting topics...``: an empty frame on id 0)
  and sets up each publisher, subscriber, service server and service client it
  announces (``Setup publisher on chatter [std_msgs/String]``), noting the device's
  buffer sizes once (``Note: publish buffer size is 280 bytes``);
* answers time requests with the bus clock's time (``std_msgs/Time`` on id 10),
  parameter requests from the parameter server (id 6), and forwards the device's
  log messages to its own log and ``/rosout`` at the device's level (id 7);
* after three timeouts (15 s) without a time request, says ``Lost sync with device,
  restarting...`` (or ``Unable to sync with device; ...`` if it never synced) and asks
  again;
* reports damaged input with rosserial_python's lines (wrong checksums, mismatched
  protocol version with the Rev 0/Rev 1 notice, ``Tried to publish before
  configured``) and on ``/diagnostics``, and goes on with the next frame;
* on stop, sends TX_STOP (id 11) so the device stops sending.

Unlike the original it never loses a frame to a damaged neighbour (see
:mod:`workbench.serial.framing`), never blocks reading on a service the device
calls, and keeps its bus endpoints when the link is replaced after a reconnect.
What one device may set up is bounded (:data:`MAX_PUBLISHERS`,
:data:`MAX_SUBSCRIBERS`, :data:`MAX_SERVICES`; ros_lib's own default is 25
publishers and 25 subscribers): a registration past a bound is refused with one
line naming the device and the topic, and :meth:`Bridge.forget_device` removes
everything a device set up (the TCP host calls it when a device disconnects).
"""

from __future__ import annotations

import contextlib
import queue
import threading
import time
from collections.abc import Callable
from typing import Any

from workbench.errors import WorkbenchError
from workbench.msgs import deserialize, get_type, md5sum, serialize
from workbench.serial import framing
from workbench.serial.framing import Frame, FrameDecoder, FrameProblem
from workbench.serial.host_endpoints import (
    CallQueue,
    DevicePublisher,
    DeviceServiceClient,
    DeviceServiceServer,
    DeviceSubscriber,
    check_md5,
)
from workbench.serial.links import LinkLost
from workbench.serial.protocol import (
    FRAME_OVERHEAD,
    ID_LOG,
    ID_PARAMETER_REQUEST,
    ID_PUBLISHER,
    ID_SERVICE_CLIENT,
    ID_SERVICE_SERVER,
    ID_SUBSCRIBER,
    ID_TIME,
    MAX_PAYLOAD,
    PROTOCOL_VER,
    REQUEST_TOPICS,
    TX_STOP,
    encode_frame,
    version_name,
)

ERROR_MISMATCHED_PROTOCOL = (
    "Mismatched protocol version in packet: lost sync or rosserial_python is from different "
    "ros release than the rosserial client"
)
ERROR_NO_SYNC = "no sync with device"
ERROR_PACKET_FAILED = "Packet Failed : Failed to read msg data"
UNABLE_TO_SYNC = (
    "Unable to sync with device; possible link problem or link software version mismatch "
    "such as hydro rosserial_python with groovy Arduino"
)
LOST_SYNC = "Lost sync with device, restarting..."

#: Seconds without new bytes after which a complete frame held back to see the byte after
#: it is delivered (one frame in 256 ends in 0xff and may be held).
SETTLE_WAIT = 0.02
#: Seconds without new bytes after which a frame still incomplete is given up.
IDLE_FLUSH = 0.5
#: At most one topic request per this many seconds for frames on unknown ids.
REQUEST_INTERVAL = 0.5
#: Most publishers one device may set up (ros_lib's default MAX_PUBLISHERS is 25).
MAX_PUBLISHERS = 100
#: Most subscribers one device may set up (ros_lib's default MAX_SUBSCRIBERS is 25).
MAX_SUBSCRIBERS = 100
#: Most services (servers and clients together) one device may set up.
MAX_SERVICES = 100
#: Refusals logged one by one per device before the rest are summed up in one line.
REFUSALS_SHOWN = 10


class RegistrationRefused(WorkbenchError):
    """A device set up more publishers, subscribers or services than the host allows."""


class Bridge:
    """Bridges one rosserial device to the bus through a host node.

    Args:
        node: The host's bus node (``serial_node``).
        timeout: rosserial_python's timeout in seconds: no time request for three of
            them means the sync is lost; also how long a service call waits for the device.
        clock: Monotonic seconds (tests pass their own).
        write_thread: Write frames from a thread of the bridge's own (so a bus callback
            never waits for the port); False writes them in the caller's thread.
    """

    def __init__(
        self,
        node: Any,
        timeout: float = 5.0,
        clock: Callable[[], float] = time.monotonic,
        write_thread: bool = True,
    ) -> None:
        self.node = node
        self.log = node.get_logger()
        self.timeout = timeout
        self.clock = clock
        self.decoder = FrameDecoder()
        self.link: Any = None
        self.publishers: dict[int, DevicePublisher] = {}
        self.subscribers: dict[str, DeviceSubscriber] = {}
        self.service_servers: dict[str, DeviceServiceServer] = {}
        self.service_clients: dict[str, DeviceServiceClient] = {}
        self.callbacks: dict[int, Callable[[bytes], None]] = {}
        self.buffer_out = -1
        self.buffer_in = -1
        self.synced = False
        self.lastsync = clock()
        self.lastsync_lost = 0.0
        self.last_wall_sync = 0.0
        self.frames_in = 0
        self.problems = 0
        self.device = "the device"
        self.refused = 0
        self.calls = CallQueue(self.log)
        self._last_bytes = clock()
        self._last_request = -1e9
        self._writes: queue.SimpleQueue[tuple[bytes, threading.Event | None] | None] = (
            queue.SimpleQueue()
        )
        self._writer: threading.Thread | None = None
        self._threaded = write_thread
        self._write_lock = threading.Lock()
        self._diagnostics = node.create_publisher(
            "/diagnostics", "diagnostic_msgs/DiagnosticArray", queue_size=10
        )
        self._endpoints: dict[int, Callable[[bytes], None]] = {
            ID_PUBLISHER: self._setup_publisher,
            ID_SUBSCRIBER: self._setup_subscriber,
            ID_SERVICE_SERVER + ID_PUBLISHER: self._setup_server_publisher,
            ID_SERVICE_SERVER + ID_SUBSCRIBER: self._setup_server_subscriber,
            ID_SERVICE_CLIENT + ID_PUBLISHER: self._setup_client_publisher,
            ID_SERVICE_CLIENT + ID_SUBSCRIBER: self._setup_client_subscriber,
            ID_PARAMETER_REQUEST: self._parameter_request,
            ID_LOG: self._device_log,
            ID_TIME: self._time_request,
        }

    # --- the link -------------------------------------------------------------------------

    def attach(self, link: Any) -> None:
        """Talk over ``link`` from now on (a new device, or the same one after a reconnect)."""
        self.link = link
        self.device = str(getattr(link, "name", "the device"))
        self.decoder.reset()
        self.decoder.max_length = MAX_PAYLOAD
        self.buffer_out = self.buffer_in = -1
        self.synced = False
        self.lastsync = self._last_bytes = self.clock()
        if self._threaded and self._writer is None:
            self._writer = threading.Thread(
                target=self._write_loop, name="rosserial-tx", daemon=True
            )
            self._writer.start()

    def serve(self, stop: threading.Event) -> None:
        """Read and handle the device's frames until ``stop`` is set.

        Raises:
            LinkLost: The link went away (the caller may reconnect and call again).
        """
        link = self.link
        while not stop.is_set():
            data = link.read_some()
            if data:
                self.receive(data)
            self.tick()

    def receive(self, data: bytes) -> None:
        """Handle bytes that came from the device."""
        self._last_bytes = self.clock()
        self._handle(self.decoder.feed(data))

    def tick(self) -> None:
        """Give up a frame the line went quiet in; say when the sync is lost and ask again."""
        now = self.clock()
        if self.decoder.pending:
            quiet = now - self._last_bytes
            if quiet > IDLE_FLUSH:
                self._handle(self.decoder.flush())
            elif quiet > SETTLE_WAIT:
                self._handle(self.decoder.settle())
        if now - self.lastsync > self.timeout * 3:
            self._sync_lost(now)

    def _handle(self, events: list[Frame | FrameProblem]) -> None:
        for event in events:
            if type(event) is Frame:
                self.synced = True
                self.frames_in += 1
                handler = self.callbacks.get(event.topic_id) or self._endpoints.get(event.topic_id)
                if handler is None:
                    self._unknown_topic(event.topic_id)
                    continue
                try:
                    handler(event.payload)
                except WorkbenchError as error:  # a bus endpoint refused what the device sent
                    self.log.error(error.one_line())
            else:
                self.problems += 1
                self._problem(event)  # type: ignore[arg-type]

    def _sync_lost(self, now: float) -> None:
        self.log.error(LOST_SYNC if self.synced else UNABLE_TO_SYNC)
        self.lastsync_lost = time.time()
        self.send_diagnostics(ERROR_NO_SYNC)
        self.request_topics()
        self.lastsync = now

    def _unknown_topic(self, topic_id: int) -> None:
        now = self.clock()
        if now - self._last_request >= REQUEST_INTERVAL:
            self.log.error("Tried to publish before configured, topic id %d", topic_id)
            self.request_topics()

    def _problem(self, problem: FrameProblem) -> None:
        kind = problem.kind
        if kind == framing.VERSION:
            self.send_diagnostics(ERROR_MISMATCHED_PROTOCOL)
            self.log.error(
                "Mismatched protocol version in packet (%r): lost sync or rosserial_python is "
                "from different ros release than the rosserial client",
                bytes((problem.detail,)),
            )
            found = version_name(problem.detail)
            found_text = (
                "Protocol version of client is unrecognized"
                if found == "unrecognized"
                else f"Protocol version of client is {found}"
            )
            self.log.info("%s, expected %s", found_text, version_name(PROTOCOL_VER))
        elif kind == framing.LENGTH_CHECKSUM:
            self.log.info(
                "Wrong checksum for msg length, length %d, dropping message.", problem.length
            )
        elif kind == framing.TOO_LONG:
            self.log.info(
                "Wrong msg length %d: longer than the device's buffer of %d bytes, dropping "
                "message.",
                problem.length,
                self.decoder.max_length + FRAME_OVERHEAD,
            )
        elif kind in (framing.MESSAGE_CHECKSUM, framing.OVERLAP):
            self.log.info("wrong checksum for topic id and msg")
        elif kind == framing.TRUNCATED:
            self.send_diagnostics(ERROR_PACKET_FAILED)
            self.log.info("Packet Failed :  Failed to read msg data")
            self.log.info("expected msg length is %d", problem.length)
            self.request_topics()
        else:
            self.log.debug("skipped %d bytes that belong to no frame", problem.length)

    # --- sending ----------------------------------------------------------------------------

    def send(self, topic_id: int, payload: bytes) -> None:
        """Queue a frame for the device (dropped while no link is attached)."""
        self._put(encode_frame(topic_id, payload))

    def _put(self, frame: bytes, done: threading.Event | None = None) -> None:
        if self._threaded:
            self._writes.put((frame, done))
            return
        self._write([frame])
        if done is not None:
            done.set()

    def request_topics(self) -> None:
        """Ask the device to announce its topics (``Requesting topics...``)."""
        self.log.info("Requesting topics...")
        self._last_request = self.clock()
        self._discard_input()
        self._put(REQUEST_TOPICS)

    def stop_device(self, timeout: float = 1.0) -> None:
        """Send TX_STOP and wait (up to ``timeout`` s) until it is written."""
        if self.link is None:
            return
        self._discard_input()
        done = threading.Event()
        self._put(TX_STOP, done)
        self.log.info("Sending tx stop request")
        done.wait(timeout)

    def close(self) -> None:
        """Stop the writer and service-call threads (the node's shutdown closes the bus
        endpoints; :meth:`forget_device` closes them now). :meth:`attach` starts them again."""
        self.calls.close()
        if self._writer is not None:
            self._writes.put(None)
            self._writer.join(2.0)
            self._writer = None
            self._writes = queue.SimpleQueue()  # nothing queued for one device reaches the next

    def forget_device(self) -> None:
        """Remove every publisher, subscriber and service the device set up on the bus."""
        endpoints: list[Any] = [
            *self.publishers.values(),
            *self.subscribers.values(),
            *self.service_servers.values(),
            *self.service_clients.values(),
        ]
        self.publishers.clear()
        self.subscribers.clear()
        self.service_servers.clear()
        self.service_clients.clear()
        self.callbacks.clear()
        for endpoint in endpoints:
            try:
                endpoint.close()
            except WorkbenchError as error:
                self.log.error(error.one_line())
        self.calls.close()
        self.refused = 0
        self.buffer_out = self.buffer_in = -1
        self.decoder.max_length = MAX_PAYLOAD

    def _check_room(self, kind: str, count: int, limit: int, topic: str) -> None:
        """Refuse a new ``kind`` on ``topic`` when the device already has ``limit`` of them.

        Raises:
            RegistrationRefused: The device is at the limit (logged by the caller for the
                first :data:`REFUSALS_SHOWN` refusals; later ones raise an empty message).
        """
        if count < limit:
            return
        self.refused += 1
        if self.refused > REFUSALS_SHOWN:
            raise RegistrationRefused("")
        more = (
            f"; further refusals of {self.device} are not logged"
            if self.refused == REFUSALS_SHOWN
            else ""
        )
        raise RegistrationRefused(
            f"{self.device} set up {limit} {kind}s already, the host's limit per device; "
            f"refusing {kind} {topic[:200]}{more}"
        )

    def _discard_input(self) -> None:
        if self.link is not None:
            with contextlib.suppress(LinkLost):  # the reader finds out and reconnects
                self.link.discard_input()
            self.decoder.reset()

    def _write_loop(self) -> None:
        writes = self._writes
        while True:
            item = writes.get()
            if item is None:
                return
            chunks, events = [item[0]], [item[1]]
            while len(chunks) < 64:  # write what queued up meanwhile in one go
                try:
                    more = writes.get_nowait()
                except queue.Empty:
                    break
                if more is None:
                    writes.put(None)
                    break
                chunks.append(more[0])
                events.append(more[1])
            self._write(chunks)
            for event in events:
                if event is not None:
                    event.set()

    def _write(self, chunks: list[bytes]) -> None:
        link = self.link
        if link is not None:
            try:
                with self._write_lock:
                    link.write(b"".join(chunks))
            except LinkLost:
                pass  # the reader sees the same loss and reconnects

    def fits(self, size: int, topic: str) -> bool:
        """Whether a ``size``-byte message for ``topic`` fits the device's input buffer."""
        if self.buffer_in > 0 and size > self.buffer_in:
            self.log.error(
                "Message from ROS network dropped: message larger than buffer. (%s: %d bytes, "
                "the device takes %d)",
                topic,
                size,
                self.buffer_in,
            )
            return False
        return True

    def send_diagnostics(self, text: str) -> None:
        """Publish an ERROR status named ``rosserial_python`` on ``/diagnostics``."""
        array = get_type("diagnostic_msgs/DiagnosticArray")()
        status = get_type("diagnostic_msgs/DiagnosticStatus")(
            level=2, name="rosserial_python", message=text
        )
        pair = get_type("diagnostic_msgs/KeyValue")
        last = time.ctime(self.last_wall_sync) if self.last_wall_sync else "never"
        status.values = [
            pair(key="last sync", value=last),
            pair(key="last sync lost", value=time.ctime(self.lastsync_lost)),
        ]
        array.header.stamp = self.node.now()
        array.status = [status]
        self._diagnostics.publish(array)

    # --- negotiation ------------------------------------------------------------------------

    def _topic_info(self, payload: bytes) -> Any:
        return deserialize(payload, "rosserial_msgs/TopicInfo")

    def _set_publish_size(self, size: int) -> None:
        if self.buffer_out < 0:
            self.buffer_out = size
            self.log.info("Note: publish buffer size is %d bytes", size)
        # a device sends no frame longer than its buffer: longer claims are damage
        biggest = max(size - FRAME_OVERHEAD, 0)
        if self.decoder.max_length == MAX_PAYLOAD or biggest > self.decoder.max_length:
            self.decoder.max_length = min(biggest, MAX_PAYLOAD) if biggest else MAX_PAYLOAD

    def _set_subscribe_size(self, size: int) -> None:
        if self.buffer_in < 0:
            self.buffer_in = size
            self.log.info("Note: subscribe buffer size is %d bytes", size)

    def _refusal(self, kind: str, error: WorkbenchError) -> None:
        if error.message:  # refusals past REFUSALS_SHOWN say nothing
            self.log.error("Creation of %s failed: %s", kind, error.one_line())

    def _setup_publisher(self, payload: bytes) -> None:
        try:
            info = self._topic_info(payload)
            old = self.publishers.get(info.topic_id)
            if old is None:
                self._check_room("publisher", len(self.publishers), MAX_PUBLISHERS, info.topic_name)
            if old is None or not old.same(info):
                if old is not None:
                    old.close()
                publisher = DevicePublisher(self.node, info)
                self.publishers[info.topic_id] = publisher
                self.callbacks[info.topic_id] = publisher.handle
            else:
                check_md5(md5sum(old.type), info.md5sum)
            self._set_publish_size(info.buffer_size)
            self.log.info("Setup publisher on %s [%s]", info.topic_name, info.message_type)
        except WorkbenchError as error:
            self._refusal("publisher", error)

    def _setup_subscriber(self, payload: bytes) -> None:
        try:
            info = self._topic_info(payload)
            old = self.subscribers.get(info.topic_name)
            if old is None:
                self._check_room(
                    "subscriber", len(self.subscribers), MAX_SUBSCRIBERS, info.topic_name
                )
                self.subscribers[info.topic_name] = DeviceSubscriber(
                    self.node, info, self.send, self.fits
                )
                self._set_subscribe_size(info.buffer_size)
                self.log.info("Setup subscriber on %s [%s]", info.topic_name, info.message_type)
            elif info.message_type != old.type:
                old.close()
                self.subscribers[info.topic_name] = DeviceSubscriber(
                    self.node, info, self.send, self.fits
                )
                self._set_subscribe_size(info.buffer_size)
                self.log.info(
                    "Change the message type of subscriber on %s from [%s] to [%s]",
                    info.topic_name,
                    old.type,
                    info.message_type,
                )
            else:
                old.id = int(info.topic_id)  # the same subscriber, maybe renumbered
        except WorkbenchError as error:
            self._refusal("subscriber", error)

    def _service(self, info: Any, kind: str) -> Any:
        table: dict[str, Any] = self.service_servers if kind == "server" else self.service_clients
        service = table.get(info.topic_name)
        if service is None:
            count = len(self.service_servers) + len(self.service_clients)
            self._check_room("service", count, MAX_SERVICES, info.topic_name)
            if kind == "server":
                service = DeviceServiceServer(self.node, info, self.send, self.timeout)
            else:
                service = DeviceServiceClient(self.node, info, self.send, self.timeout, self.calls)
            self.log.info("Setup service %s on %s [%s]", kind, info.topic_name, info.message_type)
            table[info.topic_name] = service
        return service

    def _setup_service(self, payload: bytes, kind: str, device_publishes: bool) -> None:
        """One of a service's two TopicInfos: the device's publisher or its subscriber."""
        try:
            info = self._topic_info(payload)
            if device_publishes:
                self._set_publish_size(info.buffer_size)
            else:
                self._set_subscribe_size(info.buffer_size)
            service = self._service(info, kind)
            # the server publishes responses and takes requests; the client the reverse
            sends_response = device_publishes == (kind == "server")
            ours = service.response_md5() if sends_response else service.request_md5()
            check_md5(ours, info.md5sum)
            if device_publishes:
                self.callbacks[info.topic_id] = service.handle
            else:
                service.id = int(info.topic_id)
        except WorkbenchError as error:
            self._refusal(f"service {kind}", error)

    def _setup_server_publisher(self, payload: bytes) -> None:
        self._setup_service(payload, "server", device_publishes=True)

    def _setup_server_subscriber(self, payload: bytes) -> None:
        self._setup_service(payload, "server", device_publishes=False)

    def _setup_client_publisher(self, payload: bytes) -> None:
        self._setup_service(payload, "client", device_publishes=True)

    def _setup_client_subscriber(self, payload: bytes) -> None:
        self._setup_service(payload, "client", device_publishes=False)

    # --- time, parameters, logging ----------------------------------------------------------

    def _time_request(self, payload: bytes) -> None:
        reply = get_type("std_msgs/Time")(data=self.node.now())
        self.send(ID_TIME, serialize(reply))
        self.lastsync = self.clock()
        self.last_wall_sync = time.time()

    def _parameter_request(self, payload: bytes) -> None:
        from workbench.serial.parameters import parameter_response

        request: Any = deserialize(payload, "rosserial_msgs/RequestParamRequest")
        response = parameter_response(self.node, request.name, self.log)
        if response is not None:
            self.send(ID_PARAMETER_REQUEST, serialize(response))

    def _device_log(self, payload: bytes) -> None:
        message: Any = deserialize(payload, "rosserial_msgs/Log")
        write = {
            0: self.log.debug,
            1: self.log.info,
            2: self.log.warn,
            3: self.log.error,
            4: self.log.fatal,
        }.get(message.level)
        if write is None:
            self.log.warn("device log message of unknown level %d: %s", message.level, message.msg)
        else:
            write(message.msg)
