"""rosserial's wire format: the frame, the reserved topic ids and the fixed frames.

A frame (protocol "Rev 1", rosserial 0.5 and later, as in rosserial_python's
``SerialClient.py`` and rosserial_client's ``ros/node_handle.h``, noetic-devel)::

    0xff  0xfe  len_lo len_hi  len_checksum  id_lo id_hi  payload (len bytes)  checksum

* ``len`` is the payload length in bytes, little-endian, and ``len_checksum`` makes
  ``len_lo + len_hi + len_checksum`` equal 255 modulo 256;
* ``id`` is the topic id, little-endian; ``checksum`` makes the sum of the two id bytes,
  the payload and itself equal 255 modulo 256;
* the payload is the message in ROS 1 serialization.

The second byte is the protocol version: 0xff for Rev 0 (rosserial 0.4 and earlier,
through groovy), 0xfe for Rev 1 (hydro and later). Topic ids below 100 are reserved
(``rosserial_msgs/TopicInfo``'s constants); a device numbers its subscribers from 100
and its publishers from ``100 + MAX_SUBSCRIBERS``.
"""

from __future__ import annotations

#: First byte of every frame.
SYNC = 0xFF
#: Protocol version byte of Rev 0 (rosserial 0.4 and earlier).
PROTOCOL_VER1 = 0xFF
#: Protocol version byte of Rev 1 (rosserial 0.5+), the one spoken here.
PROTOCOL_VER2 = 0xFE
PROTOCOL_VER = PROTOCOL_VER2

#: What each version byte means, as rosserial_python names it.
PROTOCOL_NAMES = {
    PROTOCOL_VER1: "Rev 0 (rosserial 0.4 and earlier)",
    PROTOCOL_VER2: "Rev 1 (rosserial 0.5+)",
    0xFD: "Some future rosserial version",
}

# Reserved topic ids (rosserial_msgs/TopicInfo).
ID_PUBLISHER = 0
ID_SUBSCRIBER = 1
ID_SERVICE_SERVER = 2
ID_SERVICE_CLIENT = 4
ID_PARAMETER_REQUEST = 6
ID_LOG = 7
ID_TIME = 10
ID_TX_STOP = 11
#: The first id a device gives its own subscribers and publishers.
FIRST_TOPIC_ID = 100

#: Bytes before the payload: sync, version, length (2), length checksum, topic id (2).
HEADER_SIZE = 7
#: Bytes a frame adds to its payload (the header and the final checksum).
FRAME_OVERHEAD = HEADER_SIZE + 1
#: The largest payload the 16-bit length can describe.
MAX_PAYLOAD = 0xFFFF

# rosserial_msgs/Log levels.
LOG_DEBUG = 0
LOG_INFO = 1
LOG_WARN = 2
LOG_ERROR = 3
LOG_FATAL = 4


def checksum(data: bytes | bytearray | memoryview) -> int:
    """The byte that brings the sum of ``data`` and itself to 255 modulo 256."""
    return 255 - (sum(data) & 0xFF)


def encode_frame(topic_id: int, payload: bytes | bytearray | memoryview = b"") -> bytes:
    """One Rev 1 frame carrying ``payload`` on ``topic_id``.

    Args:
        topic_id: 0..65535.
        payload: The serialized message (at most 65535 bytes).

    Raises:
        ValueError: The payload is longer than 65535 bytes or the id is out of range.
    """
    length = len(payload)
    if length > MAX_PAYLOAD:
        raise ValueError(f"a rosserial frame carries at most {MAX_PAYLOAD} bytes, not {length}")
    if not 0 <= topic_id <= 0xFFFF:
        raise ValueError(f"a rosserial topic id is 0..65535, not {topic_id}")
    len_lo, len_hi = length & 0xFF, length >> 8
    id_lo, id_hi = topic_id & 0xFF, topic_id >> 8
    body = bytes((id_lo, id_hi)) + bytes(payload)
    head = bytes((SYNC, PROTOCOL_VER, len_lo, len_hi, 255 - ((len_lo + len_hi) & 0xFF)))
    return head + body + bytes((checksum(body),))


#: The host's request that the device (re)send its topics: an empty frame on id 0.
REQUEST_TOPICS = encode_frame(ID_PUBLISHER)
#: The host's request that the device stop sending until asked again.
TX_STOP = encode_frame(ID_TX_STOP)


def version_name(byte: int) -> str:
    """rosserial_python's description of a protocol version byte."""
    return PROTOCOL_NAMES.get(byte, "unrecognized")
