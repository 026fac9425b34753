"""The records of a ROS 1 bag (v2.0), read within bounds.

Every record is ``header_len`` (uint32), a header of ``field_len`` + ``name=value``
fields, ``data_len`` (uint32) and the data. Reading a record checks each length
against what is left of the file or chunk and against a bound, and every
problem -- a length past the end, a missing field, a field of the wrong size, a
chunk that decompresses to more than it says -- is one :class:`Corrupt` naming
the byte offset. Nothing here raises ``struct.error``, ``KeyError`` or a
decompressor's own exception.
"""

from __future__ import annotations

import bz2
import struct
from dataclasses import dataclass
from typing import BinaryIO

from workbench.limits import MiB, human_bytes

MAGIC = b"#ROSBAG V2.0\n"

OP_MSG_DATA = 0x02
OP_BAG_HEADER = 0x03
OP_INDEX_DATA = 0x04
OP_CHUNK = 0x05
OP_CHUNK_INFO = 0x06
OP_CONNECTION = 0x07

#: Largest record header (a connection's fields, a chunk's), bytes.
MAX_HEADER_BYTES = 1 * MiB
#: Largest data of a record outside a chunk (a connection's definition, an index), bytes.
MAX_RECORD_BYTES = 64 * MiB
#: Largest chunk once decompressed, bytes (rosbag writes 768 KiB; one message may be larger).
MAX_CHUNK_BYTES = 256 * MiB

_U32 = struct.Struct("<I")
_U64 = struct.Struct("<Q")
_TIME = struct.Struct("<II")


class Corrupt(Exception):
    """A record that cannot be read; ``offset`` is where it starts."""

    def __init__(self, reason: str, offset: int) -> None:
        super().__init__(reason)
        self.reason = reason
        self.offset = offset


@dataclass
class Record:
    """One record: its header fields, and where its data lies."""

    offset: int  # of the record in its file or chunk
    fields: dict[str, bytes]
    data_offset: int
    data_length: int
    declared_length: int | None = None  # when the data is cut short: what the record says

    @property
    def end(self) -> int:
        return self.data_offset + self.data_length

    @property
    def op(self) -> int:
        value = self.fields.get("op")
        if value is None or len(value) != 1:
            raise Corrupt("record without an op code", self.offset)
        return value[0]

    def _field(self, name: str, size: int | None = None) -> bytes:
        value = self.fields.get(name)
        if value is None:
            raise Corrupt(f"record has no '{name}' field", self.offset)
        if size is not None and len(value) != size:
            raise Corrupt(f"field '{name}' has {len(value)} bytes, not {size}", self.offset)
        return value

    def u32(self, name: str) -> int:
        return _U32.unpack(self._field(name, 4))[0]

    def u64(self, name: str) -> int:
        return _U64.unpack(self._field(name, 8))[0]

    def time(self, name: str) -> int:
        """A ``time`` field in integer nanoseconds."""
        sec, nsec = _TIME.unpack(self._field(name, 8))
        return sec * 1_000_000_000 + nsec

    def text(self, name: str) -> str:
        try:
            return self._field(name).decode("utf-8")
        except UnicodeDecodeError:
            raise Corrupt(f"field '{name}' is not UTF-8 text", self.offset) from None

    def optional_text(self, name: str) -> str | None:
        return self.text(name) if name in self.fields else None


def parse_fields(raw: bytes, offset: int) -> dict[str, bytes]:
    """``name=value`` fields, each preceded by its length."""
    fields: dict[str, bytes] = {}
    at = 0
    while at < len(raw):
        if at + 4 > len(raw):
            raise Corrupt("record header ends inside a field length", offset)
        (length,) = _U32.unpack_from(raw, at)
        at += 4
        if length > len(raw) - at:
            raise Corrupt(f"header field of {length} bytes runs past its header", offset)
        item = raw[at : at + length]
        at += length
        name, sep, value = item.partition(b"=")
        if not sep:
            raise Corrupt("header field without '='", offset)
        try:
            fields[name.decode("ascii")] = value
        except UnicodeDecodeError:
            raise Corrupt("header field name is not ASCII", offset) from None
    return fields


def read_record(
    stream: BinaryIO, offset: int, end: int, max_data: int, clamp: bool = False
) -> Record:
    """The record at ``offset`` of ``stream`` (which ends at ``end``); its data is not read.

    Args:
        clamp: Accept data cut short by ``end`` (a file cut off while its last chunk was
            written): the record then says so in ``declared_length``.

    Raises:
        Corrupt: The lengths run past ``end`` or the bounds, or the header is malformed.
    """
    stream.seek(offset)
    head = stream.read(4)
    if len(head) < 4:
        raise Corrupt("record cut short before its header length", offset)
    (header_length,) = _U32.unpack(head)
    if header_length > min(MAX_HEADER_BYTES, end - offset - 8):
        raise Corrupt(f"record header of {header_length} bytes does not fit", offset)
    raw = stream.read(header_length)
    fields = parse_fields(raw, offset)
    tail = stream.read(4)
    if len(tail) < 4:
        raise Corrupt("record cut short before its data length", offset)
    (data_length,) = _U32.unpack(tail)
    data_offset = offset + 4 + header_length + 4
    if data_length > max_data:
        raise Corrupt(f"record data of {human_bytes(data_length)} is past the bound", offset)
    if data_length > end - data_offset and clamp:
        return Record(offset, fields, data_offset, end - data_offset, data_length)
    if data_length > end - data_offset:
        raise Corrupt(
            f"record data of {data_length} bytes runs past the end "
            f"({end - data_offset} bytes left)",
            offset,
        )
    return Record(offset, fields, data_offset, data_length)


def read_data(stream: BinaryIO, record: Record) -> bytes:
    stream.seek(record.data_offset)
    data = stream.read(record.data_length)
    if len(data) < record.data_length:
        raise Corrupt("record data cut short", record.offset)
    return data


def decompress(compression: str, data: bytes, size: int, offset: int) -> bytes:
    """A chunk's records, decompressed to at most ``size`` bytes (the chunk header's claim).

    Raises:
        Corrupt: Unknown compression, a claim past :data:`MAX_CHUNK_BYTES`, data that does
            not decompress, or decompresses to more than it claims.
    """
    if size > MAX_CHUNK_BYTES:
        raise Corrupt(
            f"chunk claims {human_bytes(size)} uncompressed, more than the "
            f"{human_bytes(MAX_CHUNK_BYTES)} a chunk may hold",
            offset,
        )
    try:
        if compression == "none":
            out = data
        elif compression == "bz2":
            out = bz2.BZ2Decompressor().decompress(data, max_length=size + 1)
        elif compression == "lz4":
            import lz4.frame

            out = lz4.frame.LZ4FrameDecompressor().decompress(data, max_length=size + 1)
        else:
            raise Corrupt(f"unknown compression {compression[:20]!r}", offset)
    except Corrupt:
        raise
    except Exception as error:  # bz2's OSError, lz4's RuntimeError: the data is damaged
        reason = " ".join(str(error).split())[:80]
        raise Corrupt(f"{compression} data does not decompress ({reason})", offset) from None
    if len(out) > size:
        raise Corrupt(f"chunk decompresses to more than the {size} bytes it claims", offset)
    return out
