"""The bus's parts: the Transport protocol, a transport of one's own, and failures that are
reported (and survived) instead of vanishing: timer threads, executor runs, Zenoh callbacks,
the raw receive pump and latched replies."""

from __future__ import annotations

import threading
import time

import pytest

from workbench.bus import Bus, Node
from workbench.bus.graph import Endpoint
from workbench.bus.inprocess import InProcessTransport
from workbench.bus.params import ParameterServer
from workbench.bus.transport import Transport
from workbench.msgs.std_msgs import String


class RecordingTransport:
    """A transport of one's own: remembers what it is asked and shows one remote node."""

    def __init__(self) -> None:
        self.params = ParameterServer()
        self.sent: list[tuple[str, object]] = []
        self.calls: list[tuple[str, str]] = []
        self.closed = False

    def announce_node(self, node):
        self.calls.append(("announce", node.name))

    def retract_node(self, node):
        self.calls.append(("retract", node.name))

    def advertise(self, pub):
        self.calls.append(("advertise", pub.topic))
        return lambda msg: self.sent.append((pub.topic, msg))

    def unadvertise(self, pub):
        self.calls.append(("unadvertise", pub.topic))

    def subscribe(self, sub):
        self.calls.append(("subscribe", sub.topic))

    def unsubscribe(self, sub):
        self.calls.append(("unsubscribe", sub.topic))

    def offer(self, server):
        self.calls.append(("offer", server.name))

    def withdraw(self, server):
        self.calls.append(("withdraw", server.name))

    def has_service(self, name):
        return False

    def call(self, client, request, timeout):
        raise AssertionError("not offered here")

    def remote_nodes(self):
        return {"/elsewhere": 4242}

    def remote_endpoints(self):
        return [Endpoint("/elsewhere", "pub", "/far", "std_msgs/String", "*", local=False)]

    def kill(self, name, reason):
        self.calls.append(("kill", name))

    def flush(self, topics=None, timeout=None):
        self.calls.append(("flush", ",".join(sorted(topics or []))))
        return True

    def close(self):
        self.closed = True


def test_both_transports_and_a_custom_one_satisfy_the_protocol():
    bus = Bus(threaded=False)
    assert isinstance(bus.transports[0], InProcessTransport)
    assert isinstance(bus.transports[0], Transport)
    assert isinstance(RecordingTransport(), Transport)
    assert not isinstance(object(), Transport)
    bus.shutdown()


def test_an_attached_transport_sees_every_endpoint_and_message():
    bus = Bus(threaded=False)
    extra = RecordingTransport()
    bus.attach(extra, "test://x")
    assert bus.is_connected and bus.remote is extra and bus.params is extra.params
    node = Node("n", bus=bus, disable_rosout=True)
    got = []
    node.create_subscription("chatter", String, got.append)
    pub = node.create_publisher("chatter", String)
    pub.publish("hi")
    assert extra.sent == [("/chatter", String(data="hi"))]
    assert bus.spin_until(lambda: got, 1.0) and got == [String(data="hi")]  # in-process too
    assert bus.graph().nodes["/elsewhere"].pid == 4242
    assert "/far" in bus.graph().topics
    bus.kill_node("/elsewhere", "test")
    node.shutdown()
    assert ("flush", "/chatter") in extra.calls
    for step in [
        ("announce", "/n"),
        ("subscribe", "/chatter"),
        ("advertise", "/chatter"),
        ("kill", "/elsewhere"),
        ("unsubscribe", "/chatter"),
        ("unadvertise", "/chatter"),
        ("retract", "/n"),
    ]:
        assert step in extra.calls
    pub_sent = len(extra.sent)
    bus.shutdown()
    assert extra.closed and len(extra.sent) == pub_sent


def test_attach_refuses_a_bus_that_has_nodes():
    bus = Bus(threaded=False)
    Node("n", bus=bus, disable_rosout=True)
    with pytest.raises(Exception, match="before any node joins"):
        bus.attach(RecordingTransport())
    bus.shutdown()


def test_a_failing_timer_thread_is_reported_and_restarted(capfd):
    with Bus() as bus:
        node = Node("ticker", bus=bus, disable_rosout=True)
        clock = bus.clock
        real = clock.sleep_until_ns
        failures = [RuntimeError("clock broke")]

        def flaky(deadline, stop=None, back=False):
            if failures:
                raise failures.pop()
            real(deadline, stop, back)

        clock.sleep_until_ns = flaky
        ticks = threading.Semaphore(0)

        def on_tick(event):
            ticks.release()

        timer = node.create_timer(0.01, on_tick)
        assert ticks.acquire(timeout=5.0)  # it runs again after the failure
        assert timer.restarts == 1 and timer.is_alive()
        timer.shutdown()
    err = capfd.readouterr().err
    line = next(line for line in err.splitlines() if "clock broke" in line)
    assert "[ERROR]" in line and "/ticker" in line and "on_tick" in line and "restarting" in line


def test_a_timer_thread_that_keeps_failing_stops_loudly(capfd):
    with Bus() as bus:
        node = Node("ticker", bus=bus, disable_rosout=True)

        def broken(deadline, stop=None, back=False):
            raise RuntimeError("clock gone")

        bus.clock.sleep_until_ns = broken
        timer = node.create_timer(0.01, lambda event: None)
        deadline = time.monotonic() + 5.0
        while timer.is_alive() and time.monotonic() < deadline:
            time.sleep(0.01)
        assert not timer.is_alive() and timer.restarts == timer.MAX_RESTARTS + 1
    err = capfd.readouterr().err
    assert "[FATAL]" in err and "timer stops" in err and "/ticker" in err


def test_an_executor_run_that_raises_is_logged_and_the_executor_goes_on(capfd):
    bus = Bus(threaded=False)
    node = Node("n", bus=bus, disable_rosout=True)
    got = []
    sub = node.create_subscription("x", String, got.append)
    real = sub.run_pending
    broken = [True]

    def run_pending(budget=8):
        if broken:
            broken.pop()
            raise RuntimeError("run broke")
        return real(budget)

    sub.run_pending = run_pending
    pub = node.create_publisher("x", String)
    pub.publish("one")
    assert bus.spin_once(1.0)  # the failing run
    assert "run broke" in capfd.readouterr().err
    assert bus.spin_until(lambda: got, 1.0)  # the message is still queued and delivered
    assert got == [String(data="one")]
    bus.shutdown()


def test_zenoh_callback_failures_are_logged_and_delivery_goes_on(core_uri, capfd):
    with Bus.connect(core_uri) as one, Bus.connect(core_uri) as two:
        talker = Node("talker", bus=one, disable_rosout=True)
        listener = Node("listener", bus=two, disable_rosout=True)
        got = []
        sub = listener.create_subscription("/topic", String, got.append, inline=True)
        real = sub.deliver
        broken = [True]

        def deliver(msg, callerid=""):
            if broken:
                broken.pop()
                raise RuntimeError("deliver broke")
            real(msg, callerid)

        sub.deliver = deliver
        pub = talker.create_publisher("/topic", String)
        deadline = time.monotonic() + 20
        while not got and time.monotonic() < deadline:
            pub.publish("hello")
            time.sleep(0.05)
        assert got and got[0] == String(data="hello")
        err = capfd.readouterr().err
        assert "receiving a message on /topic failed: RuntimeError: deliver broke" in err


def test_a_latched_message_that_cannot_be_sent_is_logged(core_uri, capfd):
    with Bus.connect(core_uri) as one, Bus.connect(core_uri) as two:
        talker = Node("talker", bus=one, disable_rosout=True)
        pub = talker.create_publisher("/latched", String, latch=True)
        pub.publish("ok")
        pub.last_message = object()  # not serializable: answering the late joiner fails
        listener = Node("listener", bus=two, disable_rosout=True)
        listener.create_subscription("/latched", String, lambda msg: None)
        deadline = time.monotonic() + 20
        err = ""
        while time.monotonic() < deadline:
            err += capfd.readouterr().err
            if "the latched message of /latched" in err:
                break
            time.sleep(0.05)
        assert "Zenoh callback for the latched message of /latched raised" in err


def test_the_raw_pump_restarts_after_a_failure_and_stops_when_closed(core_uri, capfd):
    import zenoh

    with Bus.connect(core_uri) as bus:
        transport = bus.remote

        class Channel:
            def __init__(self, outcomes):
                self.outcomes = list(outcomes)

            def recv(self):
                raise self.outcomes.pop(0)

        transport._pump(Channel([RuntimeError("recv broke"), zenoh.ZError("closed")]), "/raw")
        assert "raw receiver of /raw failed (RuntimeError: recv broke); restarting" in (
            capfd.readouterr().err
        )
        transport._pump(Channel([RuntimeError("again")] * 10), "/raw")
        assert "it stops: raw subscribers of /raw" in capfd.readouterr().err


def test_flush_does_not_warn_about_a_subscriber_whose_session_has_closed(core_uri, capfd):
    # The subscriber left (its liveliness token not yet withdrawn here): its barrier query
    # ends at once unanswered, and there is nothing queued for it that could be lost.
    from workbench.bus import keys

    with Bus.connect(core_uri) as bus:
        talker = Node("talker", bus=bus, disable_rosout=True)
        pub = talker.create_publisher("/chatter", String)
        transport = bus.remote
        gone = keys.endpoint_token(
            "f00dfeedf00dfeedf00dfeedf00dfeed", 1, "sub", "/gone", "/chatter", pub.type, pub.md5
        )
        transport._remote[gone] = keys.parse_token(gone)
        pub.publish("hello")
        started = time.monotonic()
        assert transport.flush(timeout=5.0)
        assert time.monotonic() - started < 4.0  # it did not sit out the timeout
        assert "did not confirm receipt" not in capfd.readouterr().err


def test_flush_warns_when_a_subscriber_does_not_confirm_in_time(core_uri, capfd):
    with Bus.connect(core_uri) as one, Bus.connect(core_uri) as two:
        talker = Node("talker", bus=one, disable_rosout=True)
        pub = talker.create_publisher("/chatter", String)
        listener = Node("listener", bus=two, disable_rosout=True)
        # an inline callback runs on the receive thread, so the barrier waits behind it
        listener.create_subscription("/chatter", String, lambda msg: time.sleep(3), inline=True)
        deadline = time.monotonic() + 20
        while pub.get_num_connections() < 1 and time.monotonic() < deadline:
            time.sleep(0.05)
        pub.publish("hello")
        assert not one.remote.flush(timeout=1.0)
        assert "did not confirm receipt" in capfd.readouterr().err
