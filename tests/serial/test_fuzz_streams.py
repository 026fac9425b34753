"""Seeded fuzzing of what a rosserial device sends the host: no traceback, no hang, no threads.

Valid device streams (registrations of publishers, subscribers and services, messages, time
and parameter requests, log lines), written by hand in ``rosserial_bytes``, are mutated at
the byte level and with whole hostile frames spliced in (lengths, checksums, protocol
versions, TopicInfos with odd names, types, md5sums and ids, thousands of registrations),
then fed to one host bridge as successive devices, in chunks of random sizes. Every mutant
must be handled without an exception reaching the reader, within the hang bound, without
more threads than the bridge's own, and the same host must then serve a valid device (its
message reaches the bus) once the mutant device is forgotten.
"""

from __future__ import annotations

import random
import struct
import threading

from fuzz_helpers import Mutator, bounded, fuzz_runs, fuzz_seed, report
from process_helpers import wait_for
from rosserial_bytes import MD5, FakeLink, frame, log, string, topic_info
from tcp_host_helpers import WAIT, connect, tcp_host

from workbench.bus import Bus, Node
from workbench.serial.bridge import MAX_PUBLISHERS, MAX_SUBSCRIBERS, Bridge


class Clock:
    def __init__(self) -> None:
        self.t = 100.0

    def __call__(self) -> float:
        return self.t


def _service_frames() -> bytes:
    return (
        frame(3, topic_info(100, "led", "std_srvs/SetBool", MD5["std_srvs/SetBoolRequest"]))
        + frame(2, topic_info(126, "led", "std_srvs/SetBool", MD5["std_srvs/SetBoolResponse"]))
        + frame(4, topic_info(127, "greeting", "std_srvs/Trigger", MD5["std_srvs/TriggerRequest"]))
        + frame(5, topic_info(101, "greeting", "std_srvs/Trigger", MD5["std_srvs/TriggerResponse"]))
        + frame(127, b"")  # the device calls greeting
        + frame(126, b"\x01" + string("on"))  # a response nobody asked for
    )


#: What valid devices send, from power-up.
STREAMS = [
    frame(10)
    + frame(0, topic_info(125, "chatter", "std_msgs/String"))
    + frame(125, string("hello world!"))
    + frame(7, log(1, "up"))
    + frame(10),
    frame(1, topic_info(100, "toggle_led", "std_msgs/Empty", buffer=20))
    + frame(0, topic_info(125, "pushed", "std_msgs/Bool"))
    + frame(125, b"\x01")
    + frame(6, string("~greeting_period"))
    + frame(6, string("/no/such/param")),
    _service_frames()
    + frame(0, topic_info(128, "counts", "std_msgs/Int32"))
    + frame(128, b"\x07\0\0\0"),
]

#: Whole hostile frames and fragments spliced into the streams.
TOKENS = [
    b"\xff\xfe",
    b"\xff\xff",
    b"\xff\xfd\x00\x00\xff",
    b"\xff\xfe\xff\xff\x01",  # a 65,535-byte frame announced
    frame(0, topic_info(125, "chatter", "std_msgs/String", md5="0" * 32)),
    frame(0, topic_info(129, "x" * 600, "std_msgs/String")),
    frame(0, topic_info(130, "bad name!", "std_msgs/String")),
    frame(0, topic_info(131, "", "std_msgs/String")),
    frame(0, topic_info(132, "odd", "no_such_msgs/Thing", md5="0" * 32)),
    frame(0, topic_info(133, "odd", "../../etc/passwd", md5="0" * 32)),
    frame(0, topic_info(0, "zero", "std_msgs/String")),
    frame(0, topic_info(7, "log_id", "std_msgs/String")),
    frame(0, topic_info(125, "chatter", "std_msgs/Int32")),
    frame(1, topic_info(100, "toggle_led", "std_msgs/String")),
    frame(
        1, topic_info(102, "/rosout", "rosgraph_msgs/Log", md5="acffd30cd6b6de30f120938c17c593fb")
    ),
    frame(2, topic_info(140, "svc", "std_msgs/String")),
    frame(4, topic_info(141, "svc2", "no_such/Srv", md5="0" * 32)),
    frame(0, struct.pack("<H", 150) + struct.pack("<I", 0xFFFFFFF0) + b"name"),
    frame(0, b"\x01"),
    frame(6, struct.pack("<I", 0x7FFFFFFF)),
    frame(6, string("~" * 3000)),
    frame(7, b"\x09" + string("level nine")),
    frame(7, b"\x03" + struct.pack("<I", 1 << 30)),
    frame(10, b"\x00" * 8),
    frame(11),
    frame(125, b"\xff\xff\xff\x7fabc"),
    frame(127, b"\xff" * 40),
    frame(0xFFFF, b"?"),
    b"".join(frame(0, topic_info(200 + i, f"many/p{i}", "std_msgs/Empty")) for i in range(150)),
    b"".join(frame(1, topic_info(200 + i, f"many/s{i}", "std_msgs/Empty")) for i in range(150)),
    b"".join(frame(127, b"") for _ in range(40)),  # service calls in a burst
]


def _feed(bridge: Bridge, clock: Clock, data: bytes, rng: random.Random) -> None:
    at = 0
    while at < len(data):
        size = rng.choice((1, 7, 64, 512, 4096))
        bridge.receive(data[at : at + size])
        at += size
        clock.t += rng.choice((0.0, 0.01, 0.03, 0.6))
        bridge.tick()
    clock.t += 1.0  # long enough for every timeout: sync lost, frames flushed
    bridge.tick()


def _serves_a_valid_device(bus, bridge: Bridge, clock: Clock, got: list) -> bool:
    link = FakeLink()
    bridge.attach(link)
    bridge.receive(frame(0, topic_info(125, "fuzz/alive", "std_msgs/String")))
    before = len(got)
    bridge.receive(frame(125, string("alive")))
    bus.spin_once(0.0)
    ok = len(got) == before + 1 and got[-1].data == "alive"
    bridge.forget_device()
    return ok


def test_mutated_device_streams(tmp_path):
    seed = fuzz_seed(28)
    runs = fuzz_runs(150)
    rng = random.Random(seed)
    mutator = Mutator(seed=seed, tokens=TOKENS)
    bus = Bus(threaded=False)
    try:
        clock = Clock()
        node = Node("serial_node", bus=bus)
        node.set_param("~greeting_period", 2)
        # a short timeout: a service call the device made ends soon after it is forgotten
        bridge = Bridge(node, timeout=0.05, clock=clock, write_thread=False)
        got: list = []
        Node("fuzz_echo", bus=bus).create_subscription(
            "fuzz/alive", "std_msgs/String", got.append, inline=True
        )
        baseline = threading.active_count()
        frames_in = problems = refused = 0
        for run in range(runs):
            data = mutator.mutate(STREAMS[run % len(STREAMS)], rounds=1 + run % 4)
            with bounded(f"device stream mutant {run} (seed {seed})"):
                bridge.attach(FakeLink())
                _feed(bridge, clock, data, rng)
                assert len(bridge.publishers) <= MAX_PUBLISHERS
                assert len(bridge.subscribers) <= MAX_SUBSCRIBERS
                frames_in += bridge.frames_in
                problems += bridge.problems
                refused += bridge.refused
                bridge.frames_in = bridge.problems = 0
                bridge.forget_device()
                assert wait_for(lambda: threading.active_count() <= baseline, 30.0), sorted(
                    t.name for t in threading.enumerate()
                )
                publishers, subscriptions, services = node.endpoints()
                left = [e.topic for e in publishers if e.topic not in ("/diagnostics", "/rosout")]
                left += [e.topic for e in subscriptions] + [e.name for e in services]
                assert not left, f"mutant {run} left endpoints behind: {left[:5]}"
                assert _serves_a_valid_device(bus, bridge, clock, got), f"after mutant {run}"
        bridge.close()
    finally:
        bus.shutdown()
    assert frames_in > runs and problems > runs // 4, (frames_in, problems)
    report("rosserial streams", runs, frames=frames_in, damaged=problems, refused=refused)


def test_mutated_device_streams_over_tcp():
    """The TCP host, device after device: a mutant connects, sends and disconnects, then a
    valid device must be served, and the threads return to what they were."""
    seed = fuzz_seed(2828)
    runs = fuzz_runs(10)
    mutator = Mutator(seed=seed, tokens=TOKENS)
    bus = Bus()
    try:
        with tcp_host(bus) as (port, lines):
            exits = 0

            def session(data: bytes, what: str) -> None:
                nonlocal exits
                board = connect(port)
                try:
                    board.sendall(data)
                    if what == "valid":
                        assert wait_for(
                            lambda: lines.having("Setup publisher on fuzz/tcp_alive"), WAIT
                        ), "the host no longer serves a valid device"
                finally:
                    board.close()
                exits += 1
                assert wait_for(lambda: len(lines.having("Client has exited")) >= exits, WAIT)
                lines.lines[:] = [line for line in lines.lines if "Client has exited" in line]

            valid = STREAMS[0] + frame(0, topic_info(190, "fuzz/tcp_alive", "std_msgs/String"))
            session(valid, "valid")  # what a bus starts once (executor, pools), it starts
            baseline = threading.active_count()
            for run in range(runs):
                with bounded(f"device stream mutant {run} over TCP (seed {seed})"):
                    session(mutator.mutate(STREAMS[run % len(STREAMS)]), "mutant")
                    session(valid, "valid")
                    assert wait_for(lambda: threading.active_count() <= baseline, WAIT), sorted(
                        t.name for t in threading.enumerate()
                    )
    finally:
        bus.shutdown()
    report("rosserial streams over TCP", runs)
