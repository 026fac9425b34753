"""Where a bag's connections and chunks are: from its index, or by walking its records.

An intact bag is read through its index (the connection and chunk-info records
that the bag header's ``index_pos`` points at), checking that every chunk it
names is a chunk record inside the file. A bag without a usable index -- a
``.bag.active`` of a recorder that was killed, a file cut short, a damaged
index -- is walked record by record from the start, as ``rosbag reindex``
does. A damaged record on the way is skipped: the walk looks for the next
chunk record after it, so every chunk that can be read is found.

Damage is reported as text naming the byte offset (``warnings``), never raised,
unless nothing at all can be read.
"""

from __future__ import annotations

import io
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import BinaryIO

from workbench.bag.records import (
    MAGIC,
    MAX_CHUNK_BYTES,
    MAX_RECORD_BYTES,
    OP_BAG_HEADER,
    OP_CHUNK,
    OP_CHUNK_INFO,
    OP_CONNECTION,
    OP_INDEX_DATA,
    OP_MSG_DATA,
    Corrupt,
    Record,
    decompress,
    read_data,
    read_record,
)

#: The bytes every chunk record header holds (the ``op=`` field of a chunk), for resyncing.
_CHUNK_OP_FIELD = b"\x04\x00\x00\x00op=\x05"
#: How far before an ``op=`` field a record may start (its other fields come first), bytes.
_RESYNC_BACK = 256


@dataclass(frozen=True)
class Connection:
    """One connection record: a topic with its type as the recorder saw it."""

    id: int
    topic: str
    typename: str  # ROS 1 style, e.g. "geometry_msgs/Twist"
    md5sum: str
    definition: str
    callerid: str | None = None
    latching: bool = False


@dataclass
class Chunk:
    """One chunk: where it is, compression, sizes in bytes, time span (ns), counts."""

    pos: int
    compression: str
    uncompressed_size: int
    compressed_size: int
    start_ns: int
    end_ns: int
    counts: dict[int, int] = field(default_factory=dict)
    #: Whether ``start_ns``/``end_ns`` agree with the index data records after the chunk; a
    #: message outside them then has a damaged time and is skipped.
    trusted: bool = False


@dataclass
class Layout:
    """What reading the index (or walking the records) found."""

    size: int
    connections: dict[int, Connection]
    chunks: list[Chunk]
    indexed: bool
    warnings: list[str] = field(default_factory=list)


def connection_from(record: Record, stream: BinaryIO) -> Connection:
    """A connection record (its header names the topic; its data holds the type)."""
    from workbench.bag.records import parse_fields

    conn = record.u32("conn")
    topic = record.text("topic")
    data = Record(record.offset, parse_fields(read_data(stream, record), record.offset), 0, 0)
    latching = data.optional_text("latching") or ""
    return Connection(
        conn,
        topic,
        data.text("type"),
        data.text("md5sum"),
        data.optional_text("message_definition") or "",
        data.optional_text("callerid"),
        latching not in ("", "0"),
    )


def bag_header(stream: BinaryIO, size: int) -> tuple[int, int, int, int]:
    """``(index_pos, conn_count, chunk_count, first record offset)`` of the bag header."""
    record = read_record(stream, len(MAGIC), size, MAX_RECORD_BYTES)
    if record.op != OP_BAG_HEADER:
        raise Corrupt("the first record is not a bag header", record.offset)
    return record.u64("index_pos"), record.u32("conn_count"), record.u32("chunk_count"), record.end


def _chunk_at(stream: BinaryIO, pos: int, limit: int) -> tuple[Record, str, int]:
    record = read_record(stream, pos, limit, limit)
    if record.op != OP_CHUNK:
        raise Corrupt(f"record at byte {pos} is not a chunk (op {record.op})", pos)
    return record, record.text("compression"), record.u32("size")


def read_index(stream: BinaryIO, size: int) -> Layout:
    """The layout from the index section.

    Raises:
        Corrupt: No index, or an index that cannot be trusted (then walk the records).
    """
    index_pos, conn_count, chunk_count, first = bag_header(stream, size)
    if index_pos == size and index_pos >= first and conn_count == chunk_count == 0:
        # An empty bag as rosbag closes it: an index of nothing, at the end of the file.
        return Layout(size, {}, [], indexed=True)
    if not first <= index_pos < size:
        raise Corrupt("the bag has no index" if index_pos == 0 else "index_pos is outside", 0)
    connections: dict[int, Connection] = {}
    chunks: list[Chunk] = []
    at = index_pos
    for _ in range(conn_count):
        record = read_record(stream, at, size, MAX_RECORD_BYTES)
        if record.op != OP_CONNECTION:
            raise Corrupt("the index holds fewer connections than the header says", at)
        conn = connection_from(record, stream)
        connections[conn.id] = conn
        at = record.end
    layout = Layout(size, connections, chunks, indexed=True)
    for _ in range(chunk_count):
        record = read_record(stream, at, size, MAX_RECORD_BYTES)
        if record.op != OP_CHUNK_INFO or record.u32("ver") != 1:
            raise Corrupt("the index holds fewer chunk infos than the header says", at)
        at = record.end
        chunk = _chunk_from_info(record, stream, first, index_pos, connections, layout)
        if chunk is not None:
            chunks.append(chunk)
    return layout


def _chunk_from_info(
    info: Record,
    stream: BinaryIO,
    first: int,
    index_pos: int,
    connections: dict[int, Connection],
    layout: Layout,
) -> Chunk | None:
    pos = info.u64("chunk_pos")
    if not first <= pos < index_pos:
        raise Corrupt(f"a chunk info points at byte {pos}, outside the chunks", info.offset)
    data = read_data(stream, info)
    count = info.u32("count")
    if len(data) != 8 * count:
        raise Corrupt("a chunk info's counts do not match its length", info.offset)
    counts = {}
    for k in range(count):
        conn = int.from_bytes(data[8 * k : 8 * k + 4], "little")
        counts[conn] = int.from_bytes(data[8 * k + 4 : 8 * k + 8], "little")
        if conn not in connections:
            raise Corrupt(f"a chunk info counts unknown connection {conn}", info.offset)
    try:
        record, compression, size = _chunk_at(stream, pos, index_pos)
    except Corrupt as error:
        skipped = sum(counts.values())
        layout.warnings.append(
            f"skipped the damaged chunk at byte {pos} ({error.reason}; "
            f"{skipped} message{'s' if skipped != 1 else ''} lost)"
        )
        return None
    start, end = (info.time("start_time"), info.time("end_time")) if count else (0, 0)
    if start > end:
        raise Corrupt(f"the chunk info of the chunk at byte {pos} ends before it starts", pos)
    span = _indexed_span(stream, record.end, index_pos)
    if span is not None and span != (start, end):
        raise Corrupt(
            f"the chunk info of the chunk at byte {pos} gives other times than its messages",
            info.offset,
        )
    return Chunk(pos, compression, size, record.data_length, start, end, counts, span is not None)


def _indexed_span(stream: BinaryIO, at: int, limit: int) -> tuple[int, int] | None:
    """The first and last time of the index data records after a chunk, if they can be read."""
    times: list[int] = []
    try:
        while at < limit:
            record = read_record(stream, at, limit, MAX_RECORD_BYTES)
            if record.op != OP_INDEX_DATA:
                break
            data = read_data(stream, record)
            for k in range(0, len(data) - 11, 12):
                sec = int.from_bytes(data[k : k + 4], "little")
                times.append(sec * 1_000_000_000 + int.from_bytes(data[k + 4 : k + 8], "little"))
            at = record.end
    except Corrupt:
        return None
    return (min(times), max(times)) if times else None


# --- walking the records ------------------------------------------------------------------


def walk(stream: BinaryIO, size: int) -> Layout:
    """The layout found by walking every record from the start (no index needed).

    Raises:
        Corrupt: The bag header itself cannot be read.
    """
    _index_pos, _conns, _chunks, at = bag_header(stream, size)
    layout = Layout(size, {}, [], indexed=False)
    end = size  # the index's own records (connections, chunk infos) are walked over too
    while at < end:
        try:
            record = read_record(stream, at, size, MAX_CHUNK_BYTES, clamp=True)
            op = record.op
            if record.declared_length is not None and op != OP_CHUNK:
                raise Corrupt("record cut short", at)
            if record.declared_length is not None:
                layout.warnings.append(
                    f"the chunk at byte {at} is cut short ({record.data_length} of "
                    f"{record.declared_length} bytes); read what it holds"
                )
            if op == OP_CHUNK:
                layout.chunks.append(_walk_chunk(stream, record, layout))
            elif op == OP_CONNECTION:
                conn = connection_from(record, stream)
                layout.connections.setdefault(conn.id, conn)
            elif op not in (OP_INDEX_DATA, OP_CHUNK_INFO):
                raise Corrupt(f"unexpected record type {op}", at)
            at = record.end
        except Corrupt as error:
            found = next_chunk(stream, error.offset + 1, end)
            lost = f"{found - error.offset} bytes up to the next chunk" if found else "the rest"
            layout.warnings.append(
                f"skipped damage at byte {error.offset} ({error.reason}; {lost})"
            )
            if found is None:
                break
            at = found
    return layout


def _walk_chunk(stream: BinaryIO, record: Record, layout: Layout) -> Chunk:
    """A chunk found by walking: its times and counts come from its messages."""
    compression, size = record.text("compression"), record.u32("size")
    chunk = Chunk(record.offset, compression, size, record.data_length, 0, 0)
    span = _indexed_span(stream, record.end, layout.size)  # the recorder's own account
    if span is not None:
        chunk.start_ns, chunk.end_ns = span
        chunk.trusted = True
    times = []
    for item in chunk_records(stream, layout.size, chunk, layout.connections, layout.warnings):
        if isinstance(item, Connection):
            continue
        conn, stamp, _data = item
        chunk.counts[conn.id] = chunk.counts.get(conn.id, 0) + 1
        times.append(stamp)
    if times and not chunk.trusted:
        chunk.start_ns, chunk.end_ns = min(times), max(times)
    return chunk


def next_chunk(stream: BinaryIO, start: int, end: int) -> int | None:
    """The offset of the next readable chunk record at or after ``start``, or None."""
    block = 1024 * 1024
    at = start
    while at < end:
        stream.seek(at)
        data = stream.read(min(block + len(_CHUNK_OP_FIELD), end - at))
        hit = data.find(_CHUNK_OP_FIELD)
        while hit != -1:
            found = _record_start(stream, at + hit, start, end)
            if found is not None:
                return found
            hit = data.find(_CHUNK_OP_FIELD, hit + 1)
        at += block
    return None


def _record_start(stream: BinaryIO, field_at: int, start: int, end: int) -> int | None:
    """A chunk record holding the ``op`` field at ``field_at``: where it starts, if any."""
    for offset in range(max(start, field_at - _RESYNC_BACK), field_at - 3):
        try:
            record = read_record(stream, offset, end, MAX_CHUNK_BYTES)
            if record.op == OP_CHUNK and offset + 4 <= field_at < record.data_offset:
                record.text("compression")
                record.u32("size")
                return offset
        except Corrupt:
            continue
    return None


# --- inside a chunk -----------------------------------------------------------------------


def chunk_records(
    stream: BinaryIO,
    size: int,
    chunk: Chunk,
    connections: dict[int, Connection],
    warnings: list[str],
) -> Iterator[Connection | tuple[Connection, int, bytes]]:
    """The connections and ``(connection, stamp_ns, data)`` messages of one chunk.

    What is readable is yielded; damage ends the chunk with a warning naming its offset.
    """
    try:
        record = read_record(stream, chunk.pos, size, MAX_CHUNK_BYTES, clamp=True)
        raw = read_data(stream, record)
        data = decompress(chunk.compression, raw, chunk.uncompressed_size, chunk.pos)
    except Corrupt as error:
        warnings.append(f"skipped the damaged chunk at byte {chunk.pos} ({error.reason})")
        return
    inner = io.BytesIO(data)
    at = 0
    unknown: set[int] = set()
    while at < len(data):
        try:
            item = read_record(inner, at, len(data), MAX_CHUNK_BYTES)
            op = item.op
            if op == OP_CONNECTION:
                conn = connection_from(item, inner)
                connections.setdefault(conn.id, conn)
                yield conn
            elif op == OP_MSG_DATA:
                cid = item.u32("conn")
                stamp = item.time("time")
                payload = read_data(inner, item)
                if chunk.trusted and not chunk.start_ns <= stamp <= chunk.end_ns:
                    warnings.append(
                        f"chunk at byte {chunk.pos}: skipped a message whose time ({stamp} ns) "
                        "lies outside the chunk's time span (a damaged time)"
                    )
                elif cid in connections:
                    yield connections[cid], stamp, payload
                elif cid not in unknown:
                    unknown.add(cid)
                    warnings.append(
                        f"chunk at byte {chunk.pos}: skipped messages on unknown connection {cid}"
                    )
            else:
                raise Corrupt(f"unexpected record type {op} inside a chunk", at)
            at = item.end
        except Corrupt as error:
            warnings.append(
                f"skipped the rest of the chunk at byte {chunk.pos} (damage at byte "
                f"{error.offset} of its {len(data)} bytes: {error.reason})"
            )
            return
