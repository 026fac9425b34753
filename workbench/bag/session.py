"""``bag record`` and ``bag play`` as command-line sessions on the default bus."""

from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
import time
from pathlib import Path
from typing import Any

from workbench.bag.errors import BagError
from workbench.bag.writer import default_bag_name


def _install_sigterm() -> None:
    # SIGTERM ends a recording as cleanly as Ctrl-C does (rosbag record on roslaunch shutdown)
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))


def output_path(args: argparse.Namespace) -> Path:
    """rosbag's naming: ``-O NAME`` as given (``.bag`` added), else a dated name with ``-o PREFIX``."""
    if args.output_name:
        name = args.output_name
        return Path(name if name.endswith(".bag") else name + ".bag")
    prefix = args.output_prefix or ""
    directory = ""
    if prefix and (prefix.endswith("/") or os.path.isdir(prefix)):
        directory, prefix = prefix, ""
    return Path(directory) / default_bag_name(prefix)


def record(args: argparse.Namespace) -> int:
    """Record until Ctrl-C, ``--duration`` or ``--limit``; prints rosbag's lines."""
    from workbench.bag.record import Recorder
    from workbench.bus import Node

    if not args.all and not args.topics:
        raise BagError("nothing to record", hint="give topic names or -a for all topics")
    compression = "bz2" if args.bz2 else "lz4" if args.lz4 else "none"
    path = output_path(args)
    node = Node("record", anonymous=True)
    recorder = Recorder(
        node,
        path,
        topics=args.topics,
        all_topics=args.all,
        exclude=args.exclude,
        compression=compression,
    )
    _install_sigterm()
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
            if args.duration is not None and time.monotonic() - start >= args.duration:
                break
            if (
                args.limit is not None
                and recorder.counts
                and all(n >= args.limit for n in recorder.counts.values())
            ):
                break
    except KeyboardInterrupt:
        pass
    finally:
        _drain(node)
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


def play(args: argparse.Namespace) -> int:
    """Publish a bag with its timing; prints rosbag play's opening lines and progress."""
    from workbench.bag.play import play as play_bag
    from workbench.bag.reader import summarize
    from workbench.bus import Node
    from workbench.msgs import get_type

    summary = summarize(args.bag)
    remaps = _remaps(getattr(args, "remaps", None) or [])
    node = Node("play", anonymous=True)
    publishers: dict[str, Any] = {}
    for conn in summary.connections.values():
        if args.topics and conn.topic not in args.topics:
            continue
        if conn.topic not in publishers:
            publishers[conn.topic] = node.create_publisher(
                remaps.get(conn.topic, conn.topic),
                get_type(conn.typename),
                queue_size=1000,
                latch=conn.latching,
            )
    clock_pub = None
    if args.clock:
        clock_pub = node.create_publisher("/clock", get_type("rosgraph_msgs/Clock"), queue_size=10)
    print(f"[ INFO] [{time.time():.9f}]: Opening {args.bag}", flush=True)
    print(f"\nWaiting {args.delay:g} seconds after advertising topics...", end="", flush=True)
    _install_sigterm()
    total = (summary.end_ns - summary.start_ns) / 1e9 if summary.start_ns is not None else 0.0
    quiet = args.quiet or not sys.stdout.isatty()
    state = {"delay_done": False}

    def publish(topic: str, typename: str, msg: Any) -> None:
        if not state["delay_done"]:
            print(" done.", flush=True)
            state["delay_done"] = True
        publishers[topic].publish(msg)
        node.bus.spin_once(timeout=0.0)

    def clock(ns: int) -> None:
        from workbench.msgs import Time

        clock_pub.publish(get_type("rosgraph_msgs/Clock")(clock=Time(ns // 10**9, ns % 10**9)))

    def progress(bag_time: float, elapsed: float) -> None:
        if not quiet:
            print(
                f"\r [RUNNING]  Bag Time: {bag_time:13.6f}   Duration: {elapsed:.6f} / {total:.6f}     ",
                end="",
                flush=True,
            )

    try:
        report = play_bag(
            args.bag,
            publish,
            rate=args.rate,
            delay=args.delay,
            loop=args.loop,
            clock=clock if clock_pub is not None else None,
            start=args.start,
            topics=args.topics,
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
