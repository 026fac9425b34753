"""Writing ROS 1 bags (v2.0), record by record as ``rosbag record`` lays them out.

Like ``rosbag record``, the file is written as ``NAME.bag.active`` and
renamed to ``NAME.bag`` when it is closed cleanly, so a half-written bag is
never mistaken for a finished one (and can still be read, see
:mod:`workbench.bag.reader`).

Layout: the 4096-byte bag header record, then chunks (each followed by its
index data records), then the index section (every connection record, then
one chunk info record per chunk) that the header's ``index_pos`` points at.
A connection is one ``(topic, type, callerid, latching)``; its record is
written into the chunk of its first message (and again in the index), with
the connection header fields ``topic``, ``type``, ``md5sum``,
``message_definition``, and ``callerid`` and ``latching=1`` when known.

Crash safety (``chunk_seconds``): a chunk holding data is written out once its
oldest message is that many seconds old, so a process killed outright loses at
most about that much. The index section is then rewritten after the last
chunk and the header pointed at it, so the ``.active`` file of a killed
recording is an indexed bag that any reader opens as it is. Before the index
is overwritten by the next chunk the header's ``index_pos`` is set to 0
(unindexed, as while ``rosbag record`` runs); a file killed in that window is
read by scanning its records (:mod:`workbench.bag.reader`, ``rosbag reindex``).
"""

from __future__ import annotations

import bz2
import datetime
import os
import struct
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, BinaryIO

from workbench.bag.errors import BagWriteError

COMPRESSIONS = ("none", "bz2", "lz4")


def default_bag_name(prefix: str = "", when: datetime.datetime | None = None) -> str:
    """rosbag's default name: ``[prefix_]YYYY-MM-DD-HH-MM-SS.bag`` in local time."""
    stamp = (when or datetime.datetime.now()).strftime("%Y-%m-%d-%H-%M-%S")
    return f"{prefix}_{stamp}.bag" if prefix else f"{stamp}.bag"


def to_ns(stamp: Any) -> int:
    """A time as integer nanoseconds: ``int`` ns, ``float`` s, or a Time with secs/nsecs."""
    if type(stamp) is int:
        return stamp
    if stamp is None:
        return time.time_ns()
    if isinstance(stamp, bool):
        raise TypeError("a time cannot be a bool")
    if isinstance(stamp, int):
        return stamp
    if isinstance(stamp, float):
        return round(stamp * 1e9)
    if hasattr(stamp, "secs") and hasattr(stamp, "nsecs"):
        return int(stamp.secs) * 1_000_000_000 + int(stamp.nsecs)
    if hasattr(stamp, "sec") and hasattr(stamp, "nanosec"):
        return int(stamp.sec) * 1_000_000_000 + int(stamp.nanosec)
    raise TypeError(f"cannot use {stamp!r} as a time (give seconds, nanoseconds or a Time)")


def roslz4_frame(data: bytes) -> bytes:
    """An LZ4 frame as ROS's roslz4 writes and reads it.

    roslz4 (ros_comm 1.15) writes independent 1 MB blocks with a content checksum
    and no content size, and refuses frames that differ (the lz4 package's
    default frame carries the content size: "malformed data to decompress").
    """
    import lz4.frame

    return bytes(
        lz4.frame.compress(
            data,
            compression_level=0,
            block_size=lz4.frame.BLOCKSIZE_MAX1MB,
            block_linked=False,
            content_checksum=True,
            store_size=False,
        )
    )


_MAGIC = b"#ROSBAG V2.0\n"
# The bag header's fields and padding take 4096 bytes (8 more with their two lengths), as
# rosbag writes it: rosbag rewrites it in place (reindex, append), which must not reach the
# first chunk.
_HEADER_PADDED_SIZE = 4096
_U32 = struct.Struct("<I")
_U64 = struct.Struct("<Q")
_TIME = struct.Struct("<II")

# record op codes of the v2.0 format
_OP_MSG_DATA = 0x02
_OP_BAG_HEADER = 0x03
_OP_INDEX_DATA = 0x04
_OP_CHUNK = 0x05
_OP_CHUNK_INFO = 0x06
_OP_CONNECTION = 0x07


def _time(ns: int) -> bytes:
    return _TIME.pack(ns // 1_000_000_000, ns % 1_000_000_000)


def _fields(fields: dict[str, bytes]) -> bytes:
    """``name=value`` fields, each preceded by its length (a record header's body)."""
    out = bytearray()
    for name, value in fields.items():
        item = name.encode() + b"=" + value
        out += _U32.pack(len(item))
        out += item
    return bytes(out)


def _record(op: int, fields: dict[str, bytes], data: bytes = b"") -> bytes:
    """One record: its header (``op`` first, then ``fields``), then its data."""
    header = _fields({"op": bytes((op,)), **fields})
    return _U32.pack(len(header)) + header + _U32.pack(len(data)) + data


def _bag_header(index_pos: int, conn_count: int, chunk_count: int) -> bytes:
    header = _fields(
        {
            "op": bytes((_OP_BAG_HEADER,)),
            "index_pos": _U64.pack(index_pos),
            "conn_count": _U32.pack(conn_count),
            "chunk_count": _U32.pack(chunk_count),
        }
    )
    padding = _HEADER_PADDED_SIZE - len(header)
    return _U32.pack(len(header)) + header + _U32.pack(padding) + b" " * padding


@dataclass
class _Connection:
    id: int
    topic: str
    fields: dict[str, bytes]  # the connection header stored in the bag
    message_prefix: bytes = field(
        init=False, default=b""
    )  # a message record's header up to the time's value

    def __post_init__(self) -> None:
        op = _fields({"op": bytes((_OP_MSG_DATA,)), "conn": _U32.pack(self.id)})
        time_field = _U32.pack(len(b"time=") + _TIME.size) + b"time="
        self.message_prefix = _U32.pack(len(op) + len(time_field) + _TIME.size) + op + time_field

    def record(self) -> bytes:
        return _record(
            _OP_CONNECTION,
            {"conn": _U32.pack(self.id), "topic": self.topic.encode()},
            _fields(self.fields),
        )


@dataclass
class _ChunkInfo:
    pos: int
    start_ns: int
    end_ns: int
    counts: dict[int, int] = field(default_factory=dict)

    def record(self) -> bytes:
        data = b"".join(_U32.pack(cid) + _U32.pack(n) for cid, n in self.counts.items())
        return _record(
            _OP_CHUNK_INFO,
            {
                "ver": _U32.pack(1),
                "chunk_pos": _U64.pack(self.pos),
                "start_time": _time(self.start_ns),
                "end_time": _time(self.end_ns),
                "count": _U32.pack(len(self.counts)),
            },
            data,
        )


class BagWriter:
    """Write messages to a ROS 1 bag.

    Args:
        path: The finished bag's path (``.bag`` is added if missing).
        compression: ``none`` (default), ``bz2`` or ``lz4`` chunks.
        chunk_size: Bytes per chunk before it is written out (rosbag uses 768 KiB).
        chunk_seconds: Also write a chunk out (and the index after it) once its oldest
            message is this many seconds old (wall time), so that a process killed
            outright loses at most about that much; None: by size only, as rosbag.

    Example::

        with BagWriter("run.bag") as bag:
            bag.write("/turtle1/cmd_vel", Twist(), t=0.5)
    """

    def __init__(
        self,
        path: str | os.PathLike[str],
        *,
        compression: str = "none",
        chunk_size: int = 768 * 1024,
        chunk_seconds: float | None = None,
    ) -> None:
        path = Path(path)
        if path.suffix != ".bag":
            path = path.with_name(path.name + ".bag")
        self.path = path
        self.active_path = path.with_name(path.name + ".active")
        if compression not in COMPRESSIONS:
            raise BagWriteError(
                f"unknown compression '{compression}'", hint=f"use one of {', '.join(COMPRESSIONS)}"
            )
        if chunk_seconds is not None and not chunk_seconds > 0:
            raise BagWriteError(f"chunk_seconds must be positive, got {chunk_seconds}")
        self.compression = compression
        self.chunk_size = chunk_size
        self.chunk_seconds = chunk_seconds
        self.counts: dict[str, int] = {}
        self._file: BinaryIO | None = None
        self._closed = False
        self._connections: dict[tuple[str, str, str | None, bool], _Connection] = {}
        self._chunks: list[_ChunkInfo] = []
        self._data_end = 0  # where the next chunk goes (the index follows the last chunk)
        self._indexed = False  # whether the header points at an index of every chunk written
        self._index_written_at = 0.0  # time.monotonic() of the last index written
        self._new_chunk()

    def _new_chunk(self) -> None:
        self._buffer = bytearray()  # the open chunk, uncompressed
        self._entries: dict[int, list[tuple[int, int]]] = {}  # conn -> (time ns, offset)
        self._start_ns = 2**64 - 1
        self._end_ns = 0
        self._opened_at = 0.0  # time.monotonic() of the open chunk's first message

    # --- life cycle ----------------------------------------------------------------

    def open(self) -> BagWriter:
        """Create ``NAME.bag.active``.

        Raises:
            BagWriteError: the directory is missing or not writable.
        """
        parent = self.path.parent
        if not parent.is_dir():
            raise BagWriteError(
                "cannot record: the directory does not exist",
                path=self.path,
                hint=f"create {parent} first",
            )
        try:
            if self.active_path.exists():
                self.active_path.unlink()
            handle = self.active_path.open("xb")
            handle.write(_MAGIC + _bag_header(0, 0, 0))
            handle.flush()
        except OSError as error:
            raise BagWriteError(
                f"cannot record: {error.strerror or error}",
                path=self.path,
                hint="choose a writable directory",
            ) from None
        self._file = handle
        self._data_end = handle.tell()
        self._index_written_at = time.monotonic()
        return self

    def close(self) -> Path:
        """Write the last chunk and the index, rename ``.bag.active`` to ``.bag``; returns the path."""
        handle = self._file
        if handle is None:
            return self.path
        try:
            self._write_chunk(index=True)
            handle.close()
            os.replace(self.active_path, self.path)
        except OSError as error:
            raise BagWriteError(
                f"cannot finish the bag: {error.strerror or error}",
                path=self.active_path,
                hint="the messages written so far are in the .active file",
            ) from None
        finally:
            self._file = None
            self._closed = True
            if not handle.closed:
                handle.close()
        return self.path

    def __enter__(self) -> BagWriter:
        return self.open() if self._file is None else self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def is_open(self) -> bool:
        return self._file is not None

    # --- writing -------------------------------------------------------------------

    def add_connection(
        self,
        topic: str,
        typename: str,
        *,
        md5sum: str | None = None,
        definition: str | None = None,
        callerid: str | None = None,
        latching: bool = False,
    ) -> int:
        """The id of the connection ``(topic, type, callerid, latching)``, declaring it if new.

        Its record is written into the open chunk, ahead of the message that needs it
        (``write`` declares connections itself; md5sum and definition are looked up
        when omitted).
        """
        typename = typename.replace("/msg/", "/", 1)
        key = (topic, typename, callerid or None, bool(latching))
        conn = self._connections.get(key)
        if conn is not None:
            return conn.id
        if self._file is None:
            if self._closed:
                raise BagWriteError("cannot write: the bag is closed", path=self.path)
            self.open()
        if md5sum is None or definition is None:
            from workbench.bag.types import type_info

            md5sum, definition = type_info(typename)
        fields = {
            "topic": topic.encode(),
            "type": typename.encode(),
            "md5sum": md5sum.encode(),
            "message_definition": definition.encode(),
        }
        if callerid:
            fields["callerid"] = callerid.encode()
        if latching:
            fields["latching"] = b"1"
        conn = _Connection(len(self._connections), topic, fields)
        self._connections[key] = conn
        self._buffer += conn.record()
        return conn.id

    def write(
        self,
        topic: str,
        msg: Any = None,
        t: Any = None,
        *,
        typename: str | None = None,
        data: bytes | None = None,
        callerid: str | None = None,
        latching: bool = False,
    ) -> None:
        """Append one message.

        Args:
            topic: Topic name.
            msg: A ``workbench.msgs`` message (or None when ``data`` is given).
            t: Receive time: float seconds, int nanoseconds or a Time; None is now.
            typename: Needed with ``data``; defaults to ``msg._type``.
            data: Already serialized ROS 1 bytes.
            callerid: The publishing node (a connection per topic and publisher, as rosbag).
            latching: Whether the publisher latches (stored as ``latching=1``).

        Raises:
            BagWriteError: The file cannot be written, or the time is outside ROS's range.
        """
        if typename is None:
            if msg is None:
                raise BagWriteError(f"no message and no type for topic {topic}")
            typename = msg._type
        stamp = to_ns(t)
        if not 0 <= stamp < 2**32 * 1_000_000_000:
            raise BagWriteError(f"time {stamp / 1e9} s is outside a bag's range (0 to 2^32 s)")
        if data is None:
            from workbench.msgs import serialize

            data = serialize(msg)
        if self._file is None:
            if self._closed:
                raise BagWriteError("cannot write: the bag is closed", path=self.path)
            self.open()
        key = (topic, typename.replace("/msg/", "/", 1), callerid or None, bool(latching))
        conn = self._connections.get(key)
        if conn is None:
            self.add_connection(topic, typename, callerid=callerid, latching=latching)
            conn = self._connections[key]
        buffer = self._buffer
        if not self._entries:
            self._opened_at = time.monotonic()
        self._entries.setdefault(conn.id, []).append((stamp, len(buffer)))
        self._start_ns = min(self._start_ns, stamp)
        self._end_ns = max(self._end_ns, stamp)
        buffer += conn.message_prefix
        buffer += _time(stamp)
        buffer += _U32.pack(len(data))
        buffer += data
        self.counts[topic] = self.counts.get(topic, 0) + 1
        if len(buffer) >= self.chunk_size:
            seconds = self.chunk_seconds
            index = seconds is not None and time.monotonic() - self._index_written_at >= seconds
            self._write_out(index)
        else:
            self.flush_if_due()

    def flush_if_due(self) -> bool:
        """Write the open chunk and the index if its oldest message is ``chunk_seconds`` old.

        A recorder calls this now and then, so that data is written out even when no
        more messages arrive. Returns whether it wrote.
        """
        seconds = self.chunk_seconds
        if seconds is None or not self._entries or self._file is None:
            return False
        if time.monotonic() - self._opened_at < seconds:
            return False
        self._write_out(True)
        return True

    def flush(self) -> None:
        """Write the open chunk and the index now (the file is then a complete bag)."""
        if self._file is not None:
            self._write_out(True)

    def _write_out(self, index: bool) -> None:
        try:
            self._write_chunk(index)
        except OSError as error:
            raise BagWriteError(
                f"cannot write to the bag: {error.strerror or error}", path=self.active_path
            ) from None

    def _write_chunk(self, index: bool) -> None:
        """Write the open chunk (if it has messages), then the index section if ``index``."""
        handle = self._file
        assert handle is not None
        if self._entries:
            if self._indexed:  # the chunk goes where the index is: unindexed meanwhile
                self._write_header(0)
            raw = bytes(self._buffer)
            packed = _COMPRESSORS[self.compression](raw)
            out = bytearray(
                _record(
                    _OP_CHUNK,
                    {"compression": self.compression.encode(), "size": _U32.pack(len(raw))},
                    packed,
                )
            )
            info = _ChunkInfo(self._data_end, self._start_ns, self._end_ns)
            for cid, entries in self._entries.items():
                info.counts[cid] = len(entries)
                out += _record(
                    _OP_INDEX_DATA,
                    {"ver": _U32.pack(1), "conn": _U32.pack(cid), "count": _U32.pack(len(entries))},
                    b"".join(_time(stamp) + _U32.pack(offset) for stamp, offset in entries),
                )
            handle.seek(self._data_end)
            handle.write(out)
            handle.flush()
            self._data_end += len(out)
            self._chunks.append(info)
            self._new_chunk()
        if index and not self._indexed:
            handle.seek(self._data_end)
            for conn in self._connections.values():
                handle.write(conn.record())
            for info in self._chunks:
                handle.write(info.record())
            handle.truncate()
            handle.flush()
            self._write_header(self._data_end)
            self._index_written_at = time.monotonic()

    def _write_header(self, index_pos: int) -> None:
        handle = self._file
        assert handle is not None
        handle.seek(len(_MAGIC))
        handle.write(_bag_header(index_pos, len(self._connections), len(self._chunks)))
        handle.flush()
        self._indexed = index_pos != 0


def _bz2(data: bytes) -> bytes:
    return bz2.compress(data, 9)


_COMPRESSORS: dict[str, Callable[[bytes], bytes]] = {
    "none": bytes,
    "bz2": _bz2,
    "lz4": roslz4_frame,
}
