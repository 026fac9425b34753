"""Reading ROS 1 bags (v2.0): summary, messages, and recovery of damaged files.

An intact bag is read through ``rosbags.rosbag1.Reader`` (its index).
A bag without a usable index -- a ``.bag.active`` left by a recorder that
was killed, a file cut short by a full disk, a corrupt index -- is read by
walking its records from the start with rosbags' record parser, the way
``rosbag reindex`` does, and everything up to the damage is returned.

Times are nanoseconds since the epoch (``int``) in the raw API and seconds
(``float``) in :class:`BagMessage`.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from io import BytesIO
from pathlib import Path
from typing import Any, BinaryIO, NamedTuple, cast

from rosbags.interfaces import ConnectionExtRosbag1
from rosbags.rosbag1 import Reader as _RosbagsReader
from rosbags.rosbag1.reader import (
    Header,
    ReaderError,
    RecordType,
    decompressors,
    read_bytes,
    read_uint32,
)
from rosbags.typesys.msg import denormalize_msgtype

from workbench.bag.errors import BagDamagedError, BagFormatError, BagNotFoundError

_MAGIC = b"#ROSBAG V2.0\n"


@dataclass(frozen=True)
class BagConnection:
    """One connection record: a topic with its type as the recorder saw it."""

    id: int
    topic: str
    typename: str  # ROS 1 style, e.g. "geometry_msgs/Twist"
    md5sum: str
    definition: str
    callerid: str | None = None
    latching: bool = False


@dataclass
class ChunkSummary:
    """One chunk: compression, sizes in bytes, time span (ns) and counts per connection."""

    compression: str
    uncompressed_size: int
    compressed_size: int
    start_ns: int
    end_ns: int
    counts: dict[int, int] = field(default_factory=dict)


@dataclass
class BagSummary:
    """What ``rosbag info`` shows, plus how the bag was read.

    Attributes:
        path: The file.
        size: File size in bytes.
        connections: By connection id.
        chunks: In file order.
        indexed: True when read through the index; False when recovered by a scan.
        damage: Why the scan stopped early (None for an intact bag).
    """

    path: Path
    size: int
    connections: dict[int, BagConnection]
    chunks: list[ChunkSummary]
    indexed: bool = True
    damage: str | None = None

    @property
    def message_count(self) -> int:
        return sum(sum(c.counts.values()) for c in self.chunks)

    @property
    def start_ns(self) -> int | None:
        starts = [c.start_ns for c in self.chunks if c.counts]
        return min(starts) if starts else None

    @property
    def end_ns(self) -> int | None:
        ends = [c.end_ns for c in self.chunks if c.counts]
        return max(ends) if ends else None

    def topic_counts(self) -> dict[str, int]:
        """Messages per topic, topics sorted."""
        counts: dict[str, int] = {}
        for chunk in self.chunks:
            for cid, n in chunk.counts.items():
                topic = self.connections[cid].topic
                counts[topic] = counts.get(topic, 0) + n
        for conn in self.connections.values():
            counts.setdefault(conn.topic, 0)
        return dict(sorted(counts.items()))

    def topic_types(self) -> dict[str, str]:
        """Topic -> message type."""
        return {c.topic: c.typename for c in sorted(self.connections.values(), key=lambda c: c.id)}


class BagMessage(NamedTuple):
    """One message read from a bag.

    Attributes:
        topic: Topic name.
        time: Receive time in seconds since the epoch (what rosbag stores).
        msg: The message (a ``workbench.msgs`` object), or bytes when read raw.
        typename: ROS 1 type name.
        stamp_ns: ``time`` in integer nanoseconds.
    """

    topic: str
    time: float
    msg: Any
    typename: str
    stamp_ns: int


# --- opening --------------------------------------------------------------------------


def _check_file(path: Path) -> None:
    if not path.exists():
        hint = None
        active = path.with_name(path.name + ".active")
        if active.exists():
            hint = f"a recording was interrupted; read {active.name} instead"
        raise BagNotFoundError("bag file does not exist", path=path, hint=hint)
    if path.is_dir():
        raise BagFormatError("is a directory, not a bag file", path=path)
    with path.open("rb") as f:
        magic = f.read(len(_MAGIC))
    if not magic:
        raise BagDamagedError("bag file is empty", path=path, hint="nothing was recorded")
    if magic.startswith(b"#ROSBAG V") and magic != _MAGIC:
        version = magic[9:].split(b"\n")[0].decode(errors="replace")
        raise BagFormatError(
            f"bag version {version} is not supported (only 2.0)",
            path=path,
            hint="migrate it with 'rosbag fix' on a ROS machine",
        )
    if magic != _MAGIC:
        raise BagFormatError("not a ROS bag (no '#ROSBAG V2.0' magic)", path=path)


def summarize(path: str | os.PathLike[str]) -> BagSummary:
    """Read a bag's summary; a damaged bag is scanned and its readable part summarized.

    Raises:
        BagNotFoundError: no such file.
        BagFormatError: not a v2.0 bag.
        BagDamagedError: nothing at all could be read.
    """
    path = Path(path)
    _check_file(path)
    try:
        return _summarize_indexed(path)
    except (ReaderError, AssertionError, KeyError, ValueError, OSError):
        pass
    return _scan(path, want_messages=False)[0]


def _ros1_ext(connection: Any) -> ConnectionExtRosbag1:
    """The ROS 1 part of a rosbags connection (a .bag file's connections all have one)."""
    return cast(ConnectionExtRosbag1, connection.ext)


def _summarize_indexed(path: Path) -> BagSummary:
    reader = _RosbagsReader(path)
    reader.open()
    try:
        connections = {
            c.id: BagConnection(
                c.id,
                c.topic,
                denormalize_msgtype(c.msgtype),
                c.digest,
                c.msgdef.data,
                _ros1_ext(c).callerid,
                bool(_ros1_ext(c).latching),
            )
            for c in reader.connections
        }
        chunks = []
        bio = reader.bio
        assert bio is not None
        for info in reader.chunk_infos:
            bio.seek(info.pos)
            header = Header.read(bio, RecordType.CHUNK)
            compressed = read_uint32(bio)
            chunks.append(
                ChunkSummary(
                    header.get_string("compression"),
                    header.get_uint32("size"),
                    compressed,
                    info.start_time,
                    info.end_time - 1,  # rosbags reports end + 1 ns
                    dict(info.connection_counts),
                )
            )
    finally:
        reader.close()
    return BagSummary(path, path.stat().st_size, connections, chunks, indexed=True)


# --- scanning (recovery) -----------------------------------------------------------------


def _read_connection_data(header: Header, bio: BinaryIO) -> BagConnection:
    conn = header.get_uint32("conn")
    topic = header.get_string("topic")
    data = Header.read(bio)
    latching = data.get_string("latching") if "latching" in data else ""
    return BagConnection(
        conn,
        topic,
        data.get_string("type"),
        data.get_string("md5sum"),
        data.get_string("message_definition"),
        data.get_string("callerid") if "callerid" in data else None,
        latching not in ("", "0"),
    )


def _scan(
    path: Path, *, want_messages: bool
) -> tuple[BagSummary, list[tuple[BagConnection, int, bytes]]]:
    """Walk the records from the start; stop at the first damage."""
    connections: dict[int, BagConnection] = {}
    chunks: list[ChunkSummary] = []
    messages: list[tuple[BagConnection, int, bytes]] = []
    damage: str | None = None
    with path.open("rb") as bio:
        bio.read(len(_MAGIC))
        try:
            header = Header.read(bio, RecordType.BAGHEADER)
            index_pos = header.get_uint64("index_pos")
            bio.seek(read_uint32(bio), os.SEEK_CUR)
        except ReaderError as error:
            raise BagDamagedError(
                f"bag header is unreadable ({error})",
                path=path,
                hint="the file is not a usable bag",
            ) from None
        end = path.stat().st_size
        while bio.tell() < end:
            if index_pos and bio.tell() >= index_pos:
                break  # the index section: everything before it has been read
            start = bio.tell()
            try:
                header = Header.read(bio)
                op = header.get_uint8("op")
                if op == RecordType.CHUNK:
                    chunk, damage = _scan_chunk(header, bio, connections, messages, want_messages)
                    if chunk.counts or damage is None:
                        chunks.append(chunk)
                    if damage:
                        break
                elif op == RecordType.CONNECTION:
                    conn = _read_connection_data(header, bio)
                    connections.setdefault(conn.id, conn)
                elif op in (RecordType.IDXDATA, RecordType.CHUNK_INFO):
                    bio.seek(read_uint32(bio), os.SEEK_CUR)
                else:
                    damage = f"unexpected record type {op} at byte {start}"
                    break
            except (ReaderError, ValueError) as error:
                damage = f"truncated or corrupt at byte {start} ({error})"
                break
    summary = BagSummary(
        path, path.stat().st_size, connections, chunks, indexed=False, damage=damage or "no index"
    )
    if not connections and not chunks and damage:
        raise BagDamagedError(f"no readable messages: {damage}", path=path)
    return summary, messages


def _scan_chunk(
    header: Header,
    bio: BinaryIO,
    connections: dict[int, BagConnection],
    messages: list[tuple[BagConnection, int, bytes]],
    want_messages: bool,
) -> tuple[ChunkSummary, str | None]:
    compression = header.get_string("compression")
    size = header.get_uint32("size")
    datasize = read_uint32(bio)
    raw = bio.read(datasize)
    damage = None
    if len(raw) < datasize:
        damage = f"chunk cut short ({len(raw)} of {datasize} bytes)"
    try:
        data = decompressors[compression](raw)
    except KeyError:
        return ChunkSummary(
            compression, size, datasize, 0, 0
        ), f"unknown compression {compression!r}"
    except Exception:  # a cut-off compressed chunk cannot be decompressed at all
        return ChunkSummary(
            compression, size, datasize, 0, 0
        ), damage or "chunk does not decompress"
    chunk = ChunkSummary(compression, size, datasize, 2**63 - 1, 0)
    inner = BytesIO(data)
    while inner.tell() < len(data):
        try:
            record = Header.read(inner)
            op = record.get_uint8("op")
            if op == RecordType.CONNECTION:
                conn = _read_connection_data(record, inner)
                connections.setdefault(conn.id, conn)
            elif op == RecordType.MSGDATA:
                cid = record.get_uint32("conn")
                stamp = record.get_time("time")
                payload = read_bytes(inner, read_uint32(inner))
                if cid not in connections:
                    damage = damage or f"message on unknown connection {cid}"
                    break
                chunk.counts[cid] = chunk.counts.get(cid, 0) + 1
                chunk.start_ns = min(chunk.start_ns, stamp)
                chunk.end_ns = max(chunk.end_ns, stamp)
                if want_messages:
                    messages.append((connections[cid], stamp, payload))
            else:
                damage = damage or f"unexpected record type {op} inside a chunk"
                break
        except (ReaderError, ValueError):
            damage = damage or "corrupt record inside a chunk"
            break
    if not chunk.counts:
        chunk.start_ns = chunk.end_ns = 0
    return chunk, damage


# --- messages ---------------------------------------------------------------------------


def iter_raw(
    path: str | os.PathLike[str], topics: Iterable[str] | None = None
) -> Iterator[tuple[BagConnection, int, bytes]]:
    """Yield ``(connection, stamp_ns, serialized bytes)`` in time order.

    A damaged bag yields the messages before the damage.
    """
    path = Path(path)
    wanted = set(topics) if topics else None
    summary = summarize(path)
    if summary.indexed:
        with _RosbagsReader(path) as reader:
            conns = [c for c in reader.connections if wanted is None or c.topic in wanted]
            if not conns:
                return
            for conn, stamp, data in reader.messages(connections=conns):
                yield summary.connections[conn.id], stamp, data
        return
    _, messages = _scan(path, want_messages=True)
    messages.sort(key=lambda m: m[1])
    for stored, stamp, data in messages:
        if wanted is None or stored.topic in wanted:
            yield stored, stamp, data


def read_messages(
    path: str | os.PathLike[str], topics: Iterable[str] | None = None, *, raw: bool = False
) -> Iterator[BagMessage]:
    """Iterate a bag's messages as :class:`BagMessage` ``(topic, time, msg, ...)``.

    Args:
        path: The ``.bag`` file (a ``.bag.active`` one is read as far as it goes).
        topics: Only these topics; None for all.
        raw: Give the serialized bytes instead of message objects.
    """
    from workbench.bag.types import decode

    for conn, stamp, data in iter_raw(path, topics):
        msg = data if raw else decode(conn, data)
        yield BagMessage(conn.topic, stamp / 1e9, msg, conn.typename, stamp)
