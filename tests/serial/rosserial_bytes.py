"""A rosserial device's bytes, written out by hand from the protocol (not with workbench's encoder).

Importable by name from the serial tests (``from rosserial_bytes import frame``). The
md5sums are ROS's own (``rosmsg md5``), typed in, so a test compares workbench's
against them rather than against itself.
"""

from __future__ import annotations

import struct
from collections import deque

MD5 = {
    "std_msgs/String": "992ce8a1687cec8c8bd883ec73ca41d1",
    "std_msgs/Empty": "d41d8cd98f00b204e9800998ecf8427e",
    "std_msgs/Bool": "8b94c1b53db61fb6aed406028ad6332a",
    "std_msgs/Int32": "da5909fbe378aeaf85e547e830cc1bb7",
    "std_srvs/SetBoolRequest": "8b94c1b53db61fb6aed406028ad6332a",
    "std_srvs/SetBoolResponse": "937c9679a518e3a18d831e57125ea522",
    "std_srvs/TriggerRequest": "d41d8cd98f00b204e9800998ecf8427e",
    "std_srvs/TriggerResponse": "937c9679a518e3a18d831e57125ea522",
}

REQUEST_TOPICS = bytes.fromhex("ff fe 00 00 ff 00 00 ff")
TIME_REQUEST = bytes.fromhex("ff fe 00 00 ff 0a 00 f5")
TX_STOP = bytes.fromhex("ff fe 00 00 ff 0b 00 f4")


def frame(topic: int, payload: bytes = b"", version: int = 0xFE) -> bytes:
    """One frame: sync, version, length, length checksum, topic id, payload, checksum."""
    lo, hi = len(payload) & 0xFF, len(payload) >> 8
    body = struct.pack("<H", topic) + payload
    return (
        bytes([0xFF, version, lo, hi, 255 - (lo + hi) % 256])
        + body
        + bytes([255 - sum(body) % 256])
    )


def string(text: str | bytes) -> bytes:
    data = text.encode() if isinstance(text, str) else text
    return struct.pack("<I", len(data)) + data


def topic_info(
    topic_id: int, name: str, type_: str, md5: str | None = None, buffer: int = 280
) -> bytes:
    """A rosserial_msgs/TopicInfo: id, topic, type, md5sum, buffer size."""
    md5 = MD5[type_] if md5 is None else md5
    return (
        struct.pack("<H", topic_id)
        + string(name)
        + string(type_)
        + string(md5)
        + struct.pack("<i", buffer)
    )


def log(level: int, text: str) -> bytes:
    """A rosserial_msgs/Log."""
    return bytes([level]) + string(text)


def parse(data: bytes) -> list[tuple[int, bytes]]:
    """The (topic, payload) of each well-formed frame in ``data``, in order (asserting checksums)."""
    out = []
    at = 0
    while at < len(data):
        assert data[at : at + 2] == b"\xff\xfe", data[at:].hex(" ")
        length = data[at + 2] | data[at + 3] << 8
        assert (data[at + 2] + data[at + 3] + data[at + 4]) % 256 == 255
        body = data[at + 5 : at + 7 + length]
        assert (sum(body) + data[at + 7 + length]) % 256 == 255
        out.append((struct.unpack("<H", body[:2])[0], body[2:]))
        at += 8 + length
    return out


class FakeLink:
    """A link whose device side is the test: it queues incoming bytes and keeps what is written."""

    def __init__(self) -> None:
        self.incoming: deque[bytes] = deque()
        self.written = bytearray()
        self.lost = False

    def read_some(self) -> bytes:
        from workbench.serial.links import LinkLost

        if self.lost:
            raise LinkLost("the test pulled the cable")
        return self.incoming.popleft() if self.incoming else b""

    def write(self, data: bytes) -> None:
        self.written += data

    def discard_input(self) -> None:
        self.incoming.clear()

    def close(self) -> None:
        self.lost = True

    def take(self) -> list[tuple[int, bytes]]:
        """The frames written since the last call."""
        frames = parse(bytes(self.written))
        self.written.clear()
        return frames
