"""``rosbag info``'s text layout for a :class:`~workbench.bag.reader.BagSummary`.

The rows, their alignment, the duration/size/time formats and the
``N msgs    : type`` topic lines follow rosbag's ``Bag.__str__`` (ROS Noetic,
``rosbag/bag.py``) as printed without ``--freq``. Times are local time, as
rosbag prints them.
"""

from __future__ import annotations

import time

from workbench.bag.reader import BagSummary


def human_size(size: float) -> str:
    """rosbag's size: always in KB or larger, one decimal (1024-based)."""
    for suffix in ("KB", "MB", "GB", "TB", "PB", "EB"):
        size /= 1024.0
        if size < 1024.0:
            return f"{size:.1f} {suffix}"
    return "-"


def _time_to_str(secs: float) -> str:
    frac = f"{secs - int(secs):.2f}"[1:]
    return time.strftime("%b %d %Y %H:%M:%S", time.localtime(secs)) + frac


def _duration_to_str(duration: float) -> str:
    secs = duration % 60
    mins = int(duration / 60)
    hours = int(mins / 60)
    if hours > 0:
        return f"{hours}hr {mins % 60}:{int(secs):02d}s ({int(duration)}s)"
    if mins > 0:
        return f"{mins}:{int(secs):02d}s ({int(duration)}s)"
    return f"{duration:.1f}s"


def format_info(summary: BagSummary, *, name: str | None = None) -> str:
    """The ``bag info`` text (no trailing newline).

    Args:
        summary: From :func:`workbench.bag.reader.summarize`.
        name: The path as the user typed it (defaults to the summary's path).
    """
    rows: list[tuple[str, str]] = [("path", name or str(summary.path))]
    rows.append(("version", "2.0" if summary.indexed else "2.0 (unindexed, recovered)"))
    start_ns, end_ns = summary.start_ns, summary.end_ns
    if start_ns is None or end_ns is None:
        rows.append(("size", human_size(summary.size)))  # all rosbag shows of an empty bag
    else:
        start, end = start_ns / 1e9, end_ns / 1e9
        rows.append(("duration", _duration_to_str(end - start)))
        rows.append(("start", f"{_time_to_str(start)} ({start:.2f})"))
        rows.append(("end", f"{_time_to_str(end)} ({end:.2f})"))
        rows.append(("size", human_size(summary.size)))
        rows.append(("messages", str(summary.message_count)))
        rows.append(("compression", _compression(summary)))
        types: dict[str, str] = {}
        for conn in summary.connections.values():
            types.setdefault(conn.typename, conn.md5sum)
        width = max(len(t) for t in types)
        for i, typename in enumerate(sorted(types)):
            rows.append(("types" if i == 0 else "", f"{typename:<{width}} [{types[typename]}]"))
        counts = summary.topic_counts()
        topic_types = summary.topic_types()
        conns_per_topic: dict[str, int] = {}
        for conn in summary.connections.values():
            conns_per_topic[conn.topic] = conns_per_topic.get(conn.topic, 0) + 1
        topic_width = max(len(t) for t in counts)
        count_width = max(len(str(n)) for n in counts.values())
        for i, topic in enumerate(counts):
            n = counts[topic]
            line = f"{topic:<{topic_width}}   {n:>{count_width}} {'msgs' if n > 1 else 'msg '}   "
            line += f" : {topic_types[topic]:<{width}}"
            if conns_per_topic[topic] > 1:
                line += f" ({conns_per_topic[topic]} connections)"
            rows.append(("topics" if i == 0 else "", line.rstrip()))
    for i, text in enumerate(summary.warnings):
        rows.append(("warning" if i == 0 else "", f"recovered what was readable: {text}"))
    if not summary.warnings and not summary.indexed:
        rows.append(("warning", "recovered what was readable: the bag has no index"))
    first = max(len(field) for field, _ in rows) + 1
    lines = [f"{(field + ':') if field else '':<{first}} {value}" for field, value in rows]
    return "\n".join(lines).rstrip()


def _compression(summary: BagSummary) -> str:
    if not summary.chunks:
        return "none"
    counts: dict[str, int] = {}
    raw: dict[str, int] = {}
    packed: dict[str, int] = {}
    for chunk in summary.chunks:
        counts[chunk.compression] = counts.get(chunk.compression, 0) + 1
        raw[chunk.compression] = raw.get(chunk.compression, 0) + chunk.uncompressed_size
        packed[chunk.compression] = packed.get(chunk.compression, 0) + chunk.compressed_size
    total = len(summary.chunks)
    parts = []
    for count, kind in sorted(((v, k) for k, v in counts.items()), reverse=True):
        if kind == "none":
            parts.append(f"{kind} [{count}/{total} chunks]")
        else:
            fraction = 100.0 * packed[kind] / max(raw[kind], 1)
            parts.append(f"{kind} [{count}/{total} chunks; {fraction:.2f}%]")
    return ", ".join(parts)
