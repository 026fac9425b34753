"""The in-process bus: topics, queues, latching, services, timers, clock, graph, errors.

Most tests step the executor by hand (``Bus(threaded=False)``) so they are deterministic.
"""

from __future__ import annotations

import threading
import time

import pytest
from process_helpers import wait_for

from workbench.bus import (
    AnyMsg,
    Bus,
    BusError,
    InvalidNameError,
    Node,
    ServiceError,
    ServiceTimeout,
    ShutdownError,
    TopicTypeError,
)
from workbench.errors import MessageError
from workbench.msgs import Time
from workbench.msgs.beginner_tutorials import AddTwoInts
from workbench.msgs.geometry_msgs import Twist
from workbench.msgs.rosgraph_msgs import Clock, Log
from workbench.msgs.std_msgs import Int32, String


@pytest.fixture
def bus():
    bus = Bus(threaded=False)
    yield bus
    bus.shutdown()


def drain(bus: Bus) -> int:
    count = 0
    while bus.spin_once():
        count += 1
    return count


def test_talker_listener(bus):
    talker, listener = Node("talker", bus=bus), Node("listener", bus=bus)
    heard: list[str] = []
    pub = talker.create_publisher("chatter", String, queue_size=10)
    listener.create_subscription("chatter", String, lambda msg: heard.append(msg.data))
    pub.publish(String(data="hello world"))
    pub.publish("built from a value")  # rospy-style: the publisher builds the message
    assert heard == []  # nothing runs until the executor is stepped
    assert bus.spin_until(lambda: len(heard) == 2, timeout=1.0)
    assert heard == ["hello world", "built from a value"]


def test_header_seq_is_numbered_per_publisher(bus):
    from workbench.msgs.geometry_msgs import PoseStamped

    node = Node("n", bus=bus)
    seqs = []
    node.create_subscription("pose", PoseStamped, lambda m: seqs.append(m.header.seq))
    pub = node.create_publisher("pose", PoseStamped)
    for _ in range(3):
        pub.publish(PoseStamped())
    drain(bus)
    assert seqs == [1, 2, 3]


def test_callback_args_and_names(bus):
    node = Node("listener", bus=bus, namespace="lab")
    got = []
    sub = node.create_subscription(
        "chatter", String, lambda m, tag: got.append((m.data, tag)), callback_args="A"
    )
    assert sub.topic == "/lab/chatter"
    Node("talker", bus=bus).create_publisher("/lab/chatter", String).publish("x")
    drain(bus)
    assert got == [("x", "A")]
    assert node.resolve_name("~rate") == "/lab/listener/rate"


def test_queue_drops_the_oldest(bus):
    node = Node("n", bus=bus)
    got = []
    node.create_subscription("numbers", Int32, lambda m: got.append(m.data), queue_size=3)
    pub = node.create_publisher("numbers", Int32)
    for i in range(10):
        pub.publish(Int32(data=i))
    drain(bus)
    assert got == [7, 8, 9]


def test_latched_topic_reaches_late_subscribers(bus):
    node = Node("n", bus=bus)
    node.create_publisher("map", String, latch=True).publish("the map")
    node.create_publisher("plain", String).publish("gone")
    got = []
    node.create_subscription("map", String, lambda m: got.append(m.data))
    node.create_subscription("plain", String, lambda m: got.append(m.data))
    drain(bus)
    assert got == ["the map"]


def test_type_mismatch_is_refused_naming_both_types(bus):
    node = Node("n", bus=bus)
    node.create_publisher("chatter", String)
    with pytest.raises(TopicTypeError, match="std_msgs/String.*refusing std_msgs/Int32"):
        node.create_subscription("chatter", Int32, print)
    any_sub = node.create_subscription("chatter", AnyMsg, print)  # type-agnostic is fine
    assert any_sub.type == "*"


def test_publishing_the_wrong_type(bus):
    pub = Node("n", bus=bus).create_publisher("chatter", String)
    with pytest.raises(TopicTypeError, match="publisher on /chatter is std_msgs/String.*Twist"):
        pub.publish(Twist())
    with pytest.raises(MessageError, match="cannot publish on /chatter"):
        pub.publish(42)


def test_malformed_names(bus):
    with pytest.raises(InvalidNameError):
        Node("my node", bus=bus)
    node = Node("n", bus=bus)
    with pytest.raises(InvalidNameError, match="'bad topic' is not a valid ROS topic name"):
        node.create_publisher("bad topic", String)
    with pytest.raises(MessageError, match="unknown message type"):
        node.create_publisher("x", "std_msgs/Strin")


def test_subscribe_by_type_name_and_any(bus):
    node = Node("tool", bus=bus)
    got = []
    node.create_subscription("cmd_vel", "geometry_msgs/Twist", got.append)
    node.create_subscription("cmd_vel", "*", got.append)
    pub = node.create_publisher("cmd_vel", "geometry_msgs/Twist")
    pub.publish(Twist())
    drain(bus)
    assert len(got) == 2 and all(isinstance(m, Twist) for m in got)


def test_services_and_errors(bus):
    server, caller = Node("add_two_ints_server", bus=bus), Node("client", bus=bus)
    server.create_service("add_two_ints", AddTwoInts, lambda req: req.a + req.b)
    client = caller.create_client("add_two_ints", AddTwoInts)
    client.wait_for_service(timeout=1.0)
    assert client.call(AddTwoInts.Request(a=1, b=3)).sum == 4
    assert client.call(a=2, b=5).sum == 7

    def broken(req):
        raise ValueError("cannot add")

    server.create_service("broken", AddTwoInts, broken)
    with pytest.raises(ServiceError, match="error processing request: cannot add"):
        caller.create_client("broken", AddTwoInts).call(AddTwoInts.Request())
    assert client.call(AddTwoInts.Request(a=1, b=1)).sum == 2  # the server keeps running

    missing = caller.create_client("nobody", AddTwoInts)
    with pytest.raises(ServiceTimeout, match="timeout exceeded while waiting for service /nobody"):
        missing.wait_for_service(timeout=0.1)
    with pytest.raises(ServiceError, match=r"service \[/nobody\] unavailable"):
        missing.call(AddTwoInts.Request())
    with pytest.raises(BusError, match="already offered"):
        caller.create_service("add_two_ints", AddTwoInts, lambda r: 0)
    with pytest.raises(MessageError, match="not a service type"):
        caller.create_service("x", String, lambda r: 0)


def test_timer_and_sim_time(bus):
    node = Node("timed", bus=bus)
    bus.params.set("/use_sim_time", True)
    node2 = Node("sim_user", bus=bus)
    assert bus.clock.is_simulated
    ticks = []
    node2.create_timer(0.5, lambda event: ticks.append(event.current_real.to_sec()))
    clock_pub = node.create_publisher("/clock", Clock)
    for step in range(1, 5):
        clock_pub.publish(Clock(clock=Time(step * 0.5)))
        drain(bus)
    assert node2.now() == Time(2.0)
    assert ticks == [0.5, 1.0, 1.5, 2.0]


@pytest.mark.parametrize("threaded", [False, True])
def test_a_timer_starts_over_when_simulated_time_jumps_back(threaded):
    # a simulation reset: the timers of amcl, the costmaps and move_base must tick again
    # from the new time, not wait until it reaches where the old one was
    with Bus(threaded=threaded) as bus:
        bus.params.set("/use_sim_time", True)
        node = Node("timed", bus=bus)
        clock_pub = node.create_publisher("/clock", Clock)
        ticks: list[float] = []
        node.create_timer(0.5, lambda event: ticks.append(event.current_real.to_sec()))

        def advance(to: float, until, pace: bool = False) -> bool:
            t = bus.clock.now_ns() / 1e9
            while t < to - 1e-9:
                t = min(t + 0.1, to)
                clock_pub.publish(Clock(clock=Time(t)))
                if not threaded:
                    drain(bus)
                # (give the timer's thread the time to look at the clock)
                if pace and wait_for(until, 0.02, poll=0.005):
                    return True
            return wait_for(until, 5.0, poll=0.01)

        assert advance(10.0, lambda: ticks and ticks[-1] >= 9.9), ticks
        clock_pub.publish(Clock(clock=Time(0.0)))  # /gazebo/reset_simulation
        before = len(ticks)
        assert advance(5.0, lambda: len(ticks) >= before + 2, pace=True), ticks
        assert all(t < 3.0 for t in ticks[before:]), ticks


def test_threaded_executor_runs_callbacks_in_the_background():
    with Bus() as bus:
        node = Node("n", bus=bus)
        done = threading.Event()
        node.create_subscription("x", String, lambda m: done.set())
        node.create_publisher("x", String).publish("go")
        assert done.wait(2.0)
        ticks = threading.Semaphore(0)
        timer = node.create_timer(0.01, lambda e: ticks.release())
        assert ticks.acquire(timeout=2.0) and ticks.acquire(timeout=2.0)
        timer.shutdown()
    assert all(not w.is_alive() for w in bus.executor.workers)  # shutdown leaves no thread behind


def test_rate_follows_the_clock():
    with Bus() as bus:
        node = Node("n", bus=bus)
        rate = node.create_rate(50)
        start = time.monotonic()
        for _ in range(5):
            rate.sleep()
        assert time.monotonic() - start > 0.07  # five periods of 20 ms, the first may be short


def test_same_name_replaces_the_older_node(bus, capsys):
    old = Node("talker", bus=bus)
    pub = old.create_publisher("chatter", String)
    new = Node("talker", bus=bus)
    assert old.is_shutdown and not new.is_shutdown
    assert "new node registered with same name" in capsys.readouterr().err
    with pytest.raises(ShutdownError):
        pub.publish("late")
    assert list(bus.graph().nodes) == ["/talker"]


def test_parameters_private_relative_global(bus):
    node = Node("talker", bus=bus, namespace="lab", argv=["_rate:=10", "chatter:=/speech"])
    assert node.get_param("~rate") == 10
    assert bus.params.get("/lab/talker/rate") == 10
    node.set_param("gain", {"p": 1.0, "d": 0.1})
    assert node.get_param("/lab/gain/p") == 1.0
    assert node.get_param("missing", 3) == 3
    with pytest.raises(KeyError):
        node.get_param("missing")
    assert node.search_param("gain") == "/lab/gain"
    node.delete_param("gain")
    assert not node.has_param("gain")
    assert node.create_publisher("chatter", String).topic == "/speech"  # remapped


def test_logging_prints_and_goes_to_rosout(bus, capsys):
    node = Node("talker", bus=bus)
    logs = []
    Node("rosout", bus=bus).create_subscription("/rosout", Log, logs.append)
    node.get_logger().info("hello %s", "world")
    drain(bus)
    out = capsys.readouterr().out
    assert "[INFO] [" in out and "]: hello world" in out
    assert logs[-1].msg == "hello world" and logs[-1].name == "/talker" and logs[-1].level == 2


def test_graph_lists_nodes_topics_services(bus):
    talker, listener = Node("talker", bus=bus), Node("listener", bus=bus)
    talker.create_publisher("chatter", String)
    listener.create_subscription("chatter", String, print)
    listener.create_service("add_two_ints", AddTwoInts, lambda r: 0)
    graph = bus.graph()
    assert set(graph.nodes) == {"/talker", "/listener"}
    chatter = graph.topics["/chatter"]
    assert chatter.type == "std_msgs/String"
    assert chatter.publishers == ["/talker"] and chatter.subscribers == ["/listener"]
    assert graph.services["/add_two_ints"].providers == ["/listener"]
    assert graph.nodes["/talker"].publications == ["/chatter", "/rosout"]


def test_bad_callback_is_logged_and_the_bus_keeps_going(bus, capsys):
    node = Node("n", bus=bus)
    got = []

    def bad(msg):
        raise RuntimeError("oops")

    node.create_subscription("x", String, bad)
    node.create_subscription("x", String, got.append)
    node.create_publisher("x", String).publish("a")
    drain(bus)
    assert len(got) == 1
    assert "bad callback" in capsys.readouterr().err


def test_a_callback_publishing_on_a_node_shut_down_meanwhile_is_quiet(bus, capsys):
    """Ctrl-C closes a node while a delivered message's callback republishes (issue 14, 18)."""
    relay = Node("relay", bus=bus)
    out = relay.create_publisher("out", String)
    relay.create_subscription("x", String, lambda msg: out.publish(msg))
    Node("talker", bus=bus).create_publisher("x", String).publish("a")
    out.unregister()  # as the node's shutdown does
    drain(bus)
    assert "bad callback" not in capsys.readouterr().err


def test_a_refusal_the_handler_means_is_one_line_without_traceback(capsys):
    """rospy: a handler's ServiceException is reported without a traceback (issue 14, item 18)."""
    from workbench.errors import WorkbenchError

    bus = Bus()
    server, caller = Node("server", bus=bus), Node("caller", bus=bus)

    def refuse(req):
        raise WorkbenchError("a turtle named 'turtle1' already exists")

    server.create_service("refuse", AddTwoInts, refuse)
    with pytest.raises(
        ServiceError,
        match="service cannot process request: a turtle named 'turtle1' already exists",
    ):
        caller.create_client("refuse", AddTwoInts).call(AddTwoInts.Request())
    assert "Traceback" not in capsys.readouterr().err
    bus.shutdown()


def test_a_timer_tick_publishing_while_its_node_shuts_down_logs_no_error(bus, capsys):
    bus.params.set("/use_sim_time", True)
    clock = Node("clock", bus=bus).create_publisher("/clock", Clock)
    node = Node("closing", bus=bus)
    late = node.create_publisher("/late", String)
    other = Node("other", bus=bus)
    lost = other.create_publisher("/lost", String)
    lost.unregister()
    ticks = []

    def closing_tick(event):
        ticks.append("closing")
        node.shutdown()
        late.publish(String(data="after shutdown"))

    def broken_tick(event):
        ticks.append("other")
        lost.publish(String(data="on an unregistered publisher"))

    node.create_timer(0.5, closing_tick)
    other.create_timer(0.5, broken_tick)
    clock.publish(Clock(clock=Time(0.5)))
    drain(bus)
    assert sorted(ticks) == ["closing", "other"]
    err = capsys.readouterr()
    text = err.out + err.err
    # the node that shut down ends quietly; a live node's closed publisher is still reported
    assert "after shutdown" not in text and "/late" not in text
    assert "timer callback raised ShutdownError" in text and "/lost" in text
