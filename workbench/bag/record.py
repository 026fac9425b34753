"""Recording bus topics into a bag (``rosbag record``).

The recorder subscribes with a deep queue and writes every message it
receives, stamped with its receive time on the node's clock. It subscribes
in the bus's raw mode: messages from other processes go into the bag as the
bytes that arrived, never decoded and encoded again. With ``all_topics`` it
keeps looking for new topics while it runs, as ``rosbag record -a`` does.

As rosbag, it stores one connection per topic and publisher, with the
publisher's name (``callerid``) and ``latching=1`` for a latched publisher,
and writes a connection only with its first message (a topic that stays
silent leaves no trace). A background thread writes the open chunk out once
its oldest message is :data:`CHUNK_SECONDS` old, so a recorder killed outright
(SIGKILL, power cut of the process) loses at most about that much.
"""

from __future__ import annotations

import os
import re
import sys
import threading
import time
from collections.abc import Iterable
from typing import Any

from workbench.bag.writer import BagWriter

QUEUE_SIZE = 0  # unbounded: the recorder must not drop messages

#: Wall-clock seconds of messages a recorder keeps in memory at most before writing them out.
CHUNK_SECONDS = 1.0

#: How often (seconds) the recorder's flusher thread looks for a chunk to write out.
FLUSH_PERIOD = 0.05


class Recorder:
    """Subscribe to topics on a bus node and write what arrives into a bag.

    Args:
        node: A ``workbench.bus.Node`` to subscribe with.
        path: The bag to write (``NAME.bag``; ``NAME.bag.active`` while recording).
        topics: Topic names to record.
        all_topics: Record every published topic, including ones that appear later.
        exclude: A regular expression of topics not to record (``-x``).
        compression: ``none``, ``bz2`` or ``lz4``.
    """

    def __init__(
        self,
        node: Any,
        path: str | os.PathLike[str],
        *,
        topics: Iterable[str] = (),
        all_topics: bool = False,
        exclude: str | None = None,
        compression: str = "none",
    ) -> None:
        self.node = node
        self.writer = BagWriter(path, compression=compression, chunk_seconds=CHUNK_SECONDS)
        self.all_topics = all_topics
        self.exclude = re.compile(exclude) if exclude else None
        self._wanted = [node.resolve_name(t) for t in topics]
        self._subscriptions: dict[str, Any] = {}
        self.received = 0
        self._lock = threading.Lock()
        self.writer.open()
        self.error: BaseException | None = None  # why the flusher thread stopped, if it failed
        self._stop = threading.Event()
        self._flusher = threading.Thread(
            target=self._flush_periodically, name=f"bag flusher {self.writer.path}", daemon=True
        )
        self._flusher.start()

    @property
    def path(self):
        return self.writer.path

    @property
    def counts(self) -> dict[str, int]:
        return dict(self.writer.counts)

    def poll_topics(self) -> list[str]:
        """Subscribe to wanted topics that now have a publisher; returns the new ones."""
        from workbench.msgs import get_type

        published = _published_topics(self.node)
        names = published if self.all_topics else [t for t in self._wanted if t in published]
        new = []
        for topic in names:
            if topic in self._subscriptions or (self.exclude and self.exclude.search(topic)):
                continue
            typename = published[topic]
            cls = get_type(typename)
            self._subscriptions[topic] = self.node.create_subscription(
                topic,
                cls,
                self._callback,
                queue_size=QUEUE_SIZE,
                callback_args=topic,
                raw=True,
                inline=True,  # write where the message arrives: no hand-over to the executor
            )
            new.append(topic)
        return new

    def _callback(self, raw: Any, topic: str) -> None:
        # raw: a workbench.bus.RawMessage (serialized bytes, type, receive time in ns)
        with self._lock:  # callbacks of different topics may run on different threads
            if not self.writer.is_open:  # arrived while the recording was being closed
                return
            self.writer.write(
                topic,
                t=raw.recv_ns,
                typename=raw.type,
                data=raw.data,
                callerid=raw.callerid or self.node.name,
                latching=raw.latching,
            )
            self.received += 1

    def _flush_periodically(self) -> None:
        """Write the open chunk out when due, also while no message arrives."""
        while not self._stop.wait(FLUSH_PERIOD):
            try:
                with self._lock:
                    if not self.writer.is_open:
                        return
                    self.writer.flush_if_due()
            except Exception as error:  # a full disk: say so once; close() reports it again
                self.error = error
                print(f"[ERROR] recording to {self.writer.active_path}: {error}", file=sys.stderr)
                return

    def flush(self, timeout: float = 10.0) -> bool:
        """Wait until every message the subscriptions received has been written.

        Returns:
            Whether everything was written within ``timeout`` seconds.
        """
        bus = self.node.bus
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            arrived = sum(getattr(sub, "received", 0) for sub in self._subscriptions.values())
            if self.received >= arrived:
                return True
            if getattr(bus, "threaded", True):
                time.sleep(0.002)
            else:
                bus.spin_once(0.0)
        return False

    def close(self):
        """Write what is still queued, stop subscribing and finish the bag; returns its path."""
        # The bag is finished (renamed from .bag.active, index written) even when stopping
        # the subscriptions fails or a second interrupt arrives while they stop.
        try:
            self.flush()
            for sub in self._subscriptions.values():
                for name in ("unregister", "shutdown", "destroy"):
                    stop = getattr(sub, name, None)
                    if callable(stop):
                        stop()
                        break
            self._subscriptions.clear()
        finally:
            self._stop.set()
            if self._flusher is not threading.current_thread():
                self._flusher.join(timeout=5.0)
            with self._lock:
                written = self.writer.close()
        return written


def _published_topics(node: Any) -> dict[str, str]:
    """Topic -> type of every topic with at least one publisher (other than ours)."""
    graph = node.bus.graph() if hasattr(node, "bus") else node.graph()
    topics = getattr(graph, "topics", graph.get("topics") if isinstance(graph, dict) else None)
    out: dict[str, str] = {}
    for info in _iter_topics(topics):
        name, typename, publishers = info
        if publishers:
            out[name] = typename
    return out


def _iter_topics(topics: Any):
    if isinstance(topics, dict):
        for name, info in topics.items():
            yield name, _attr(info, "type"), _attr(info, "publishers")
    else:
        for info in topics or ():
            yield _attr(info, "name"), _attr(info, "type"), _attr(info, "publishers")


def _attr(info: Any, name: str) -> Any:
    return info.get(name) if isinstance(info, dict) else getattr(info, name)
