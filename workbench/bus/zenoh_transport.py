"""The Zenoh transport of a bus: topics, services, graph and parameters across processes.

It implements :class:`~workbench.bus.transport.Transport`; ``zenoh`` is
imported only here (and in :mod:`workbench.bus.zconfig`).

One Zenoh session (client mode, connected to the core's router) per joined
bus. The same ROS 1 bytes as in bags go on the wire; publishers block
rather than drop under congestion (reliable delivery). Nodes and endpoints
are Zenoh liveliness tokens, so a process that exits or is killed vanishes
from every other process's graph. Before a session closes (node shutdown,
bus shutdown, interpreter exit) it flushes: a barrier query to each
subscribing session waits until what was published has arrived there.
The publishing node's name travels in the data key (ROS's ``callerid``).

A latched publisher numbers its messages (the sample's attachment is
``"<publisher id> <number>"``, and its latched reply carries the same), so
a subscriber that gets one message both live and as the latched reply of a
publisher it just found takes it once, and knows the publisher latches.
"""

from __future__ import annotations

import atexit
import functools
import itertools
import os
import sys
import threading
import time
import traceback
import weakref
from collections.abc import Callable, Iterable
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any

from workbench.bus import keys
from workbench.bus.entities import RawMessage
from workbench.bus.errors import CoreError, ServiceError, ServiceTimeout
from workbench.bus.graph import Endpoint
from workbench.bus.remote_params import RemoteParams
from workbench.bus.wire import (
    check_size,
    guarded,
    install_panic_hooks,
    is_transport_panic,
    transport_failed,
)
from workbench.bus.zconfig import client_config, parse_uri, port_open, zenoh_module
from workbench.errors import MessageError
from workbench.msgs import deserialize, serialize

if TYPE_CHECKING:
    from workbench.bus.bus import Bus
    from workbench.bus.entities import Client, Publisher, ServiceServer, Subscription
    from workbench.bus.node import Node
    from workbench.bus.transport import Sender

#: Seconds a service call waits when the caller gives no timeout (rospy waits forever).
NO_TIMEOUT = 24 * 3600.0

#: Seconds a closing node or process waits, at most, for slower subscribers in other
#: processes to receive what it published (``WORKBENCH_FLUSH_TIMEOUT`` overrides).
FLUSH_TIMEOUT = 10.0

#: Seconds before a flush's timeout by which a barrier query that ended unanswered counts as
#: "the subscriber's session has closed" rather than "did not confirm in time".
GONE_MARGIN = 0.25

#: Samples a raw subscription's channel holds before Zenoh waits (backpressure, no loss).
RAW_CHANNEL_SIZE = 65536

#: Consecutive failures of a raw subscription's pump thread before it gives up.
PUMP_RESTARTS = 5

#: Numbers the latched publishers of this process (part of their messages' attachment).
_latched_ids = itertools.count(1)


class _Latched:
    """The last message of a latched publisher, numbered (what its queryable answers)."""

    __slots__ = ("origin", "seq", "msg", "data", "lock")

    def __init__(self, origin: str) -> None:
        self.origin = origin  # unique to this publisher instance, across processes
        self.seq = 0  # number of the last message sent
        self.msg: Any = None  # the last message sent, and its bytes
        self.data = b""
        self.lock = threading.Lock()

    def attachment(self, seq: int) -> str:
        return f"{self.origin} {seq}"


def parse_latched(attachment: Any) -> tuple[str, int] | None:
    """A latched publisher's attachment -> ``(publisher id, message number)``."""
    if attachment is None:
        return None
    origin, _, seq = attachment.to_string().rpartition(" ")
    try:
        return origin, int(seq)
    except ValueError:
        return None


def report(text: str) -> None:
    """Print an error line of the transport (its threads have no node to log through)."""
    print(f"[ERROR] {text}", file=sys.stderr, flush=True)


def flush_timeout() -> float:
    """``WORKBENCH_FLUSH_TIMEOUT`` in seconds, or :data:`FLUSH_TIMEOUT`."""
    try:
        return max(0.0, float(os.environ.get("WORKBENCH_FLUSH_TIMEOUT", FLUSH_TIMEOUT)))
    except ValueError:
        return FLUSH_TIMEOUT


class ZenohTransport:
    """Connects a :class:`~workbench.bus.Bus` to the core at ``uri``.

    Raises:
        CoreError: Nothing answers at ``uri``, or it is not a workbench core.
    """

    def __init__(self, bus: Bus, uri: str) -> None:
        _proto, host, port = parse_uri(uri)
        if _proto == "tcp" and not port_open(host, port):
            raise CoreError(
                f"no workbench core at {uri}",
                hint="start one with 'workbench core', or set WORKBENCH_MASTER_URI",
            )
        zenoh = zenoh_module()
        self._z = zenoh
        install_panic_hooks()
        try:
            self.session = zenoh.open(client_config(uri))
        except zenoh.ZError as error:
            raise CoreError(f"cannot connect to the core at {uri}: {error}") from None
        self.uri = uri
        self.bus_ref = weakref.ref(bus)
        self._subscribers = bus.local.subscription_table().get
        self._clock = bus.clock
        self.sid = str(self.session.zid())
        self.pid = os.getpid()
        self.params = RemoteParams(self.session, uri)
        self._lock = threading.RLock()
        self._closed = False
        self._tokens: dict[int, Any] = {}  # id(entity) -> liveliness token
        self._declared: dict[int, list[Any]] = {}  # id(entity) -> zenoh publishers/queryables
        # (topic, raw) -> (zenoh subscriber, number of subscriptions using it)
        self._topic_subs: dict[tuple[str, bool], tuple[Any, int]] = {}
        self._remote: dict[str, keys.Token] = {}
        self._warned: set[tuple[str, str, str]] = set()
        self._parsed_keys: dict[str, tuple[str, str, str, str]] = {}
        self._unflushed: set[str] = set()  # topics published on since the last flush
        self._pumps: list[threading.Thread] = []  # threads draining raw subscriptions
        # id(subscription) -> latched publisher id -> number of the last message delivered
        self._latched_seen: dict[int, dict[str, int]] = {}
        self._latched_lock = threading.Lock()  # delivery of latched publishers' messages
        self._pool = ThreadPoolExecutor(max_workers=4, thread_name_prefix="workbench-service")
        if not self._ping_core():
            self.session.close()
            raise CoreError(
                f"something listens at {uri} but does not answer as a workbench core",
                hint="start 'workbench core' there, or point WORKBENCH_MASTER_URI elsewhere",
            ) from None
        self._graph_sub = self.session.liveliness().declare_subscriber(
            "wb/g/**", self._handler(self._on_token, "the graph (liveliness)"), history=True
        )
        # Answered on the receive thread, so only after every sample that arrived before it.
        self._barrier = self.session.declare_queryable(
            keys.barrier_key(self.sid), self._handler(self._on_barrier, "the flush barrier")
        )
        self.refresh_graph()
        atexit.register(self.close)

    def _ping_core(self, patience: float = 5.0) -> bool:
        # A core that is just starting listens before its parameter server answers.
        deadline = time.monotonic() + patience
        while True:
            try:
                self.params._ask("has", timeout=1.0, name="/")
                return True
            except CoreError:
                if time.monotonic() > deadline:
                    return False
                time.sleep(0.1)

    def _on_barrier(self, query: Any) -> None:
        try:
            query.reply(query.key_expr, b"")
        finally:
            self._finish(query, "the flush barrier")

    def _finish(self, query: Any, what: str) -> None:
        """Drop a query (its reply is sent then); a failure is logged, not raised."""
        try:
            query.drop()
        except self._z.ZError as error:
            report(f"closing a query of {what}: {error}")

    def _undeclare(self, item: Any, what: str) -> None:
        try:
            item.undeclare()
        except self._z.ZError as error:
            if not self._closed:  # once closed, the session took everything with it
                report(f"undeclaring the Zenoh object of {what}: {error}")

    def flush(self, topics: Iterable[str] | None = None, timeout: float | None = None) -> bool:
        """Wait until subscribers in other processes have what was published so far.

        Zenoh queues messages on their way to a slower subscriber; a session that
        closes drops what is still queued. This sends a barrier query to every
        session subscribed to a topic published on since the last flush, on the
        same path and priority as the data, and waits for the answers: a session
        answers once it has handed every earlier message to its subscriptions.

        Args:
            topics: Only these topics (default: all published on).
            timeout: Seconds to wait at most (default :func:`flush_timeout`).

        Returns:
            Whether every subscribing session confirmed in time (``True`` if none).
        """
        with self._lock:
            if self._closed:
                return True
            wanted = set(self._unflushed) if topics is None else self._unflushed & set(topics)
            self._unflushed -= wanted
            sessions = {
                t.session
                for t in self._remote.values()
                if t.kind == "sub" and t.name in wanted and t.session != self.sid
            }
        if not sessions:
            return True
        z = self._z
        timeout = flush_timeout() if timeout is None else timeout
        started = time.monotonic()
        pending = []
        for sid in sorted(sessions):
            try:
                pending.append(
                    self.session.get(
                        keys.barrier_key(sid),
                        timeout=max(timeout, 0.001),
                        congestion_control=z.CongestionControl.BLOCK,
                        priority=z.Priority.DATA,
                        express=False,
                    )
                )
            except self._z.ZError as error:  # the session is closing under us
                report(f"flushing {', '.join(sorted(wanted))}: {error}; not waiting for receipt")
                return False
        missing = 0
        for replies in pending:
            if any(reply.ok is not None for reply in replies):
                continue
            # A query that ends well before its timeout without an answer found no barrier:
            # that subscriber's session has closed since its token was seen, and nothing
            # queued for it can be delivered or lost any more.
            if time.monotonic() - started < timeout - GONE_MARGIN:
                continue
            missing += 1
        if missing:
            waited = time.monotonic() - started
            print(
                f"[WARN] {missing} subscriber process(es) of {', '.join(sorted(wanted))} did not "
                f"confirm receipt within {waited:.1f} s; messages still queued for them may be "
                "lost (WORKBENCH_FLUSH_TIMEOUT sets the wait)",
                file=sys.stderr,
                flush=True,
            )
            return False
        return True

    def _handler(self, function: Callable[[Any], None], what: str) -> Any:
        """A Zenoh callback running ``function`` that logs (names ``what``) what it raises.

        Callbacks run on Zenoh's own threads: the default ("indirect") handlers start
        non-daemon Python threads that would keep a finished script from exiting.
        """

        def logged(item: Any) -> None:
            try:
                function(item)
            except Exception as error:  # Zenoh's thread must keep serving everyone else
                report(
                    f"Zenoh callback for {what} raised {type(error).__name__}: {error}\n"
                    f"{traceback.format_exc().rstrip()}"
                )
            except BaseException as error:
                if is_transport_panic(error):
                    transport_failed(f"the Zenoh callback for {what}", error)
                raise

        return self._z.handlers.Callback(logged, indirect=False)

    # --- graph ----------------------------------------------------------------------------

    def _on_token(self, sample: Any) -> None:
        key = str(sample.key_expr)
        token = keys.parse_token(key)
        if token is None or token.session == self.sid:
            return
        with self._lock:
            if sample.kind == self._z.SampleKind.DELETE:
                self._remote.pop(key, None)
            else:
                self._remote[key] = token
        bus = self.bus_ref()
        if bus is not None:
            bus.graph_changed()

    def refresh_graph(self, timeout: float = 2.0) -> None:
        """Ask the core for every live token now (so a fresh tool sees the whole graph)."""
        found: dict[str, keys.Token] = {}
        for reply in self.session.liveliness().get("wb/g/**", timeout=timeout):
            if reply.ok is not None:
                key = str(reply.ok.key_expr)
                token = keys.parse_token(key)
                if token is not None and token.session != self.sid:
                    found[key] = token
        with self._lock:
            self._remote.update(found)

    def remote_nodes(self) -> dict[str, int]:
        with self._lock:
            return {t.node: t.pid for t in self._remote.values() if t.kind == "n"}

    def remote_endpoints(self) -> list[Endpoint]:
        with self._lock:
            tokens = list(self._remote.values())
        return [
            Endpoint(t.node, t.kind, t.name, t.type, t.md5, local=False)
            for t in tokens
            if t.kind != "n"
        ]

    def has_service(self, name: str) -> bool:
        with self._lock:
            return any(t.kind == "srv" and t.name == name for t in self._remote.values())

    def _token(self, entity: Any, key: str) -> None:
        token = self.session.liveliness().declare_token(key)
        with self._lock:
            self._tokens[id(entity)] = token

    def _drop(self, entity: Any) -> None:
        with self._lock:
            token = self._tokens.pop(id(entity), None)
            declared = self._declared.pop(id(entity), [])
        for item in [token, *declared]:
            if item is not None:
                self._undeclare(item, repr(entity))

    # --- nodes ----------------------------------------------------------------------------

    def announce_node(self, node: Node) -> None:
        if self._closed:
            return
        # A newer node takes the name: tell any older one, anywhere, to shut down.
        self.session.put(keys.kill_key(node.name), f"{self.sid} new node registered with same name")
        ref = weakref.ref(node)

        def on_kill(sample: Any) -> None:
            sender, _, reason = sample.payload.to_string().partition(" ")
            target = ref()
            bus = self.bus_ref()
            if target is None or bus is None or sender == self.sid:
                return
            # Not a daemon: the interpreter must not exit while it closes Zenoh objects.
            threading.Thread(
                target=bus.replace_node,
                args=(target, reason or "shutdown request"),
                name=f"workbench-kill {node.name}",
                daemon=False,
            ).start()

        kill_sub = self.session.declare_subscriber(
            keys.kill_key(node.name), self._handler(on_kill, f"node {node.name} (kill requests)")
        )
        with self._lock:
            self._declared[id(node)] = [kill_sub]
        self._token(node, keys.node_token(self.sid, self.pid, node.name))

    def kill(self, name: str, reason: str) -> None:
        """Tell the node ``name`` in another process to shut down."""
        self.session.put(keys.kill_key(name), f"{self.sid} {reason}")

    def retract_node(self, node: Node) -> None:
        self._drop(node)

    # --- topics ---------------------------------------------------------------------------

    def advertise(self, pub: Publisher) -> Sender | None:
        if self._closed:
            return None
        z = self._z
        zpub = self.session.declare_publisher(
            keys.data_key(pub.topic, pub.type, pub.md5, pub.node.name),
            congestion_control=z.CongestionControl.BLOCK,
            reliability=z.Reliability.RELIABLE,
            priority=z.Priority.DATA,  # the flush barrier relies on the same priority
            express=False,
        )
        declared = [zpub]
        topic = pub.topic
        put = guarded(f"publishing on {topic}")(zpub.put)
        mark = self._unflushed.add
        what = f"a message on {topic}"

        if pub.latch:
            send = self._latched_sender(pub, put, declared)
        else:

            def send(msg: Any) -> None:
                put(check_size(serialize(msg), what, MessageError))
                mark(topic)

        with self._lock:
            self._declared[id(pub)] = declared
        self._token(
            pub,
            keys.endpoint_token(
                self.sid, self.pid, "pub", pub.node.name, pub.topic, pub.type, pub.md5
            ),
        )
        return send

    def _latched_sender(self, pub: Publisher, put: Any, declared: list[Any]) -> Sender:
        """The sender of a latched publisher, and the queryable answering its last message."""
        latch_key = keys.latch_key(pub.topic, pub.type, pub.md5, pub.node.name, self.sid)
        latched = _Latched(f"{self.sid}.{next(_latched_ids)}")
        topic = pub.topic
        mark = self._unflushed.add

        def send(msg: Any) -> None:  # numbered, so that no subscriber gets it twice
            data = check_size(serialize(msg), f"a message on {topic}", MessageError)
            with latched.lock:
                latched.seq += 1
                latched.msg, latched.data = msg, data
                put(data, attachment=latched.attachment(latched.seq))
            mark(topic)

        def answer(query: Any) -> None:
            last = pub.last_message
            if last is None:
                return
            with latched.lock:
                sent, data, seq = latched.msg, latched.data, latched.seq
            if last is not sent:  # being published: it gets the next number
                data, seq = serialize(last), seq + 1
            query.reply(latch_key, data, attachment=latched.attachment(seq))

        declared.append(
            self.session.declare_queryable(
                latch_key, self._handler(answer, f"the latched message of {pub.topic}")
            )
        )
        return send

    def unadvertise(self, pub: Publisher) -> None:
        self._drop(pub)

    def subscribe(self, sub: Subscription) -> None:
        if self._closed:
            return
        topic = sub.topic
        z = self._z
        with self._lock:
            zsub, count = self._topic_subs.get((topic, sub.raw), (None, 0))
            if zsub is None and sub.raw:
                # Raw subscriptions (recorders) want throughput: Zenoh queues samples in a
                # channel (blocking when full, so nothing is dropped) that one thread drains.
                # A callback per sample on Zenoh's thread costs several times more.
                zsub = self.session.declare_subscriber(
                    keys.data_selector(topic),
                    z.handlers.FifoChannel(RAW_CHANNEL_SIZE),
                    allowed_origin=z.Locality.REMOTE,
                )
                pump = threading.Thread(
                    target=self._pump,
                    args=(zsub.handler, topic),
                    name=f"workbench-raw {topic}",
                    daemon=True,
                )
                # the pumps of subscriptions undeclared since have ended: forget them
                self._pumps = [p for p in self._pumps if p.is_alive()]
                self._pumps.append(pump)
                pump.start()
            elif zsub is None:
                # _on_data logs its own errors (no wrapper on the per-message path).
                zsub = self.session.declare_subscriber(
                    keys.data_selector(topic),
                    z.handlers.Callback(
                        functools.partial(self._on_data, topic, False), indirect=False
                    ),
                    allowed_origin=z.Locality.REMOTE,
                )
            self._topic_subs[(topic, sub.raw)] = (zsub, count + 1)
        self._token(
            sub,
            keys.endpoint_token(self.sid, self.pid, "sub", sub.node.name, topic, sub.type, sub.md5),
        )
        self._pool.submit(self._fetch_latched, sub)

    def _fetch_latched(self, sub: Subscription) -> None:
        try:
            self._fetch_latched_now(sub)
        except Exception as error:  # runs on the pool: nobody else would see it
            report(
                f"fetching the latched messages of {sub.topic} for {sub.node.name} failed: "
                f"{type(error).__name__}: {error}; a latched message may be missing"
            )

    def _fetch_latched_now(self, sub: Subscription) -> None:
        replies = list(self.session.get(keys.latch_selector(sub.topic), timeout=2.0))
        for reply in replies:
            if reply.ok is None:
                report(
                    f"a publisher of {sub.topic} could not send its latched message to "
                    f"{sub.node.name}: {reply.err.payload.to_string()}"
                )
                continue
            parsed = keys.parse_data_key(str(reply.ok.key_expr))
            if parsed is None or parsed[2] == "_":
                continue
            sample_session = str(reply.ok.key_expr).rsplit("/", 1)[-1]
            if sample_session == self.sid:
                continue
            _topic, type_name, md5, callerid = parsed
            numbered = parse_latched(reply.ok.attachment)
            data = reply.ok.payload.to_bytes()
            if numbered is None:  # a publisher that does not number its messages
                self._deliver(sub, type_name, md5, callerid, data, {}, latching=True)
            else:
                self._deliver_latched(sub, numbered, type_name, md5, callerid, data, {})

    def _deliver_latched(
        self,
        sub: Subscription,
        numbered: tuple[str, int],
        type_name: str,
        md5: str,
        callerid: str,
        data: bytes,
        decoded: dict[str, Any],
    ) -> None:
        """Deliver a latched publisher's message unless ``sub`` already has it or a newer one.

        Its latched reply and the same message sent live may both reach a subscription that
        appeared as it was published; in order, each message of the publisher at most once.
        """
        origin, seq = numbered
        with self._latched_lock:
            if sub.closed:
                return
            seen = self._latched_seen.setdefault(id(sub), {})
            if seen.get(origin, 0) >= seq:
                return
            seen[origin] = seq
            self._deliver(sub, type_name, md5, callerid, data, decoded, latching=True)

    def unsubscribe(self, sub: Subscription) -> None:
        self._drop(sub)
        with self._latched_lock:
            self._latched_seen.pop(id(sub), None)
        key = (sub.topic, sub.raw)
        with self._lock:
            zsub, count = self._topic_subs.get(key, (None, 0))
            if zsub is None:
                return
            if count <= 1:
                del self._topic_subs[key]
            else:
                self._topic_subs[key] = (zsub, count - 1)
                zsub = None
        if zsub is not None:
            self._undeclare(zsub, f"the subscriber of {sub.topic}")

    def _pump(self, channel: Any, topic: str) -> None:
        """Drain a raw subscription's channel; restarts after a failure, up to a limit."""
        recv = channel.recv
        on_data = self._on_data
        failures = 0
        while True:
            try:
                sample = recv()
            except self._z.ZError:  # undeclared and empty: the subscription is gone
                return
            except Exception as error:
                failures += 1
                if failures > PUMP_RESTARTS:
                    report(
                        f"the raw receiver of {topic} failed {failures} times in a row "
                        f"({type(error).__name__}: {error}); it stops: raw subscribers of "
                        f"{topic} in this process receive nothing more"
                    )
                    return
                report(
                    f"the raw receiver of {topic} failed ({type(error).__name__}: {error}); "
                    "restarting it"
                )
                continue
            failures = 0
            on_data(topic, True, sample)  # logs its own errors

    def _on_data(self, topic: str, raw: bool, sample: Any) -> None:
        # Runs once per message from another process: keep it lean. ``raw``: which of the
        # topic's two Zenoh subscribers (raw or decoding) this came through.
        try:
            subs = self._subscribers(topic)
            if not subs:
                return
            key = str(sample.key_expr)
            parsed = self._parsed_keys.get(key)
            if parsed is None:
                parsed = keys.parse_data_key(key)
                if parsed is None:
                    report(f"ignoring a message on {topic} under a malformed key {key}")
                    return
                self._parsed_keys[key] = parsed
            _topic, type_name, md5, callerid = parsed
            data = sample.payload.to_bytes()
            numbered = parse_latched(sample.attachment)
            if numbered is not None:  # from a latched publisher: at most once per subscription
                shared: dict[str, Any] = {}
                for sub in subs:
                    if sub.raw is raw:
                        self._deliver_latched(sub, numbered, type_name, md5, callerid, data, shared)
                return
            if len(subs) == 1:
                sub = subs[0]
                if raw and sub.raw and (sub.md5 == md5 or sub.md5 == "*"):  # a recorder
                    stamp = self._clock.now_ns()
                    sub.deliver(RawMessage(data, type_name, md5, stamp, callerid, topic), callerid)
                    return
            decoded: dict[str, Any] = {}
            for sub in subs:
                if sub.raw is raw:
                    self._deliver(sub, type_name, md5, callerid, data, decoded)
        except Exception as error:  # Zenoh's thread must keep receiving the next messages
            report(
                f"receiving a message on {topic} failed: {type(error).__name__}: {error}\n"
                f"{traceback.format_exc().rstrip()}"
            )

    def _deliver(
        self,
        sub: Subscription,
        type_name: str,
        md5: str,
        callerid: str,
        data: bytes,
        decoded: dict[str, Any],
        latching: bool = False,
    ) -> None:
        if sub.md5 not in ("*", md5):
            warn_key = (sub.node.name, sub.topic, md5)
            if warn_key not in self._warned:
                self._warned.add(warn_key)
                sub.node.get_logger().error(
                    f"Client [{sub.node.name}] wants topic {sub.topic} to have datatype/md5sum "
                    f"[{sub.type}/{sub.md5}], but our version has [{type_name}/{md5}]. "
                    "Dropping connection."
                )
            return
        if sub.raw:  # no decoding: the bytes, as they came
            raw = decoded.get("")
            if raw is None:
                bus = sub.node.bus
                raw = RawMessage(
                    data, type_name, md5, bus.clock.now_ns(), callerid, sub.topic, latching
                )
                decoded[""] = raw
            sub.deliver(raw, callerid)
            return
        msg = decoded.get(md5)
        if msg is None:
            try:
                msg = deserialize(data, type_name)
            except MessageError as error:
                if sub.md5 != "*":
                    report(f"cannot decode a {type_name} on {sub.topic} from {callerid}: {error}")
                    return
                msg = data  # an unknown type for a type-agnostic subscriber: raw bytes
            decoded[md5] = msg
        sub.deliver(msg, callerid)

    # --- services -------------------------------------------------------------------------

    def offer(self, server: ServiceServer) -> None:
        if self._closed:
            return

        def on_query(query: Any) -> None:
            self._pool.submit(self._answer, server, query)

        queryable = self.session.declare_queryable(
            keys.service_key(server.name, server.type, server.md5),
            self._handler(on_query, f"service {server.name}"),
        )
        with self._lock:
            self._declared[id(server)] = [queryable]
        self._token(
            server,
            keys.endpoint_token(
                self.sid, self.pid, "srv", server.node.name, server.name, server.type, server.md5
            ),
        )

    def _answer(self, server: ServiceServer, query: Any) -> None:
        try:
            attachment = query.attachment.to_string() if query.attachment is not None else ""
            md5, _, type_name = attachment.partition(" ")
            if md5 and md5 != server.md5:
                query.reply_err(
                    f"service {server.name} is {server.type} (md5 {server.md5}) but the client "
                    f"calls it as {type_name} (md5 {md5})"
                )
                return
            try:
                request = deserialize(query.payload.to_bytes(), server.service_class.Request._type)
                response = server.handle(request)
                what = f"the response of service {server.name}"
                query.reply(query.key_expr, check_size(serialize(response), what, ServiceError))
            except ServiceError as error:
                query.reply_err(error.message)
            except MessageError as error:
                query.reply_err(f"service {server.name}: {error.message}")
        except Exception as error:  # runs on the pool: nobody else would see it
            report(
                f"answering a call of service {server.name} failed: "
                f"{type(error).__name__}: {error}\n{traceback.format_exc().rstrip()}"
            )
        except BaseException as error:  # the pool would keep it to itself
            if is_transport_panic(error):
                transport_failed(f"answering service {server.name}", error)
            raise
        finally:
            self._finish(query, f"service {server.name}")

    def withdraw(self, server: ServiceServer) -> None:
        self._drop(server)

    @guarded("a service call")
    def call(self, client: Client, request: Any, timeout: float | None) -> Any:
        if not self.has_service(client.name):
            raise ServiceError(
                f"service [{client.name}] unavailable",
                hint="nobody offers it; 'workbench service list' shows the offered services",
            )
        what = f"a request to service {client.name}"
        replies = self.session.get(
            keys.service_selector(client.name),
            payload=check_size(serialize(request), what, ServiceError),
            attachment=f"{client.md5} {client.type}",
            timeout=NO_TIMEOUT if timeout is None else timeout,
        )
        for reply in replies:
            if reply.ok is not None:
                return deserialize(reply.ok.payload.to_bytes(), client.service_class.Response._type)
            raise ServiceError(reply.err.payload.to_string())
        if timeout is not None:
            raise ServiceTimeout(f"service [{client.name}] did not answer within {timeout} s")
        raise ServiceError(f"service [{client.name}] unavailable (its server went away)")

    # --- lifetime -------------------------------------------------------------------------

    @guarded("leaving the core")
    def close(self) -> None:
        """Flush what was published (bounded wait), then leave the core."""
        with self._lock:
            if self._closed:
                return
        try:
            self.flush()
        except Exception as error:  # leaving must go on; what may be lost is said here
            report(
                f"flushing before leaving the core at {self.uri} failed: "
                f"{type(error).__name__}: {error}; messages on their way may be lost"
            )
        with self._lock:
            if self._closed:
                return
            self._closed = True
            entities = list(self._declared) + list(self._tokens)
        for key in set(entities):
            with self._lock:
                token = self._tokens.pop(key, None)
                declared = self._declared.pop(key, [])
            for item in [token, *declared]:
                if item is not None:
                    self._undeclare(item, "an endpoint")
        self._pool.shutdown(wait=False, cancel_futures=True)
        with self._lock:
            zsubs = [zsub for zsub, _count in self._topic_subs.values()]
            self._topic_subs.clear()
        for item in (self._barrier, self._graph_sub, *zsubs):
            self._undeclare(item, "the session")
        current = threading.current_thread()
        for pump in self._pumps:  # they end once their channel is closed and empty
            if pump is not current:
                pump.join(timeout=1.0)
        try:
            self.session.close()
        except self._z.ZError as error:
            report(f"closing the Zenoh session to {self.uri}: {error}")
