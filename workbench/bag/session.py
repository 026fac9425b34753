"""``bag record`` and ``bag play`` as command-line sessions on the default bus."""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from workbench.bag.errors import BagError, warnings_as_lines
from workbench.bag.writer import default_bag_name
from workbench.errors import MessageError
from workbench.limits import MAX_OPTION_SECONDS


def _playable(summary: Any, topics: Sequence[str] | None) -> set[str]:
    """The topics of the bag that can be published: types workbench knows, as recorded.

    Others (a type workbench lacks, a definition that differs from workbench's) are
    left out with a ``[WARN]`` line each, as they cannot be published from this process.
    """
    from workbench import msgs

    playable: set[str] = set()
    refused: dict[str, str] = {}
    for conn in summary.connections.values():
        if topics and conn.topic not in topics:
            continue
        try:
            md5 = msgs.md5sum(conn.typename)
        except MessageError:
            refused[conn.topic] = f"its type {conn.typename} is not one workbench knows"
            continue
        if md5 != conn.md5sum:
            refused[conn.topic] = (
                f"it was recorded as {conn.typename} with md5sum {conn.md5sum[:32]}, but "
                f"workbench's {conn.typename} has {md5}"
            )
            continue
        playable.add(conn.topic)
    for topic, reason in sorted(refused.items()):
        if topic not in playable:
            print(f"[WARN] not playing {topic}: {reason}", file=sys.stderr, flush=True)
    if refused and not playable:
        raise BagError("none of the bag's topics can be played", hint="see the warnings above")
    return playable


def output_path(output_name: str | None = None, output_prefix: str | None = None) -> Path:
    """rosbag's naming: ``-O NAME`` as given (``.bag`` added), else a dated name with ``-o PREFIX``."""
    if output_name:
        name = output_name
        return Path(name if name.endswith(".bag") else name + ".bag")
    prefix = output_prefix or ""
    directory = ""
    if prefix and (prefix.endswith("/") or os.path.isdir(prefix)):
        directory, prefix = prefix, ""
    return Path(directory) / default_bag_name(prefix)


def record(
    topics: Sequence[str] = (),
    *,
    all_topics: bool = False,
    output_name: str | None = None,
    output_prefix: str | None = None,
    exclude: str | None = None,
    duration: float | None = None,
    limit: int | None = None,
    compression: str = "none",
) -> int:
    """Record until interrupted, ``duration`` or ``limit``; prints rosbag's lines.

    Ctrl-C, SIGINT or SIGTERM (a KeyboardInterrupt from the command line) end the
    recording: the bag is closed (``NAME.bag.active`` renamed to ``NAME.bag``, index
    written) before the interrupt is reported.

    Args:
        topics: Topic names to record.
        all_topics: Record every published topic (``-a``).
        output_name: The bag's name (``-O``); ``.bag`` is added.
        output_prefix: Prefix of a dated name (``-o``).
        exclude: Regular expression of topics not to record (``-x``).
        duration: Stop after this many seconds.
        limit: Stop after this many messages on each topic.
        compression: ``none``, ``bz2`` or ``lz4``.

    Raises:
        BagError: Nothing to record, or a bad duration or limit.
    """
    from workbench.bag.record import Recorder
    from workbench.bus import Node

    if not all_topics and not topics:
        raise BagError("nothing to record", hint="give topic names or -a for all topics")
    if duration is not None and not duration > 0:
        raise BagError(f"--duration must be positive, got {duration:g}")
    if duration is not None and not duration <= MAX_OPTION_SECONDS:
        raise BagError(f"--duration must be at most {MAX_OPTION_SECONDS:,.0f} s, got {duration:g}")
    if limit is not None and limit < 1:
        raise BagError(f"--limit must be at least 1, got {limit}")
    path = output_path(output_name, output_prefix)
    node = Node("record", anonymous=True)
    try:
        recorder = Recorder(
            node,
            path,
            topics=topics,
            all_topics=all_topics,
            exclude=exclude,
            compression=compression,
        )
    except BaseException:
        node.shutdown()
        raise
    print(f"[ INFO] [{time.time():.9f}]: Recording to '{recorder.path}'.", flush=True)
    announced: set[str] = set()
    start = time.monotonic()
    try:
        while True:
            for topic in recorder.poll_topics():
                if topic not in announced:
                    announced.add(topic)
                    print(f"[ INFO] [{time.time():.9f}]: Subscribing to {topic}", flush=True)
            node.bus.spin_once(timeout=0.05)
            if duration is not None and time.monotonic() - start >= duration:
                break
            if (
                limit is not None
                and recorder.counts
                and all(n >= limit for n in recorder.counts.values())
            ):
                break
    except KeyboardInterrupt:
        pass
    finally:
        try:
            _drain(node)
        finally:
            written = recorder.close()
            node.shutdown()
    print(f"[ INFO] [{time.time():.9f}]: Closing '{written}'.", flush=True)
    return 0


def _remaps(words: list[str]) -> dict[str, str]:
    """``from:=to`` arguments (rosbag play's topic remapping)."""
    out = {}
    for word in words:
        source, sep, target = word.partition(":=")
        if not sep or not source or not target:
            raise BagError(f"cannot read remapping {word!r}", hint="write it as /from:=/to")
        out[source if source.startswith("/") else "/" + source] = (
            target if target.startswith("/") else "/" + target
        )
    return out


def _drain(node: Any) -> None:
    """Run the callbacks of messages already received, so none is lost at the end."""
    bus = node.bus
    for _ in range(1000):
        if not bus.spin_once(timeout=0.0):
            break


#: Bounds of ``bag play``'s options: a rate of 1e-300 would wait forever between two
#: messages, a start of 1e308 s overflows a ROS time (at most 2^32 s).
MIN_RATE, MAX_RATE = 1e-3, 1e6
MAX_DELAY = 86_400.0
MAX_START = float(2**32)


def check_play_options(rate: float, delay: float, start: float) -> None:
    """Refuse ``-r``, ``-d`` and ``-s`` values that are not finite or out of their bounds.

    Raises:
        BagError: The first bad value, naming the option and its bound.
    """
    if not MIN_RATE <= rate <= MAX_RATE:  # NaN fails every comparison
        raise BagError(
            f"--rate must be a speed factor from {MIN_RATE:g} to {MAX_RATE:g}, got {rate:g}",
            hint="use -r 0.5 for half speed",
        )
    if not 0 <= delay <= MAX_DELAY:
        raise BagError(f"--delay must be 0 to {MAX_DELAY:,.0f} seconds, got {delay:g}")
    if not 0 <= start <= MAX_START:
        raise BagError(f"--start must be 0 to {MAX_START:,.0f} seconds into the bag, got {start:g}")


def play(
    bag: str,
    *,
    remaps: Sequence[str] = (),
    rate: float = 1.0,
    delay: float = 0.2,
    start: float = 0.0,
    loop: bool = False,
    clock: bool = False,
    topics: Sequence[str] | None = None,
    quiet: bool = False,
) -> int:
    """Publish a bag with its timing; prints rosbag play's opening lines and progress.

    Args:
        bag: The bag file.
        remaps: ``/from:=/to`` topic renamings.
        rate: Speed factor.
        delay: Seconds to wait after advertising, before publishing.
        start: Seconds into the bag to start at.
        loop: Start over at the end, until interrupted.
        clock: Publish the bag time on ``/clock``.
        topics: Only these topics (default: all).
        quiet: No progress line (also when stdout is not a terminal).

    Raises:
        BagError: A bad remapping, rate, delay or start, or an unreadable bag.
    """
    from workbench.bag.play import play as play_bag
    from workbench.bag.reader import summarize
    from workbench.bus import Node
    from workbench.msgs import get_type

    check_play_options(rate, delay, start)
    renamed = _remaps(list(remaps))
    summary = summarize(bag)  # its damage is reported once, as the playback reads it
    playable = _playable(summary, topics)
    if not playable and summary.connections:
        recorded = sorted({conn.topic for conn in summary.connections.values()})
        shown = ", ".join(recorded[:10]) + (" ..." if len(recorded) > 10 else "")
        raise BagError(
            "nothing to play: "
            + (
                "no topic given with --topics is in the bag"
                if topics
                else "workbench knows none of the bag's message types"
            ),
            path=bag,
            hint=f"the bag's topics: {shown}",
        )
    node = Node("play", anonymous=True)
    publishers: dict[str, Any] = {}
    for conn in summary.connections.values():
        if conn.topic in playable and conn.topic not in publishers:
            publishers[conn.topic] = node.create_publisher(
                renamed.get(conn.topic, conn.topic),
                get_type(conn.typename),
                queue_size=1000,
                latch=conn.latching,
            )
            publishers[conn.topic].number_headers = False  # rosbag play keeps the recorded seq
    clock_pub = None
    if clock:
        clock_pub = node.create_publisher("/clock", get_type("rosgraph_msgs/Clock"), queue_size=10)
    print(f"[ INFO] [{time.time():.9f}]: Opening {bag}", flush=True)
    print(f"\nWaiting {delay:g} seconds after advertising topics...", end="", flush=True)
    start_ns, end_ns = summary.start_ns, summary.end_ns
    total = (end_ns - start_ns) / 1e9 if start_ns is not None and end_ns is not None else 0.0
    quiet = quiet or not sys.stdout.isatty()
    state = {"delay_done": False}

    def publish(topic: str, typename: str, msg: Any) -> None:
        if not state["delay_done"]:
            print(" done.", flush=True)
            state["delay_done"] = True
        publishers[topic].publish(msg)
        node.bus.spin_once(timeout=0.0)

    def publish_clock(ns: int) -> None:
        from workbench.msgs import Time

        if clock_pub is not None:
            clock_pub.publish(get_type("rosgraph_msgs/Clock")(clock=Time(ns // 10**9, ns % 10**9)))

    def progress(bag_time: float, elapsed: float) -> None:
        if not quiet:
            print(
                f"\r [RUNNING]  Bag Time: {bag_time:13.6f}   Duration: {elapsed:.6f} / {total:.6f}     ",
                end="",
                flush=True,
            )

    try:
        with warnings_as_lines():
            report = play_bag(
                bag,
                publish,
                rate=rate,
                delay=delay,
                loop=loop,
                clock=publish_clock if clock_pub is not None else None,
                start=start,
                topics=sorted(playable),
                progress=progress,
            )
        if not state["delay_done"]:
            print(" done.", flush=True)
        print(f"\nDone. Published {report.published} messages.", flush=True)
    except KeyboardInterrupt:
        print("", flush=True)
    finally:
        _drain(node)
        node.shutdown()
    return 0
