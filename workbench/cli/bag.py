"""``workbench bag``: rosbag -- record, info and play ROS 1 bag files."""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from workbench.bag.errors import BagError
from workbench.bag.session import play, record

__all__ = ["compression", "configure", "info", "play", "record", "run"]


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    record = verbs.add_parser(
        "record", help="record topics into a bag (Ctrl-C, SIGINT or SIGTERM stops and closes it)"
    )
    record.add_argument("topics", nargs="*", help="topics to record")
    record.add_argument("-a", "--all", action="store_true", help="record all topics")
    record.add_argument("-O", "--output-name", metavar="NAME", help="bag file name")
    record.add_argument("-o", "--output-prefix", metavar="PREFIX", help="prefix of the dated name")
    record.add_argument("-x", "--exclude", metavar="REGEX", help="topics not to record (with -a)")
    record.add_argument("--duration", type=float, metavar="SECS", help="stop after SECS seconds")
    record.add_argument(
        "-l", "--limit", type=int, metavar="N", help="stop after N messages on each topic"
    )
    record.add_argument("-j", "--bz2", action="store_true", help="compress chunks with bz2")
    record.add_argument("--lz4", action="store_true", help="compress chunks with lz4")
    info = verbs.add_parser("info", help="summarize a bag (rosbag info)")
    info.add_argument("bags", nargs="+", metavar="BAG")
    play = verbs.add_parser("play", help="publish a bag's messages with their original timing")
    play.add_argument("bag", metavar="BAG")
    play.add_argument(
        "remaps", nargs="*", metavar="FROM:=TO", help="publish a topic under another name"
    )
    play.add_argument("-r", "--rate", type=float, default=1.0, help="speed factor (default 1.0)")
    play.add_argument(
        "-d", "--delay", type=float, default=0.2, help="seconds to wait before publishing (0.2)"
    )
    play.add_argument("-s", "--start", type=float, default=0.0, help="start SECS into the bag")
    play.add_argument("-l", "--loop", action="store_true", help="loop playback")
    play.add_argument("--clock", action="store_true", help="publish the bag time on /clock")
    play.add_argument("--topics", nargs="+", metavar="TOPIC", help="only these topics")
    play.add_argument("-q", "--quiet", action="store_true", help="no progress line")


def run(args: argparse.Namespace) -> int:
    if args.verb == "info":
        return info(args.bags)
    if args.verb == "record":
        return record(
            args.topics,
            all_topics=args.all,
            output_name=args.output_name,
            output_prefix=args.output_prefix,
            exclude=args.exclude,
            duration=args.duration,
            limit=args.limit,
            compression=compression(bz2=args.bz2, lz4=args.lz4),
        )
    return play(
        args.bag,
        remaps=args.remaps,
        rate=args.rate,
        delay=args.delay,
        start=args.start,
        loop=args.loop,
        clock=args.clock,
        topics=args.topics,
        quiet=args.quiet,
    )


def compression(*, bz2: bool = False, lz4: bool = False) -> str:
    """The chunk compression of ``-j`` / ``--lz4``.

    Raises:
        BagError: Both were given.
    """
    if bz2 and lz4:
        raise BagError("choose one compression", hint="give -j (bz2) or --lz4, not both")
    return "bz2" if bz2 else "lz4" if lz4 else "none"


def info(bags: Sequence[str]) -> int:
    """Print rosbag info's summary of each bag (separated by a blank line)."""
    from workbench.bag import format_info, summarize

    texts = [format_info(summarize(path), name=path) for path in bags]
    print("\n\n".join(texts))
    return 0
