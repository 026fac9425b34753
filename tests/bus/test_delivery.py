"""Delivery across processes: nothing lost when a publisher exits, raw mode, publisher identity."""

from __future__ import annotations

import time

import pytest

from workbench.bus import Bus, Node, RawMessage, connection_header
from workbench.msgs import deserialize, md5sum
from workbench.msgs.std_msgs import Int64, String

COUNT = 200
SIZE = 100_000  # large messages fill Zenoh's queues quickly, so a backlog forms at exit

BURST = f"""
import os, sys, time
from workbench.bus import Node
from workbench.msgs.std_msgs import String
node = Node("burst", disable_rosout=True)
pub = node.create_publisher("/burst", String)
deadline = time.monotonic() + 20
while pub.get_num_connections() < 1 and time.monotonic() < deadline:
    time.sleep(0.02)
for i in range({COUNT}):
    pub.publish(String(data=str(i).rjust({SIZE})))
if sys.argv[1] == "shutdown":
    node.shutdown()
    os._exit(0)  # no interpreter clean-up: only Node.shutdown() may flush
print("BURST DONE", flush=True)  # then the interpreter exits: atexit must flush
"""


def wait_for(predicate, timeout=30.0) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.05)
    return bool(predicate())


@pytest.mark.multiprocess
@pytest.mark.parametrize("ending", ["exit", "shutdown"])
def test_publisher_exiting_right_after_a_burst_loses_nothing(procs, ending):
    with Bus.connect(procs.uri) as bus:
        got: list[int] = []

        def slow(msg: String) -> None:  # slower than the publisher: a backlog builds up
            got.append(int(msg.data))
            time.sleep(0.005)

        Node("sink", bus=bus).create_subscription("/burst", String, slow, queue_size=0, inline=True)
        child = procs.start("-c", BURST, ending, name="burst")
        assert child.wait(60) == 0, procs.output(child)
        # the publisher is gone; everything it sent must still arrive, in order
        assert wait_for(lambda: len(got) >= COUNT), (len(got), procs.output(child))
        time.sleep(0.2)
        assert got == list(range(COUNT))
        assert "did not confirm" not in procs.output(child)


PUBLISHER = """
import sys
from workbench.bus import Node
from workbench.msgs.std_msgs import Int64
node = Node("counter", disable_rosout=True)
pub = node.create_publisher("/numbers", Int64)
import time
deadline = time.monotonic() + 20
while pub.get_num_connections() < 1 and time.monotonic() < deadline:
    time.sleep(0.02)
for i in range(int(sys.argv[1])):
    pub.publish(Int64(data=i))
"""


@pytest.mark.multiprocess
def test_raw_subscription_and_callerid_across_processes(procs):
    with Bus.connect(procs.uri) as bus:
        node = Node("recorder", bus=bus)
        raw: list[RawMessage] = []
        decoded: list[tuple[int, dict | None]] = []
        node.create_subscription("/numbers", Int64, raw.append, queue_size=0, raw=True)
        node.create_subscription(
            "/numbers",
            Int64,
            lambda m: decoded.append((m.data, connection_header())),
            queue_size=0,
        )
        child = procs.start("-c", PUBLISHER, "500", name="counter")
        assert child.wait(60) == 0, procs.output(child)
        assert wait_for(lambda: len(raw) >= 500 and len(decoded) >= 500)
        first = raw[0]
        assert isinstance(first.data, bytes)
        assert (first.type, first.md5) == ("std_msgs/Int64", md5sum("std_msgs/Int64"))
        assert first.callerid == "/counter" and first.topic == "/numbers"
        assert [deserialize(r.data, r.type).data for r in raw] == list(range(500))
        stamps = [r.recv_ns for r in raw]
        assert stamps == sorted(stamps) and abs(stamps[-1] / 1e9 - time.time()) < 60
        assert [d for d, _ in decoded] == list(range(500))
        header = decoded[0][1]
        assert header is not None and header["callerid"] == "/counter"
        assert header["topic"] == "/numbers" and header["type"] == "std_msgs/Int64"


def test_raw_subscription_in_process_and_latched():
    bus = Bus(threaded=False)
    talker, listener = Node("talker", bus=bus), Node("listener", bus=bus)
    latched = talker.create_publisher("/name", String, latch=True)
    latched.publish("lab")
    raw: list[RawMessage] = []
    listener.create_subscription("/name", "*", raw.append, raw=True)
    pub = talker.create_publisher("/n", Int64)
    listener.create_subscription("/n", Int64, raw.append, raw=True)
    headers: list[dict | None] = []
    listener.create_subscription("/n", Int64, lambda m: headers.append(connection_header()))
    pub.publish(Int64(data=7))
    bus.spin_until(lambda: len(raw) == 2 and headers, timeout=5)
    assert [(r.topic, r.type, r.callerid) for r in raw] == [
        ("/name", "std_msgs/String", "/talker"),
        ("/n", "std_msgs/Int64", "/talker"),
    ]
    assert raw[0].deserialize() == String(data="lab")
    assert deserialize(raw[1].data, "std_msgs/Int64").data == 7
    assert headers[0]["callerid"] == "/talker"
    assert connection_header() is None  # outside a callback
    bus.shutdown()


def test_tf_listener_names_the_broadcasting_node():
    from workbench.tf import Buffer, StaticTransformBroadcaster, TransformListener
    from workbench.tf.broadcaster import make_transform

    bus = Bus(threaded=False)
    buffer = Buffer()
    TransformListener(buffer, node=Node("listener", bus=bus))
    broadcaster = StaticTransformBroadcaster(Node("mount_publisher", bus=bus))
    broadcaster.send_transform(make_transform("world", "base_link", (1, 0, 0), (0, 0, 0, 1)))
    bus.spin_until(lambda: "base_link" in buffer.frames_info(), timeout=5)
    assert buffer.frames_info()["base_link"]["broadcaster"] == "/mount_publisher"
    bus.shutdown()
