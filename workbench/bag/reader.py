"""Reading ROS 1 bags (v2.0): summary, messages, and recovery of damaged files.

A bag is read through its index when the index can be trusted, else by walking
its records from the start (a ``.bag.active`` left by a recorder that was
killed, a file cut short by a full disk, a damaged index), as ``rosbag
reindex`` does (:mod:`workbench.bag.layout`). A damaged chunk -- bytes that do
not decompress, a record that runs past its end -- is skipped with a
:class:`BagWarning` naming its byte offset, and every message that can be read
is returned, in time order. A message whose bytes do not decode is skipped the
same way. Nothing else than :class:`~workbench.errors.BagError` is raised, and
only when nothing at all can be read.

Times are nanoseconds since the epoch (``int``) in the raw API and seconds
(``float``) in :class:`BagMessage`.
"""

from __future__ import annotations

import heapq
import itertools
import os
import warnings
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from workbench.bag.errors import BagDamagedError, BagFormatError, BagNotFoundError, BagWarning
from workbench.bag.layout import Chunk, Connection, chunk_records, read_index, walk
from workbench.bag.records import MAGIC, Corrupt
from workbench.limits import check_regular_file

#: A connection record: a topic with its type as the recorder saw it.
BagConnection = Connection
#: One chunk: position, compression, sizes (bytes), time span (ns), counts per connection.
ChunkSummary = Chunk


@dataclass
class BagSummary:
    """What ``rosbag info`` shows, plus how the bag was read.

    Attributes:
        path: The file.
        size: File size in bytes.
        connections: By connection id.
        chunks: In file order (the readable ones).
        indexed: True when read through the index; False when recovered by a walk.
        damage: What was wrong, joined (None for an intact indexed bag; "no index" for
            an intact bag without one).
        warnings: What was skipped, one text each, naming byte offsets.
    """

    path: Path
    size: int
    connections: dict[int, Connection]
    chunks: list[Chunk]
    indexed: bool = True
    damage: str | None = None
    warnings: list[str] = field(default_factory=list)

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
    check_regular_file(path, "bag", BagFormatError)
    with path.open("rb") as f:
        magic = f.read(len(MAGIC))
    if not magic:
        raise BagDamagedError("bag file is empty", path=path, hint="nothing was recorded")
    if magic.startswith(b"#ROSBAG V") and magic != MAGIC:
        version = magic[9:].split(b"\n")[0].decode(errors="replace")
        raise BagFormatError(
            f"bag version {version} is not supported (only 2.0)",
            path=path,
            hint="migrate it with 'rosbag fix' on a ROS machine",
        )
    if magic != MAGIC:
        raise BagFormatError("not a ROS bag (no '#ROSBAG V2.0' magic)", path=path)


def summarize(path: str | os.PathLike[str]) -> BagSummary:
    """Read a bag's summary; a damaged bag is walked and its readable part summarized.

    Raises:
        BagNotFoundError: no such file.
        BagFormatError: not a v2.0 bag (or not a regular file).
        BagDamagedError: nothing at all could be read.
    """
    path = Path(path)
    _check_file(path)
    with path.open("rb") as stream:
        size = os.fstat(stream.fileno()).st_size
        try:
            layout = read_index(stream, size)
        except Corrupt as error:
            try:
                layout = walk(stream, size)
            except Corrupt as header_error:
                raise BagDamagedError(
                    f"bag header is unreadable ({header_error.reason})",
                    path=path,
                    hint="the file is not a usable bag",
                ) from None
            if error.reason != "the bag has no index":
                layout.warnings.insert(
                    0, f"the index is damaged ({error.reason}); read the records one by one"
                )
    if not layout.connections and not any(c.counts for c in layout.chunks) and layout.warnings:
        raise BagDamagedError(f"no readable messages: {layout.warnings[0]}", path=path)
    damage = "; ".join(layout.warnings) or (None if layout.indexed else "no index")
    return BagSummary(
        path, size, layout.connections, layout.chunks, layout.indexed, damage, layout.warnings
    )


# --- messages ---------------------------------------------------------------------------


class _Reporter:
    """Issues each damage warning of one read once, as a :class:`BagWarning`."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.seen: set[str] = set()

    def __call__(self, texts: Iterable[str]) -> None:
        for text in texts:
            if text not in self.seen:
                self.seen.add(text)
                warnings.warn(BagWarning(f"{self.path}: {text}"), stacklevel=4)


def iter_raw(
    path: str | os.PathLike[str], topics: Iterable[str] | None = None
) -> Iterator[tuple[Connection, int, bytes]]:
    """Yield ``(connection, stamp_ns, serialized bytes)`` in time order.

    Damaged chunks are skipped with a :class:`BagWarning`; everything readable is yielded.
    """
    path = Path(path)
    wanted = set(topics) if topics else None
    summary = summarize(path)
    report = _Reporter(path)
    report(summary.warnings)
    connections = dict(summary.connections)

    def useful(chunk: Chunk) -> bool:
        ids = chunk.counts.keys()
        return bool(ids) and (
            wanted is None or any(connections[c].topic in wanted for c in ids if c in connections)
        )

    pending = sorted((c for c in summary.chunks if useful(c)), key=lambda c: (c.start_ns, c.pos))
    heap: list[tuple[int, int, Connection, bytes]] = []
    order = itertools.count()
    found: list[str] = []
    with path.open("rb") as stream:
        index = 0
        while index < len(pending) or heap:
            # load every chunk that may hold a message earlier than the earliest one loaded
            while index < len(pending) and (not heap or pending[index].start_ns <= heap[0][0]):
                for item in chunk_records(stream, summary.size, pending[index], connections, found):
                    if isinstance(item, tuple) and (wanted is None or item[0].topic in wanted):
                        heapq.heappush(heap, (item[1], next(order), item[0], item[2]))
                report(found)
                index += 1
            if heap:
                stamp, _, conn, data = heapq.heappop(heap)
                yield conn, stamp, data


def read_messages(
    path: str | os.PathLike[str], topics: Iterable[str] | None = None, *, raw: bool = False
) -> Iterator[BagMessage]:
    """Iterate a bag's messages as :class:`BagMessage` ``(topic, time, msg, ...)``.

    Messages of damaged chunks, and messages whose bytes do not decode as their type,
    are skipped with a :class:`BagWarning`.

    Args:
        path: The ``.bag`` file (a ``.bag.active`` one is read as far as it goes).
        topics: Only these topics; None for all.
        raw: Give the serialized bytes instead of message objects.
    """
    from workbench.bag.types import decode

    skipped: dict[int, int] = {}
    for conn, stamp, data in iter_raw(path, topics):
        if raw:
            yield BagMessage(conn.topic, stamp / 1e9, data, conn.typename, stamp)
            continue
        try:
            msg = decode(conn, data)
        except Exception as error:  # damaged bytes: each deserializer raises its own types
            skipped[conn.id] = skipped.get(conn.id, 0) + 1
            if skipped[conn.id] == 1:
                reason = " ".join(f"{type(error).__name__}: {error}".split())[:120]
                warnings.warn(
                    BagWarning(
                        f"{path}: skipped a message on {conn.topic} at {stamp / 1e9:.3f} s that "
                        f"does not decode as {conn.typename} ({reason}); later ones like it "
                        "are skipped without a warning"
                    ),
                    stacklevel=2,
                )
            continue
        yield BagMessage(conn.topic, stamp / 1e9, msg, conn.typename, stamp)
