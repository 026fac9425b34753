"""``workbench topic``: rostopic (list, echo, hz, bw, type, info, pub) and rqt_plot (plot)."""

from __future__ import annotations

import argparse
import contextlib
import sys
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

PUB_USAGE = "workbench topic pub [-1 | -r RATE | -l] TOPIC TYPE [--] [ARGS ...]"
#: Most samples ``topic hz -w`` / ``topic bw -w`` keep.
MAX_WINDOW = 1_000_000


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="list topics in use")
    listing.add_argument("-v", "--verbose", action="store_true", help="types and counts")
    listing.add_argument("-p", dest="publishers", action="store_true", help="only published")
    listing.add_argument("-s", dest="subscribers", action="store_true", help="only subscribed")
    echo = verbs.add_parser("echo", help="print messages (YAML documents separated by ---)")
    echo.add_argument(
        "topic",
        nargs="?",
        help="topic, or topic/field such as /turtle1/pose/x or /tf/transforms[0]",
    )
    echo.add_argument("-b", "--bag", metavar="BAGFILE", help="echo messages from a .bag file")
    echo.add_argument("-a", "--all", action="store_true", help="every message in the bag (with -b)")
    echo.add_argument("-p", dest="plot", action="store_true", help="print CSV rows (plotting)")
    echo.add_argument("-w", dest="width", type=int, metavar="NUM_WIDTH", help="pad numbers")
    echo.add_argument("-n", type=int, metavar="COUNT", help="exit after COUNT messages")
    echo.add_argument("--noarr", action="store_true", help="print array lengths, not contents")
    echo.add_argument("--nostr", action="store_true", help="print string lengths, not contents")
    echo.add_argument(
        "--filter",
        dest="filter_expr",
        metavar="FILTER-EXPRESSION",
        help="Python expression of m (the message) that selects the messages to print",
    )
    echo.add_argument(
        "-c", "--clear", action="store_true", help="clear the screen before each message"
    )
    echo.add_argument("--timeout", type=float, metavar="SECS", help="give up after SECS seconds")
    for verb, text in (("hz", "print the publishing rate"), ("bw", "print the bandwidth used")):
        meter = verbs.add_parser(verb, help=text)
        meter.add_argument("topic")
        meter.add_argument("-w", "--window", type=int, help="samples in the window")
        meter.add_argument("--duration", type=float, metavar="SECS", help="stop after SECS")
    kind = verbs.add_parser("type", help="print a topic's message type")
    kind.add_argument("topic")
    info = verbs.add_parser("info", help="print a topic's type, publishers and subscribers")
    info.add_argument("topic")
    pub = verbs.add_parser(
        "pub",
        help="publish a message built from YAML arguments",
        usage=PUB_USAGE,
        # rostopic's options may come first (pub -r 10 TOPIC ...), which REMAINDER refuses
        # when they start with "-": this verb reads every word itself (parse_pub_words).
        prefix_chars="+",
        add_help=False,
    )
    pub.add_argument("words", nargs=argparse.REMAINDER, help=argparse.SUPPRESS)
    plot = verbs.add_parser("plot", help="plot numeric fields over time (rqt_plot)")
    plot.add_argument("fields", nargs="+", metavar="FIELD", help="e.g. /turtle1/pose/x")
    plot.add_argument("--seconds", type=float, default=10.0, help="how long to record (10)")
    plot.add_argument("--png", metavar="OUT", help="write a PNG instead of showing a window")


def run(args: argparse.Namespace) -> int:
    if args.verb == "list":
        return topic_list(
            verbose=args.verbose, publishers_only=args.publishers, subscribers_only=args.subscribers
        )
    if args.verb == "type":
        return topic_type(args.topic)
    if args.verb == "info":
        return info(args.topic)
    if args.verb == "echo":
        return echo(
            args.topic or "",
            count=args.n,
            noarr=args.noarr,
            nostr=args.nostr,
            width=args.width,
            plot=args.plot,
            bag=args.bag,
            all_topics=args.all,
            filter_expr=args.filter_expr,
            clear=args.clear,
            timeout=args.timeout,
        )
    if args.verb in ("hz", "bw"):
        return meter(args.verb, args.topic, window=args.window, duration=args.duration)
    if args.verb == "plot":
        return plot(args.fields, seconds=args.seconds, png=args.png)
    return pub(args.words)


@contextlib.contextmanager
def _cli_node() -> Iterator[Any]:
    from workbench.introspect.session import cli_node

    node = cli_node("rostopic")
    try:
        yield node
    finally:
        node.shutdown()


def _positive(value: float | None, option: str) -> None:
    from workbench.cli.values import check_seconds
    from workbench.errors import BusError

    if value is not None and not value > 0:
        raise BusError(f"{option} must be positive, got {value:g}")
    check_seconds(value, option, BusError)


def topic_list(
    *, verbose: bool = False, publishers_only: bool = False, subscribers_only: bool = False
) -> int:
    """rostopic list: print the topics in use (with types and counts when ``verbose``)."""
    with _cli_node() as node:
        return _list(node, verbose, publishers_only, subscribers_only)


def topic_type(topic: str) -> int:
    """rostopic type: print a topic's type (and the field path of ``topic/field``)."""
    with _cli_node() as node:
        return _type_info(node, "type", topic)


def info(topic: str) -> int:
    """rostopic info: print a topic's type, publishers and subscribers."""
    with _cli_node() as node:
        return _type_info(node, "info", topic)


def echo(
    topic: str,
    *,
    count: int | None = None,
    noarr: bool = False,
    nostr: bool = False,
    width: int | None = None,
    plot: bool = False,
    bag: str | None = None,
    all_topics: bool = False,
    filter_expr: str | None = None,
    clear: bool = False,
    timeout: float | None = None,
) -> int:
    """rostopic echo: print messages (or one field) as YAML until ``count`` or interrupted.

    Args:
        topic: A topic, or ``topic/field`` such as ``/turtle1/pose/x`` (``""`` with
            ``all_topics``).
        count: Return after this many messages.
        noarr: Print array lengths instead of their contents.
        nostr: Print string lengths instead of their contents.
        width: Pad numbers to this fixed width (at least 2).
        plot: Print CSV rows (``-p``) instead of YAML.
        bag: Echo the messages of this bag file instead of a live topic.
        all_topics: Every message in ``bag``, whatever its topic.
        filter_expr: A Python expression of ``m`` (the whole message) and ``topic``; only
            messages for which it is true are printed (``--filter "m.data > 2"``).
        clear: Clear the terminal before each message (``-c``).
        timeout: Raise if ``count`` messages do not arrive within this many seconds.

    Raises:
        BusError: A bad count, width or timeout, an unknown topic, or nothing within ``timeout``.
    """
    from workbench.errors import BusError

    if count is not None and count < 1:
        raise BusError(f"-n must be at least 1, got {count}")
    if width is not None and width < 2:
        raise BusError("Fixed width for numeric values must be at least 2")
    if bag is not None and not bag.strip():
        raise BusError("-b needs the name of a bag file")
    if all_topics and not bag:
        raise BusError("Display all option is only valid when echoing from bag files")
    if not topic and not all_topics:
        raise BusError("topic must be specified")
    _positive(timeout, "--timeout")
    printer = _EchoPrinter(noarr=noarr, nostr=nostr, width=width, plot=plot, count=count)
    printer.prefix = "\033[2J\033[;H" if clear and not plot else ""
    if filter_expr:
        printer.keep = _message_filter(filter_expr)
    if bag:
        return _echo_bag(bag, topic, printer, all_topics)
    with _cli_node() as node:
        return _echo(node, topic, printer, timeout)


def meter(
    kind: str, topic: str, *, window: int | None = None, duration: float | None = None
) -> int:
    """rostopic hz / bw: print a topic's rate (``kind="hz"``) or bandwidth (``"bw"``) each second.

    Args:
        kind: ``hz`` or ``bw``.
        topic: The topic.
        window: Samples in the window.
        duration: Return after this many seconds (default: when interrupted).

    Raises:
        BusError: A bad kind, window or duration.
    """
    from workbench.errors import BusError

    if kind not in ("hz", "bw"):
        raise BusError(f"unknown meter '{kind}'", hint="use hz or bw")
    if window is not None and not 1 <= window <= MAX_WINDOW:
        raise BusError(f"--window must be 1 to {MAX_WINDOW:,} samples, got {window}")
    _positive(duration, "--duration")
    with _cli_node() as node:
        return _meter(node, kind, topic, window, duration)


def pub(words: list[str]) -> int:
    """rostopic pub with its command line (``[-1 | -r RATE | -l] TOPIC TYPE [ARGS ...]``).

    Raises:
        BusError: Missing topic or type, or a bad option.
    """
    if words[:1] in (["-h"], ["--help"]):
        print(f"usage: {PUB_USAGE}\n\n-1 publishes once, -r RATE repeats at RATE Hz, -l latches")
        return 0
    options = parse_pub_words(words)
    with _cli_node() as node:
        return _pub(node, options)


def plot(fields: list[str], *, seconds: float = 10.0, png: str | None = None) -> int:
    """rqt_plot: record numeric fields for ``seconds``, then draw them (into ``png`` if given).

    Raises:
        BusError: A bad duration, or a field that names a topic.
    """
    _positive(seconds, "--seconds")
    with _cli_node() as node:
        return _plot(node, fields, seconds, png)


def _list(node: Any, verbose: bool, publishers_only: bool, subscribers_only: bool) -> int:
    from workbench.introspect.graphtext import topic_list
    from workbench.introspect.session import graph

    text = topic_list(
        _without(graph(node.bus), node.name),
        verbose=verbose,
        publishers_only=publishers_only,
        subscribers_only=subscribers_only,
    )
    if text:
        print(text)
    return 0


def _without(graph: Any, name: str) -> Any:
    """The graph without the tool's own node."""
    graph.nodes.pop(name, None)
    for topic in list(graph.topics.values()):
        for ends in (topic.publishers, topic.subscribers):
            if name in ends:
                ends.remove(name)
        if not topic.publishers and not topic.subscribers:
            del graph.topics[topic.name]
    return graph


def _type_info(node: Any, verb: str, name: str) -> int:
    from workbench.introspect.echo import split_topic_field
    from workbench.introspect.graphtext import require_topic, topic_info
    from workbench.introspect.session import graph

    g = _without(graph(node.bus), node.name)
    if verb == "info":
        print(topic_info(g, name))
        return 0
    topic, fields = split_topic_field(_absolute(name), g.topics)
    record = require_topic(g, topic)
    print(record.type if not fields else f"{record.type} {'/'.join(fields)}")
    return 0


def _absolute(name: str) -> str:
    return name if name.startswith("/") else "/" + name


def _resolve_topic(node: Any, path: str) -> tuple[str, list[str]]:
    """Topic and field path; an unknown topic is waited for (rostopic says so)."""
    from workbench.errors import BusError
    from workbench.introspect.echo import split_topic_field
    from workbench.introspect.session import graph

    path = _absolute(path)
    try:
        return split_topic_field(path, _without(graph(node.bus), node.name).topics)
    except BusError:
        print(f"WARNING: topic [{path}] does not appear to be published yet", file=sys.stderr)
        return path, []


def _wait(node: Any, done: threading.Event, timeout: float | None, what: str) -> None:
    from workbench.errors import BusError

    finished = done.wait(timeout) if timeout is not None else _wait_forever(done)
    if not finished:
        raise BusError(
            f"no message on {what} within {timeout:g} s", hint="is anything publishing it?"
        )


def _wait_forever(done: threading.Event) -> bool:
    while not done.wait(0.2):
        pass
    return True


def _message_filter(expression: str) -> Callable[[Any, str], bool]:
    """``--filter``: the expression, of ``m`` and ``topic``, as a test of a message.

    Raises:
        BusError: The expression is not valid Python, or fails on a message.
    """
    import builtins

    from workbench.errors import BusError

    try:
        code = compile(expression, "--filter", "eval")
    except SyntaxError as error:
        raise BusError(f"--filter is not a Python expression: {error.msg}") from None

    def keep(msg: Any, topic: str) -> bool:
        try:
            # the user's own expression on their own messages, as rostopic evaluates it
            return bool(eval(code, {"__builtins__": builtins}, {"m": msg, "topic": topic}))  # noqa: S307
        except Exception as error:
            raise BusError(
                f"--filter {expression!r} failed: {type(error).__name__}: {error}"
            ) from None

    return keep


class _EchoPrinter:
    """Prints echoed values (YAML documents or CSV rows) and counts them."""

    def __init__(
        self, *, noarr: bool, nostr: bool, width: int | None, plot: bool, count: int | None
    ) -> None:
        self.noarr, self.nostr, self.width, self.plot = noarr, nostr, width, plot
        self.count = count
        self.printed = 0
        self.first = True
        self.prefix = ""
        self.keep: Callable[[Any, str], bool] | None = None

    @property
    def done(self) -> bool:
        return self.count is not None and self.printed >= self.count

    def show(
        self,
        value: Any,
        *,
        ros_type: str | None = None,
        typed: bool = True,
        stamp_ns: int | None = None,
    ) -> bool:
        """Print one value; False once the reader is gone (``| head``) or ``count`` is reached."""
        from workbench.introspect.echo import format_echo, format_plot, format_plot_header

        if self.plot:
            text = format_plot(value, stamp_ns, noarr=self.noarr, nostr=self.nostr)
            if self.first:
                text = format_plot_header(value, noarr=self.noarr, nostr=self.nostr) + "\n" + text
        else:
            text = format_echo(
                value,
                noarr=self.noarr,
                nostr=self.nostr,
                width=self.width,
                ros_type=ros_type,
                typed=typed,
            )
        self.first = False
        try:
            print(self.prefix + text, flush=True)
        except BrokenPipeError:  # `| head`: the reader is gone, stop as a shell tool does
            from workbench.cli.signals import silence_stdout

            silence_stdout()
            return False
        self.printed += 1
        return not self.done


def _echo_bag(path: str, topic: str, printer: _EchoPrinter, all_topics: bool) -> int:
    """rostopic echo -b: the bag's messages of ``topic`` (or a field of them) in time order."""
    from workbench.bag import read_messages, summarize
    from workbench.bag.errors import warnings_as_lines
    from workbench.errors import BusError
    from workbench.introspect.echo import field_type, get_field, split_topic_field

    topic = _absolute(topic).rstrip("/") if topic and not all_topics else ""
    summary = summarize(path)
    named = {name: _absolute(name) for name in summary.topic_types()}
    fields: list[str] = []
    if all_topics:
        wanted = list(named)
    else:
        try:
            # the longest topic of the bag the path starts with; the rest is a field path
            found, fields = split_topic_field(topic, named.values())
        except BusError:
            raise BusError(
                f"topic {topic} is not in {path}",
                hint=f"its topics are: {', '.join(sorted(named.values())) or 'none'}",
            ) from None
        wanted = [name for name, full in named.items() if full == found]
    for conn in summary.connections.values():
        if conn.topic in wanted:
            _learn_type(conn.typename, conn.definition)
    with warnings_as_lines():  # damaged chunks: one [WARN] line each
        for record in read_messages(path, wanted):
            value = record.msg
            if printer.keep is not None and not printer.keep(value, named[record.topic]):
                continue
            ros_type = None
            if fields:
                value = get_field(value, fields, topic=named[record.topic])
                ros_type = field_type(type(record.msg), fields)
            # a bag gives rostopic no field types: --noarr/--nostr do not reach an echoed field
            if not printer.show(value, ros_type=ros_type, typed=False, stamp_ns=record.stamp_ns):
                break
    return 0


def _learn_type(typename: str, definition: str) -> None:
    """Register a bag's message type workbench lacks, from the definition the bag carries."""
    from workbench.errors import MessageError
    from workbench.msgs._store import store

    try:
        store().message_class(typename)
    except MessageError:
        with contextlib.suppress(MessageError):
            store().register_message(typename, definition)


def _echo(node: Any, path: str, printer: _EchoPrinter, timeout: float | None) -> int:
    from workbench.bus import AnyMsg
    from workbench.introspect.echo import field_type, get_field

    topic, fields = _resolve_topic(node, path)
    done = threading.Event()
    state: dict[str, Any] = {"error": None}
    lock = threading.Lock()

    def callback(msg: Any) -> None:
        with lock:
            if done.is_set():
                return
            try:
                if printer.keep is not None and not printer.keep(msg, topic):
                    return
                value = get_field(msg, fields, topic=topic) if fields else msg
            except Exception as error:  # reported once, from the main thread
                state["error"] = error
                done.set()
                return
            ros_type = field_type(type(msg), fields) if fields else None
            if not printer.show(value, ros_type=ros_type):
                done.set()

    node.create_subscription(topic, AnyMsg, callback, queue_size=0)
    try:
        _wait(node, done, timeout, topic)
    except KeyboardInterrupt:
        return 0
    if state["error"] is not None:
        raise state["error"]
    return 0


def _meter(node: Any, kind: str, path: str, window: int | None, duration: float | None) -> int:
    from workbench.bus import AnyMsg
    from workbench.introspect.rates import BwMeter, HzMeter

    topic, _ = _resolve_topic(node, path)
    rates: Any = HzMeter(window or 50000) if kind == "hz" else BwMeter(window or 100)
    lock = threading.Lock()

    def callback(msg: Any) -> None:
        now = time.monotonic()
        with lock:
            if kind == "hz":
                rates.add(now)
            else:
                from workbench.msgs import serialize

                rates.add(now, len(serialize(msg)) if not isinstance(msg, bytes) else len(msg))

    node.create_subscription(topic, AnyMsg, callback, queue_size=0)
    print(f"subscribed to [{topic}]", flush=True)
    start = time.monotonic()
    try:
        while duration is None or time.monotonic() - start < duration:
            time.sleep(min(1.0, duration or 1.0))
            with lock:
                text = rates.report()
            print(text if text else "no new messages", flush=True)
    except KeyboardInterrupt:
        pass
    return 0


def parse_pub_words(words: list[str]) -> dict[str, Any]:
    """rostopic pub's command line: options may sit between the positionals; ``--`` ends them.

    Raises:
        BusError: missing topic/type or a bad option value.
    """
    from workbench.cli.values import check_rate
    from workbench.errors import BusError

    options: dict[str, Any] = {"once": False, "rate": None, "latch": False, "positional": []}
    rest: list[str] = []
    i = 0
    while i < len(words):
        word = words[i]
        if word == "--":
            rest = words[i + 1 :]
            break
        if word in ("-1", "--once"):
            options["once"] = True
        elif word in ("-l", "--latch"):
            options["latch"] = True
        elif word in ("-r", "--rate") or word.startswith("--rate="):
            value = (
                word.split("=", 1)[1]
                if "=" in word
                else (words[i + 1] if i + 1 < len(words) else "")
            )
            i += 0 if "=" in word else 1
            try:
                options["rate"] = float(value)
            except ValueError:
                raise BusError(
                    f"-r needs a rate in Hz, got {_short(value)!r}", hint=PUB_USAGE
                ) from None
            if not options["rate"] > 0:
                raise BusError(f"-r needs a positive rate, got {_short(value)}", hint=PUB_USAGE)
            check_rate(options["rate"], "-r", BusError)
        elif word.startswith("-") and not _is_number(word) and len(options["positional"]) < 2:
            raise BusError(f"unknown option {word}", hint=PUB_USAGE)
        else:
            options["positional"].append(word)
        i += 1
    positional = options.pop("positional") + rest
    if options["rate"] is not None and options["once"]:
        raise BusError("-r and -1 cannot go together", hint=PUB_USAGE)
    if len(positional) < 2:
        raise BusError("pub needs a topic and a message type", hint=PUB_USAGE)
    options["topic"], options["type"], options["args"] = (
        positional[0],
        positional[1],
        positional[2:],
    )
    return options


def _short(text: str) -> str:
    return text if len(text) <= 40 else text[:37] + "..."


def _is_number(word: str) -> bool:
    try:
        float(word)
    except ValueError:
        return False
    return True


def _pub(node: Any, options: dict[str, Any]) -> int:
    from workbench.introspect.args import message_from_args
    from workbench.introspect.session import settle
    from workbench.msgs import get_type

    topic = node.resolve_name(options["topic"])
    cls = get_type(options["type"])
    msg = message_from_args(cls, options["args"], what=f"topic {topic}")
    pub = node.create_publisher(topic, cls, latch=not options["rate"])
    bus = node.bus

    def has_subscriber() -> bool:
        record = bus.graph().topics.get(topic)
        return bool(record and [s for s in record.subscribers if s != node.name])

    try:
        if options["rate"]:
            period = 1.0 / options["rate"]
            settle(bus, has_subscriber)
            next_time = time.monotonic()
            while True:
                pub.publish(msg)
                next_time += period
                time.sleep(max(0.0, next_time - time.monotonic()))
        settle(bus, has_subscriber, timeout=3.0)
        if options["once"]:
            print("publishing and latching message for 3.0 seconds", flush=True)
            pub.publish(msg)
            bus.spin_until(lambda: False, timeout=0.3 if not bus.is_connected else 1.0)
            return 0
        print("publishing and latching message. Press ctrl-C to terminate", flush=True)
        pub.publish(msg)
        while True:
            time.sleep(0.2)
    except KeyboardInterrupt:
        return 0


def _plot(node: Any, fields: list[str], seconds: float, png: str | None) -> int:
    import os

    from workbench.bus import AnyMsg
    from workbench.introspect.plot import FieldSeries, plot_series

    series: list[FieldSeries] = []
    for path in fields:
        topic, field_path = _resolve_topic(node, path)
        if not field_path:
            from workbench.errors import BusError

            raise BusError(f"{path} names a topic, not a field", hint=f"plot e.g. {path}/x")
        series.append(FieldSeries(path, topic, field_path))
    lock = threading.Lock()
    errors: list[Exception] = []
    t0 = time.monotonic()

    def make_callback(items: list[FieldSeries]):
        def callback(msg: Any) -> None:
            with lock:
                for s in items:
                    try:
                        s.add(time.monotonic() - t0, msg)
                    except Exception as error:
                        errors.append(error)

        return callback

    by_topic: dict[str, list[FieldSeries]] = {}
    for s in series:
        by_topic.setdefault(s.topic, []).append(s)
    for topic, items in by_topic.items():
        node.create_subscription(topic, AnyMsg, make_callback(items), queue_size=0)
    if png is None and not os.environ.get("DISPLAY"):
        png = "plot.png"
    try:
        while time.monotonic() - t0 < seconds and not errors:
            time.sleep(0.05)
    except KeyboardInterrupt:
        pass
    if errors:
        raise errors[0]
    with lock:
        out = plot_series(series, png, title=", ".join(fields))
    if out is not None:
        print(f"wrote {out}")
    return 0
