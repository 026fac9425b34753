"""ros_lib's device side (workbench.serial.device) against the host, wired back to back in memory.

The device's bytes go straight into the bridge and the bridge's into the device, so
every step is deterministic; the device's clock is set by hand.
"""

from __future__ import annotations

from collections import deque

import pytest
from rosserial_bytes import frame, parse

from workbench.bus import Bus, Node
from workbench.msgs.std_msgs import Empty, String
from workbench.serial import device as ros
from workbench.serial.bridge import Bridge


class MemoryHardware:
    """A device's serial port in memory, with a clock the test moves (milliseconds)."""

    def __init__(self) -> None:
        self.incoming: deque[bytes] = deque()
        self.sent = bytearray()
        self.ms = 0

    def read_available(self) -> bytes:
        data = b"".join(self.incoming)
        self.incoming.clear()
        return data

    def write(self, data: bytes) -> None:
        self.sent += data

    def time(self) -> int:
        return self.ms

    def wait(self, seconds: float) -> None:
        self.ms += max(1, int(seconds * 1000))


class Wire:
    """The host's link whose other end is a MemoryHardware."""

    def __init__(self, hardware: MemoryHardware) -> None:
        self.hardware = hardware

    def read_some(self) -> bytes:
        return b""

    def write(self, data: bytes) -> None:
        self.hardware.incoming.append(bytes(data))

    def discard_input(self) -> None:
        pass

    def close(self) -> None:
        pass


@pytest.fixture
def pair():
    """(bus, bridge, nh, hardware): a NodeHandle (4 subscribers) and a host back to back."""
    bus = Bus(threaded=False)
    hardware = MemoryHardware()
    bridge = Bridge(Node("serial_node", bus=bus), write_thread=False)
    bridge.attach(Wire(hardware))
    nh = ros.NodeHandle(4, 4, 120, 100, hardware=hardware)
    nh.initNode()
    yield bus, bridge, nh, hardware
    bus.shutdown()


def exchange(bridge, nh, hardware, rounds: int = 3) -> None:
    """Let the two sides talk: the device spins, the host reads what it sent."""
    for _ in range(rounds):
        nh.spinOnce()
        if hardware.sent:
            data = bytes(hardware.sent)
            hardware.sent.clear()
            bridge.receive(data)


def test_ids_negotiation_and_publishing(pair, capsys):
    bus, bridge, nh, hardware = pair
    chatter = ros.Publisher("chatter", String())
    sub = ros.Subscriber("toggle_led", Empty, lambda msg: toggled.append(msg))
    toggled: list = []
    assert nh.advertise(chatter) and nh.subscribe(sub)
    assert (sub.id_, chatter.id_) == (100, 104)  # subscribers from 100, publishers after them
    assert chatter.publish(String(data="too early")) == 0 and not hardware.sent
    bridge.request_topics()
    exchange(bridge, nh, hardware)
    assert nh.connected()
    out = capsys.readouterr().out
    assert "Note: publish buffer size is 100 bytes" in out
    assert "Note: subscribe buffer size is 120 bytes" in out
    assert "Setup publisher on chatter [std_msgs/String]" in out
    assert "Setup subscriber on toggle_led [std_msgs/Empty]" in out
    got = []
    Node("echo", bus=bus).create_subscription("chatter", String, got.append, inline=True)
    assert chatter.publish(String(data="hello world!")) == 8 + 16
    exchange(bridge, nh, hardware)
    assert [m.data for m in got] == ["hello world!"]
    Node("me", bus=bus).create_publisher("toggle_led", Empty).publish()
    exchange(bridge, nh, hardware)
    assert len(toggled) == 1


def test_time_sync_gives_the_device_the_host_clock(pair):
    bus, bridge, nh, hardware = pair
    bridge.request_topics()
    exchange(bridge, nh, hardware)
    host_now = bridge.node.now().to_sec()
    hardware.ms += 1500
    assert abs(nh.now().to_sec() - (host_now + 1.5)) < 0.05
    hardware.ms += 2600  # past 2.5 s: the device asks for the time again
    nh.spinOnce()
    assert [topic for topic, _ in parse(bytes(hardware.sent))] == [10]


def test_too_big_a_message_is_dropped_and_logged_on_the_host(pair, capsys):
    bus, bridge, nh, hardware = pair
    chatter = ros.Publisher("chatter", String)
    nh.advertise(chatter)
    bridge.request_topics()
    exchange(bridge, nh, hardware)
    assert chatter.publish(String(data="x" * 100)) == -1
    exchange(bridge, nh, hardware)
    assert "Message from device dropped: message larger than buffer." in capsys.readouterr().err


def test_tx_stop_unconfigures_the_device(pair):
    bus, bridge, nh, hardware = pair
    chatter = ros.Publisher("chatter", String)
    nh.advertise(chatter)
    bridge.request_topics()
    exchange(bridge, nh, hardware)
    hardware.sent.clear()
    bridge.stop_device()
    assert nh.spinOnce() == ros.SPIN_TX_STOP_REQUESTED
    assert not nh.connected()
    assert chatter.publish(String(data="after stop")) == 0 and not hardware.sent


def test_get_param_fills_the_list_or_says_why_not(pair, capsys):
    bus, bridge, nh, hardware = pair
    bridge.node.set_param("~gains", [0.5, 1.5])
    bridge.node.set_param("~rate", 7)
    bridge.request_topics()
    exchange(bridge, nh, hardware)

    def serve_params():  # the host answers whenever the device waits
        if hardware.sent:
            data = bytes(hardware.sent)
            hardware.sent.clear()
            bridge.receive(data)

    original_wait = hardware.wait
    hardware.wait = lambda seconds: (serve_params(), original_wait(seconds))  # type: ignore[method-assign]
    gains = [0.0, 0.0]
    assert nh.getParam("~gains", gains) and gains == [0.5, 1.5]
    rate = [0]
    assert nh.getParam("~rate", rate) and rate == [7]
    three = [0, 0, 0]
    assert not nh.getParam("~rate", three)
    assert not nh.getParam("~missing", [0], timeout=50)
    serve_params()
    out = capsys.readouterr()
    assert "Failed to get param: length mismatch" in out.out + out.err
    assert "Failed to get param: timeout expired" in out.out + out.err
    assert "Parameter ~missing does not exist" in out.err


def test_a_frame_the_device_cannot_decode_is_logged_by_the_host(pair, capsys):
    bus, bridge, nh, hardware = pair
    nh.subscribe(ros.Subscriber("words", String, lambda msg: None))
    bridge.request_topics()
    exchange(bridge, nh, hardware)
    hardware.incoming.append(frame(100, b"\x09\x00\x00\x00ab"))
    exchange(bridge, nh, hardware)
    assert "Cannot decode the message on words" in capsys.readouterr().err
