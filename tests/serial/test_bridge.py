"""The host bridge against a device played from hand-written bytes (rosserial_python's behaviour).

Every case checks the host's own lines (SerialClient.py, noetic-devel) and that the
bridge keeps serving the other topics after the bad input.
"""

from __future__ import annotations

import struct
import threading

import pytest
from process_helpers import wait_for
from rosserial_bytes import (
    MD5,
    REQUEST_TOPICS,
    TIME_REQUEST,
    TX_STOP,
    FakeLink,
    frame,
    log,
    string,
    topic_info,
)

from workbench.bus import Bus, Node
from workbench.serial.bridge import LOST_SYNC, UNABLE_TO_SYNC, Bridge
from workbench.serial.links import LinkLost

UNKNOWN_ID = 125


class Clock:
    def __init__(self) -> None:
        self.t = 100.0

    def __call__(self) -> float:
        return self.t


@pytest.fixture
def bus():
    bus = Bus(threaded=False)
    yield bus
    bus.shutdown()


@pytest.fixture
def host(bus):
    """(bridge, link, clock) with a fake device link attached and the topics requested."""
    clock = Clock()
    node = Node("serial_node", bus=bus)
    bridge = Bridge(node, timeout=5.0, clock=clock, write_thread=False)
    link = FakeLink()
    bridge.attach(link)
    bridge.request_topics()
    return bridge, link, clock


def received(bus, topic, type_):
    got = []
    Node(f"echo_{topic.strip('/').replace('/', '_')}", bus=bus).create_subscription(
        topic, type_, got.append, inline=True
    )
    return got


def text(capsys) -> str:
    captured = capsys.readouterr()
    return captured.out + captured.err


def test_handshake_time_reply_and_publisher(capsys, host, bus):
    bridge, link, _ = host
    assert bytes(link.written) == REQUEST_TOPICS
    link.written.clear()
    chatter = received(bus, "chatter", "std_msgs/String")
    node_now = bridge.node.now().to_sec()
    bridge.receive(TIME_REQUEST + frame(0, topic_info(125, "chatter", "std_msgs/String")))
    [(topic, payload)] = link.take()
    assert topic == 10 and len(payload) == 8
    secs, nsecs = struct.unpack("<II", payload)
    assert abs(secs + nsecs * 1e-9 - node_now) < 60
    bridge.receive(frame(125, string("hello world!")))
    assert [m.data for m in chatter] == ["hello world!"]
    out = text(capsys)
    for line in (
        "Requesting topics...",
        "Note: publish buffer size is 280 bytes",
        "Setup publisher on chatter [std_msgs/String]",
    ):
        assert f"]: {line}\n" in out


def test_subscriber_gets_bus_messages_and_big_ones_are_dropped(capsys, host, bus):
    bridge, link, _ = host
    bridge.receive(frame(1, topic_info(100, "toggle_led", "std_msgs/Empty", buffer=20)))
    bridge.receive(frame(1, topic_info(101, "words", "std_msgs/String", buffer=20)))
    link.written.clear()
    me = Node("me", bus=bus)
    me.create_publisher("toggle_led", "std_msgs/Empty").publish()
    words = me.create_publisher("words", "std_msgs/String")
    words.publish(data="short")
    words.publish(data="a string longer than the device's twenty bytes")
    assert bytes(link.written) == bytes.fromhex("ff fe 00 00 ff 64 00 9b") + frame(
        101, string("short")
    )
    out = text(capsys)
    assert "Note: subscribe buffer size is 20 bytes" in out
    assert "Setup subscriber on toggle_led [std_msgs/Empty]" in out
    assert "Message from ROS network dropped: message larger than buffer." in out


def test_rev0_device_gets_the_protocol_notice(capsys, host):
    bridge, _, _ = host
    bridge.receive(frame(0, topic_info(125, "chatter", "std_msgs/String"), version=0xFF))
    out = text(capsys)
    assert (
        "Mismatched protocol version in packet (b'\\xff'): lost sync or rosserial_python is from "
        "different ros release than the rosserial client" in out
    )
    assert (
        "Protocol version of client is Rev 0 (rosserial 0.4 and earlier), expected Rev 1 "
        "(rosserial 0.5+)" in out
    )
    assert out.count("Protocol version of client is") == 1
    assert not bridge.publishers
    bridge.receive(frame(10, version=0x42))
    assert "Protocol version of client is unrecognized, expected Rev 1 (rosserial 0.5+)" in text(
        capsys
    )


def test_unknown_type_and_wrong_md5_are_one_line_each_and_the_rest_works(capsys, host, bus):
    bridge, _, _ = host
    chatter = received(bus, "chatter", "std_msgs/String")
    bridge.receive(
        frame(0, topic_info(126, "odd", "no_such_msgs/Thing", md5="0" * 32))
        + frame(0, topic_info(127, "counts", "std_msgs/Int32", md5="f" * 32))
        + frame(0, topic_info(125, "chatter", "std_msgs/String"))
        + frame(125, string("still here"))
    )
    out = text(capsys)
    assert "Creation of publisher failed: unknown message type 'no_such_msgs/Thing'" in out
    assert (
        f"Creation of publisher failed: Checksum does not match: {MD5['std_msgs/Int32']},{'f' * 32}"
        in out
    )
    assert [m.data for m in chatter] == ["still here"]
    assert sorted(bridge.publishers) == [125]


def test_a_payload_that_is_not_its_type_is_an_error_and_the_next_one_arrives(capsys, host, bus):
    bridge, _, _ = host
    chatter = received(bus, "chatter", "std_msgs/String")
    bridge.receive(frame(0, topic_info(125, "chatter", "std_msgs/String")))
    bridge.receive(frame(125, b"\xff\x00\x00\x00ab") + frame(125, string("ok")))
    assert [m.data for m in chatter] == ["ok"]
    err = [line for line in text(capsys).splitlines() if "Cannot deliver" in line]
    assert len(err) == 1 and "chatter" in err[0] and "std_msgs/String" in err[0]


def test_publishing_before_configured_asks_for_the_topics(capsys, host):
    bridge, link, clock = host
    link.written.clear()
    bridge.receive(frame(UNKNOWN_ID, string("early")))  # just asked: no second request yet
    assert "Tried to publish" not in text(capsys) and not link.written
    clock.t += 1.0
    bridge.receive(frame(UNKNOWN_ID, string("early")))
    out = text(capsys)
    assert f"Tried to publish before configured, topic id {UNKNOWN_ID}" in out
    assert "Requesting topics..." in out
    assert bytes(link.written) == REQUEST_TOPICS


def test_checksum_lines(capsys, host):
    bridge, _, _ = host
    good = frame(10)
    bad_length = bytearray(good)
    bad_length[4] ^= 0x01
    bad_sum = bytearray(good)
    bad_sum[-1] ^= 0x01
    bridge.receive(bytes(bad_length) + bytes(bad_sum))
    out = text(capsys)
    assert "Wrong checksum for msg length, length 0, dropping message." in out
    assert "wrong checksum for topic id and msg" in out


def test_a_device_that_never_answers_then_one_that_stops(capsys, host):
    bridge, link, clock = host
    clock.t += 14.9
    bridge.tick()
    assert UNABLE_TO_SYNC not in text(capsys)
    link.written.clear()
    clock.t += 0.2
    bridge.tick()
    out = text(capsys)
    assert (
        "Unable to sync with device; possible link problem or link software version mismatch "
        "such as hydro rosserial_python with groovy Arduino" in out
    )
    assert "Requesting topics..." in out  # and it asks again
    assert bytes(link.written) == REQUEST_TOPICS
    clock.t += 16
    bridge.tick()
    assert text(capsys).count("Unable to sync") == 1  # once per timeout, retrying
    bridge.receive(TIME_REQUEST)
    clock.t += 16
    bridge.tick()
    assert LOST_SYNC in text(capsys)


def test_parameters(capsys, host, bus):
    bridge, link, _ = host
    node = bridge.node
    node.set_param("~gains", [1.5, 2.5])
    node.set_param("/ids", [3, 4, 5])
    node.set_param("/flag", True)
    node.set_param("/names", ["a", "bc"])
    node.set_param("/nested", {"a": 1})
    node.set_param("/mixed", [1, "x"])
    link.written.clear()

    def ask(name):
        bridge.receive(frame(6, string(name)))
        return link.take()

    [(six, floats)] = ask("~gains")
    assert six == 6
    assert floats == struct.pack("<I", 0) + struct.pack("<I2f", 2, 1.5, 2.5) + struct.pack("<I", 0)
    [(six, ints)] = ask("/ids")
    assert ints == struct.pack("<I3i", 3, 3, 4, 5) + struct.pack("<II", 0, 0)
    [(six, flag)] = ask("/flag")
    assert flag == struct.pack("<Ii", 1, 1) + struct.pack("<II", 0, 0)
    [(six, names)] = ask("/names")
    assert names == struct.pack("<II", 0, 0) + struct.pack("<I", 2) + string("a") + string("bc")
    for missing in ("/nothing", "/nested", "/mixed"):
        assert ask(missing) == []
    out = text(capsys)
    assert "Parameter /nothing does not exist" in out
    assert "Cannot send param /nested because it is a dictionary" in out
    assert "All Paramers in the list /mixed must be of the same type" in out


def test_device_log_messages_keep_their_level(capsys, host, bus):
    bridge, _, _ = host
    rosout = received(bus, "/rosout", "rosgraph_msgs/Log")
    for level, words in enumerate(("dbg", "fine", "careful", "broken", "dead")):
        bridge.receive(frame(7, log(level, words)))
    levels = {m.msg: m.level for m in rosout if m.name == "/serial_node"}
    assert levels == {"fine": 2, "careful": 4, "broken": 8, "dead": 16}  # debug is below info
    out = text(capsys)
    assert "[WARN]" in out and "careful" in out and "[FATAL]" in out


def test_service_offered_by_the_device(host, bus):
    bridge, link, _ = host
    bridge.receive(
        frame(3, topic_info(100, "led", "std_srvs/SetBool", MD5["std_srvs/SetBoolRequest"]))
    )
    bridge.receive(
        frame(2, topic_info(125, "led", "std_srvs/SetBool", MD5["std_srvs/SetBoolResponse"]))
    )
    link.written.clear()
    client = Node("caller", bus=bus).create_client("led", "std_srvs/SetBool")
    answers = []
    caller = threading.Thread(target=lambda: answers.append(client.call(data=True, timeout=10)))
    caller.start()
    assert wait_for(lambda: link.written)
    assert link.take() == [(100, b"\x01")]
    bridge.receive(frame(125, b"\x01" + string("LED on")))
    caller.join(10)
    assert answers[0].success is True and answers[0].message == "LED on"


def test_service_called_by_the_device(host, bus):
    bridge, link, _ = host
    Node("greeter", bus=bus).create_service(
        "greeting", "std_srvs/Trigger", lambda req: {"success": True, "message": "hi"}
    )
    bridge.receive(
        frame(4, topic_info(125, "greeting", "std_srvs/Trigger", MD5["std_srvs/TriggerRequest"]))
    )
    bridge.receive(
        frame(5, topic_info(100, "greeting", "std_srvs/Trigger", MD5["std_srvs/TriggerResponse"]))
    )
    link.written.clear()
    bridge.receive(frame(125))
    assert wait_for(lambda: bus.spin_once() or bool(link.written))
    assert link.take() == [(100, b"\x01" + string("hi"))]


def test_tx_stop_and_a_lost_link(host):
    bridge, link, _ = host
    link.written.clear()
    bridge.stop_device()
    assert bytes(link.written) == TX_STOP
    link.lost = True
    with pytest.raises(LinkLost):
        bridge.serve(threading.Event())


def test_a_quiet_line_settles_held_frames_and_gives_up_cut_ones(capsys, host, bus):
    bridge, link, clock = host
    bridge.receive(frame(0, topic_info(125, "chatter", "std_msgs/String")))
    chatter = received(bus, "chatter", "std_msgs/String")
    text_ff = next("x" * k for k in range(256) if frame(125, string("x" * k))[-1] == 0xFF)
    bridge.receive(frame(125, string(text_ff)))
    assert chatter == []  # its last byte is 0xff: held until the byte after it, or quiet
    clock.t += 0.03
    bridge.tick()
    assert [m.data for m in chatter] == [text_ff]
    bridge.receive(frame(125, string("cut short"))[:-3])
    clock.t += 0.3
    bridge.tick()
    assert "Packet Failed" not in text(capsys)  # still waiting for the rest
    clock.t += 0.3
    link.written.clear()
    bridge.tick()
    out = text(capsys)
    assert "Packet Failed :  Failed to read msg data" in out
    assert "expected msg length is 13" in out
    assert bytes(link.written) == REQUEST_TOPICS  # a cut frame: maybe a reset board
