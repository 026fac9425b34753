"""Writing ROS 1 bags (v2.0) with rosbags' writer.

Like ``rosbag record``, the file is written as ``NAME.bag.active`` and
renamed to ``NAME.bag`` when it is closed cleanly, so a half-written bag is
never mistaken for a finished one (and can still be read, see
:mod:`workbench.bag.reader`).
"""

from __future__ import annotations

import datetime
import os
import time
from pathlib import Path
from typing import Any

from rosbags.rosbag1 import Writer as _RosbagsWriter
from rosbags.rosbag1.writer import WriterError

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


class BagWriter:
    """Write messages to a ROS 1 bag.

    Args:
        path: The finished bag's path (``.bag`` is added if missing).
        compression: ``none`` (default), ``bz2`` or ``lz4`` chunks.
        chunk_size: Bytes per chunk before it is written out (rosbag uses 768 KiB).

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
        self.compression = compression
        self.chunk_size = chunk_size
        self.counts: dict[str, int] = {}
        self._writer: _RosbagsWriter | None = None
        self._connections: dict[tuple[str, str], Any] = {}

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
        if self.active_path.exists():
            self.active_path.unlink()
        writer = _RosbagsWriter(self.active_path)
        if self.compression != "none":
            writer.set_compression(_RosbagsWriter.CompressionFormat[self.compression.upper()])
            if self.compression == "lz4":
                writer.compressor = roslz4_frame
        writer.chunk_threshold = self.chunk_size
        try:
            writer.open()
        except (OSError, WriterError) as error:
            reason = getattr(error, "strerror", None) or str(error)
            raise BagWriteError(
                f"cannot record: {reason}", path=self.path, hint="choose a writable directory"
            ) from None
        self._writer = writer
        return self

    def close(self) -> Path:
        """Write the index and rename ``.bag.active`` to ``.bag``; returns the path."""
        if self._writer is None:
            return self.path
        writer, self._writer = self._writer, None
        try:
            writer.close()
            os.replace(self.active_path, self.path)
        except OSError as error:
            raise BagWriteError(
                f"cannot finish the bag: {error.strerror or error}",
                path=self.active_path,
                hint="the messages written so far are in the .active file",
            ) from None
        return self.path

    def __enter__(self) -> BagWriter:
        return self.open() if self._writer is None else self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def is_open(self) -> bool:
        return self._writer is not None

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
    ) -> Any:
        """Declare ``topic`` with ``typename`` (md5sum/definition looked up when omitted)."""
        key = (topic, typename)
        if key in self._connections:
            return self._connections[key]
        if self._writer is None:
            self.open()
        assert self._writer is not None
        if md5sum is None or definition is None:
            from workbench.bag.types import type_info

            md5sum, definition = type_info(typename)
        pkg, _, name = typename.rpartition("/")
        conn = self._writer.add_connection(
            topic,
            typename if "/msg/" in typename else f"{pkg}/msg/{name}",
            msgdef=definition,
            md5sum=md5sum,
            callerid=callerid,
            latching=1 if latching else None,
        )
        self._connections[key] = conn
        return conn

    def write(
        self,
        topic: str,
        msg: Any = None,
        t: Any = None,
        *,
        typename: str | None = None,
        data: bytes | None = None,
    ) -> None:
        """Append one message.

        Args:
            topic: Topic name.
            msg: A ``workbench.msgs`` message (or None when ``data`` is given).
            t: Receive time: float seconds, int nanoseconds or a Time; None is now.
            typename: Needed with ``data``; defaults to ``msg._type``.
            data: Already serialized ROS 1 bytes.
        """
        if typename is None:
            if msg is None:
                raise BagWriteError(f"no message and no type for topic {topic}")
            typename = msg._type
        conn = self.add_connection(topic, typename)
        if data is None:
            from workbench.msgs import serialize

            data = serialize(msg)
        assert self._writer is not None
        try:
            self._writer.write(conn, to_ns(t), data)
        except OSError as error:
            raise BagWriteError(
                f"cannot write to the bag: {error.strerror or error}", path=self.active_path
            ) from None
        self.counts[topic] = self.counts.get(topic, 0) + 1
