"""The device side of rosserial, in Python: ros_lib's ``ros::NodeHandle`` and friends.

A sketch written against this module reads like its C++ original, line by line::

    #include <ros.h>                              from workbench.serial import device as ros
    #include <std_msgs/String.h>                  from workbench.msgs.std_msgs import String
    ros::NodeHandle nh;                           nh = ros.NodeHandle()
    std_msgs::String str_msg;                     str_msg = String()
    ros::Publisher chatter("chatter", &str_msg);  chatter = ros.Publisher("chatter", str_msg)
    nh.initNode(); nh.advertise(chatter);         nh.initNode(); nh.advertise(chatter)
    chatter.publish(&str_msg); nh.spinOnce();     chatter.publish(str_msg); nh.spinOnce()

It follows rosserial_client's ``ros/node_handle.h`` (noetic-devel): subscribers get
topic ids from 100 and publishers from ``100 + MAX_SUBSCRIBERS``; the device
negotiates only when the host asks (an empty frame on id 0), then requests the time;
it asks for the time again every 2.5 s, counts itself disconnected after 11 s
without an answer, stops publishing on TX_STOP, drops a message larger than its
output buffer ("Message from device dropped: message larger than buffer."), and
``getParam`` fills a list (C++ fills an array) or says "Failed to get param: ...".

The buffer sizes are those of the board the sketch runs on (an Uno: 280 bytes, a
Mega: 512), unless the sketch gives them, as ``ros::NodeHandle_<ArduinoHardware, 25,
25, 200, 200>`` would: ``ros.NodeHandle_(25, 25, 200, 200)``.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from typing import Any, Protocol

from workbench.errors import MessageError
from workbench.msgs import Message, deserialize, get_type, md5sum, serialize
from workbench.serial.framing import VERSION, Frame, FrameDecoder, FrameProblem
from workbench.serial.protocol import (
    FIRST_TOPIC_ID,
    FRAME_OVERHEAD,
    ID_LOG,
    ID_PARAMETER_REQUEST,
    ID_PUBLISHER,
    ID_SERVICE_CLIENT,
    ID_SERVICE_SERVER,
    ID_SUBSCRIBER,
    ID_TIME,
    ID_TX_STOP,
    LOG_DEBUG,
    LOG_ERROR,
    LOG_FATAL,
    LOG_INFO,
    LOG_WARN,
    encode_frame,
)

SPIN_OK = 0
SPIN_ERR = -1
SPIN_TIMEOUT = -2
SPIN_TX_STOP_REQUESTED = -3
SPIN_TIME_RECV = -4

SYNC_SECONDS = 5
#: Milliseconds a frame from the host may take to arrive completely.
SERIAL_MSG_TIMEOUT = 20


class Hardware(Protocol):
    """What a NodeHandle needs from its board (ros_lib's ``Hardware`` template argument)."""

    def read_available(self) -> bytes:
        """The bytes received since the last call (never blocks)."""
        ...

    def write(self, data: bytes) -> None:
        """Send bytes to the host."""
        ...

    def time(self) -> int:
        """Milliseconds since the board started."""
        ...

    def wait(self, seconds: float) -> None:
        """Sleep up to ``seconds``, less if bytes arrive."""
        ...


def _message_type(msg: Any) -> type[Message]:
    if isinstance(msg, Message):
        return type(msg)
    if isinstance(msg, str):
        return get_type(msg)
    if isinstance(msg, type) and issubclass(msg, Message):
        return msg
    raise MessageError(f"a message, message class or type name is needed, not {msg!r}")


class Publisher:
    """``ros::Publisher``: ``Publisher("chatter", str_msg)`` (a message or its class)."""

    def __init__(self, topic_name: str, msg: Any, endpoint: int = ID_PUBLISHER) -> None:
        self.topic_ = topic_name
        self.msg_class = _message_type(msg)
        self.type_name = self.msg_class._type
        self.md5 = md5sum(self.type_name)
        self.endpoint_ = endpoint
        self.id_ = -1
        self.nh_: NodeHandle | None = None

    def publish(self, msg: Message) -> int:
        """Send ``msg`` (bytes written, 0 before the host configured the device, -1 too big)."""
        if self.nh_ is None:
            return 0
        return self.nh_.publish(self.id_, msg)

    def getEndpointType(self) -> int:  # noqa: N802 - ros_lib's name
        return self.endpoint_


class Subscriber:
    """``ros::Subscriber<MsgT>``: ``Subscriber("toggle_led", Empty, messageCb)``."""

    def __init__(
        self,
        topic_name: str,
        msg_type: Any,
        callback: Callable[[Any], Any],
        endpoint: int = ID_SUBSCRIBER,
    ) -> None:
        self.topic_ = topic_name
        self.msg_class = _message_type(msg_type)
        self.type_name = self.msg_class._type  # what TopicInfo says (a service: its type)
        self.md5 = md5sum(self.msg_class._type)
        self.cb_ = callback
        self.endpoint_ = endpoint
        self.id_ = -1

    def callback(self, data: bytes) -> None:
        self.cb_(deserialize(data, self.msg_class._type))

    def getEndpointType(self) -> int:  # noqa: N802
        return self.endpoint_


def _fill(target: Message, source: Message) -> None:
    """Copy every field of ``source`` into ``target`` (C++ deserializes in place)."""
    for name in source.__slots__:
        setattr(target, name, getattr(source, name))


class ServiceServer(Subscriber):
    """``ros::ServiceServer<Req, Res>``: ``ServiceServer("name", SrvType, callback(req, res))``."""

    def __init__(self, topic_name: str, srv_type: Any, callback: Callable[[Any, Any], Any]):
        srv = get_type(srv_type) if isinstance(srv_type, str) else srv_type
        self.srv = srv
        self.req = srv.Request()
        self.resp = srv.Response()
        super().__init__(topic_name, srv.Request, self._serve, ID_SERVICE_SERVER + ID_SUBSCRIBER)
        self.type_name = srv._type
        self.pub = Publisher(topic_name, srv.Response, ID_SERVICE_SERVER + ID_PUBLISHER)
        self.pub.type_name = srv._type
        self.srv_cb_ = callback

    def _serve(self, req: Any) -> None:
        _fill(self.req, req)
        self.srv_cb_(self.req, self.resp)
        self.pub.publish(self.resp)


class ServiceClient(Subscriber):
    """``ros::ServiceClient<Req, Res>``: ``client.call(req, res)`` fills ``res``."""

    def __init__(self, topic_name: str, srv_type: Any) -> None:
        srv = get_type(srv_type) if isinstance(srv_type, str) else srv_type
        self.srv = srv
        super().__init__(topic_name, srv.Response, self._answer, ID_SERVICE_CLIENT + ID_SUBSCRIBER)
        self.type_name = srv._type
        self.pub = Publisher(topic_name, srv.Request, ID_SERVICE_CLIENT + ID_PUBLISHER)
        self.pub.type_name = srv._type
        self.waiting = False
        self._ret: Any = None

    def _answer(self, response: Any) -> None:
        if self._ret is not None:
            _fill(self._ret, response)
        self.waiting = False

    def call(self, request: Any, response: Any) -> None:
        """Send ``request`` and spin until the response arrives (or the link drops)."""
        nh = self.pub.nh_
        if nh is None or not nh.connected():
            return
        self._ret = response
        self.waiting = True
        self.pub.publish(request)
        while self.waiting and nh.connected():
            if nh.spinOnce() < 0:
                break
            nh.pause()


class NodeHandle:
    """``ros::NodeHandle``: the device's link to the host.

    Args:
        max_subscribers: ``MAX_SUBSCRIBERS`` (None: the board's).
        max_publishers: ``MAX_PUBLISHERS`` (None: the board's).
        input_size: Bytes of the input buffer (None: the board's).
        output_size: Bytes of the output buffer (None: the board's).
        hardware: The board's serial port; None takes the board the sketch runs on
            when :meth:`initNode` is called.
    """

    def __init__(
        self,
        max_subscribers: int | None = None,
        max_publishers: int | None = None,
        input_size: int | None = None,
        output_size: int | None = None,
        hardware: Hardware | None = None,
    ) -> None:
        self._sizes = (max_subscribers, max_publishers, input_size, output_size)
        self.hardware: Any = hardware
        self.board: Any = None
        self.max_subscribers = max_subscribers or 25
        self.max_publishers = max_publishers or 25
        self.input_size = input_size or 512
        self.output_size = output_size or 512
        self.publishers: list[Publisher | None] = []
        self.subscribers: list[Subscriber | None] = []
        self.configured_ = False
        self.decoder = FrameDecoder(patient=False)
        self._events: deque[Frame | FrameProblem] = deque()
        self._pending_since: int | None = None
        self.rt_time = 0
        self.sec_offset = 0
        self.nsec_offset = 0
        self.last_sync_time = 0
        self.last_sync_receive_time = 0
        self.param_received = False
        self.req_param_resp: Any = None

    # --- setup --------------------------------------------------------------------------

    def initNode(self) -> None:  # noqa: N802
        """Start the serial port (the board's, unless one was given) and size the buffers."""
        if self.hardware is None:
            from workbench.serial.arduino import current_board

            board = current_board()
            self.board = board
            self.hardware = board.hardware
            defaults = board.profile.sizes
        else:
            defaults = (25, 25, 512, 512)
        chosen = [given or default for given, default in zip(self._sizes, defaults, strict=True)]
        self.max_subscribers, self.max_publishers, self.input_size, self.output_size = chosen
        self.publishers = [None] * self.max_publishers
        self.subscribers = [None] * self.max_subscribers
        self.decoder = FrameDecoder(max(self.input_size - FRAME_OVERHEAD, 0), patient=False)
        self._events.clear()
        self.last_sync_receive_time = self.hardware.time()

    def advertise(self, p: Publisher) -> bool:
        """Give ``p`` a publisher id (False: all ``MAX_PUBLISHERS`` slots are taken)."""
        for i, slot in enumerate(self.publishers):
            if slot is None:
                self.publishers[i] = p
                p.id_ = i + FIRST_TOPIC_ID + self.max_subscribers
                p.nh_ = self
                return True
        return False

    def subscribe(self, s: Subscriber) -> bool:
        """Give ``s`` a subscriber id (False: all ``MAX_SUBSCRIBERS`` slots are taken)."""
        for i, slot in enumerate(self.subscribers):
            if slot is None:
                self.subscribers[i] = s
                s.id_ = i + FIRST_TOPIC_ID
                return True
        return False

    def advertiseService(self, srv: ServiceServer) -> bool:  # noqa: N802
        return self.advertise(srv.pub) and self.subscribe(srv)

    def serviceClient(self, srv: ServiceClient) -> bool:  # noqa: N802
        return self.advertise(srv.pub) and self.subscribe(srv)

    def connected(self) -> bool:
        """Whether the host has configured this device (and still syncs with it)."""
        return self.configured_

    def pause(self) -> None:
        """Wait a millisecond inside a blocking call (a stopped board ends the sketch here)."""
        if self.board is not None:
            self.board.delay(1)
        else:
            self.hardware.wait(0.001)

    # --- the loop -----------------------------------------------------------------------

    def spinOnce(self) -> int:  # noqa: N802
        """Handle what the host sent; ``SPIN_OK``, ``SPIN_ERR`` (just negotiated) or another code."""
        hardware = self.hardware
        c_time = hardware.time()
        if c_time - self.last_sync_receive_time > SYNC_SECONDS * 2200:
            self.configured_ = False
        data = hardware.read_available()
        if data:
            fed = self.decoder.feed(data)
            if any(type(event) is Frame for event in fed):
                self._pending_since = None  # progress: a frame still coming starts its clock now
            self._events.extend(fed)
        if self.decoder.pending:
            if self._pending_since is None:
                self._pending_since = c_time
            elif c_time - self._pending_since > SERIAL_MSG_TIMEOUT:
                self._events.extend(self.decoder.flush())
                self._pending_since = None
        else:
            self._pending_since = None
        saw_time = tx_stop = False
        events = self._events
        while events:
            event = events.popleft()
            if type(event) is not Frame:
                if event.kind == VERSION and not self.configured_:  # type: ignore[union-attr]
                    self.requestSyncTime()  # show the host which protocol this side speaks
                continue
            topic = event.topic_id
            if topic == ID_PUBLISHER:
                self.requestSyncTime()
                self.negotiateTopics()
                self.last_sync_time = self.last_sync_receive_time = c_time
                return SPIN_ERR
            if topic == ID_TIME:
                saw_time = True
                self.syncTime(event.payload)
            elif topic == ID_PARAMETER_REQUEST:
                self._param_response(event.payload)
            elif topic == ID_TX_STOP:
                self.configured_ = False
                tx_stop = True
            else:
                self._deliver(topic, event.payload)
        if self.configured_ and c_time - self.last_sync_time > SYNC_SECONDS * 500:
            self.requestSyncTime()
            self.last_sync_time = c_time
        if saw_time:
            return SPIN_TIME_RECV
        return SPIN_TX_STOP_REQUESTED if tx_stop else SPIN_OK

    def _deliver(self, topic: int, payload: bytes) -> None:
        index = topic - FIRST_TOPIC_ID
        if 0 <= index < len(self.subscribers):
            subscriber = self.subscribers[index]
            if subscriber is not None:
                try:
                    subscriber.callback(payload)
                except MessageError:
                    self.logerror(f"Cannot decode the message on {subscriber.topic_}")

    def _param_response(self, payload: bytes) -> None:
        try:
            self.req_param_resp = deserialize(payload, "rosserial_msgs/RequestParamResponse")
        except MessageError:
            return
        self.param_received = True

    # --- time ---------------------------------------------------------------------------

    def requestSyncTime(self) -> None:  # noqa: N802
        self.publish(ID_TIME, get_type("std_msgs/Time")())
        self.rt_time = self.hardware.time()

    def syncTime(self, data: bytes) -> None:  # noqa: N802
        try:
            stamp: Any = deserialize(data, "std_msgs/Time")
        except MessageError:
            return
        offset = self.hardware.time() - self.rt_time
        sec = stamp.data.sec + offset // 1000
        nsec = stamp.data.nanosec + (offset % 1000) * 1_000_000
        self.setNow(sec, nsec)
        self.last_sync_receive_time = self.hardware.time()

    def now(self) -> Any:
        """The host's time, kept by the board's clock since the last sync (a ``Time``)."""
        ms = self.hardware.time()
        total = (ms // 1000 + self.sec_offset) * 1_000_000_000 + (
            (ms % 1000) * 1_000_000 + self.nsec_offset
        )
        return get_type("builtin_interfaces/Time")(*divmod(total, 1_000_000_000))

    def setNow(self, sec: int, nsec: int) -> None:  # noqa: N802
        ms = self.hardware.time()
        self.sec_offset = sec - ms // 1000
        self.nsec_offset = nsec - (ms % 1000) * 1_000_000

    # --- negotiation and publishing ---------------------------------------------------------

    def negotiateTopics(self) -> None:  # noqa: N802
        """Announce every publisher and subscriber (TopicInfo) and count as configured."""
        info = get_type("rosserial_msgs/TopicInfo")
        endpoints: list[tuple[list[Any], int]] = [
            (self.publishers, self.output_size),
            (self.subscribers, self.input_size),
        ]
        for slots, buffer_size in endpoints:
            for endpoint in slots:
                if endpoint is not None:
                    ti = info(
                        topic_id=endpoint.id_,
                        topic_name=endpoint.topic_,
                        message_type=endpoint.type_name,
                        md5sum=endpoint.md5,
                        buffer_size=buffer_size,
                    )
                    self.publish(endpoint.getEndpointType(), ti)
        self.configured_ = True

    def publish(self, id: int, msg: Message) -> int:  # noqa: A002 - ros_lib's signature
        """Send ``msg`` on topic ``id``: bytes written, 0 if not configured, -1 if too big."""
        if id >= FIRST_TOPIC_ID and not self.configured_:
            return 0
        payload = serialize(msg)
        size = len(payload) + FRAME_OVERHEAD
        if size <= self.output_size:
            self.hardware.write(encode_frame(id, payload))
            return size
        self.logerror("Message from device dropped: message larger than buffer.")
        return -1

    # --- logging ------------------------------------------------------------------------

    def log(self, level: int, msg: str) -> None:
        self.publish(ID_LOG, get_type("rosserial_msgs/Log")(level=level, msg=msg))

    def logdebug(self, msg: str) -> None:
        self.log(LOG_DEBUG, msg)

    def loginfo(self, msg: str) -> None:
        self.log(LOG_INFO, msg)

    def logwarn(self, msg: str) -> None:
        self.log(LOG_WARN, msg)

    def logerror(self, msg: str) -> None:
        self.log(LOG_ERROR, msg)

    def logfatal(self, msg: str) -> None:
        self.log(LOG_FATAL, msg)

    # --- parameters ---------------------------------------------------------------------

    def requestParam(self, name: str, time_out: int = 1000) -> bool:  # noqa: N802
        self.param_received = False
        request = get_type("rosserial_msgs/RequestParamRequest")(name=name)
        self.publish(ID_PARAMETER_REQUEST, request)
        end_time = self.hardware.time() + time_out
        while not self.param_received:
            self.spinOnce()
            if self.hardware.time() > end_time:
                self.logwarn("Failed to get param: timeout expired")
                return False
            if not self.param_received:
                self.pause()
        return True

    def getParam(
        self, name: str, param: list, length: int | None = None, timeout: int = 1000
    ) -> bool:  # noqa: N802
        """Fill the list ``param`` with parameter ``name`` (C++ fills an array).

        The list's first element says the type, as the C++ overload does: an int or a
        bool reads ``ints``, a float ``floats``, a str ``strings``. ``length`` defaults to
        the list's length; a parameter of another length fails ("length mismatch").
        """
        length = len(param) if length is None else length
        if not param:
            return False
        if not self.requestParam(name, timeout):
            return False
        kind = type(param[0])
        resp = self.req_param_resp
        values = (
            list(resp.floats) if kind is float else resp.strings if kind is str else list(resp.ints)
        )
        if len(values) != length:
            self.logwarn("Failed to get param: length mismatch")
            return False
        for i, value in enumerate(values):
            param[i] = bool(value) if kind is bool else kind(value)
        return True


#: ``ros::NodeHandle_<Hardware, MAX_SUBSCRIBERS, MAX_PUBLISHERS, INPUT_SIZE, OUTPUT_SIZE>``.
NodeHandle_ = NodeHandle
