"""``workbench node``: rosnode (list, info, ping, kill, cleanup) and rqt_graph (graph)."""

from __future__ import annotations

import argparse
import contextlib
import time
from collections.abc import Iterator
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    verbs.add_parser("list", help="list running nodes")
    info = verbs.add_parser("info", help="a node's publications, subscriptions and services")
    info.add_argument("node")
    ping = verbs.add_parser("ping", help="check that a node is alive")
    ping.add_argument("node")
    ping.add_argument("-c", "--count", type=int, default=1, help="pings to send (1)")
    kill = verbs.add_parser("kill", help="shut a node down")
    kill.add_argument("nodes", nargs="+", metavar="NODE")
    verbs.add_parser("cleanup", help="forget nodes that no longer answer")
    graph = verbs.add_parser("graph", help="draw nodes and topics (rqt_graph)")
    graph.add_argument("-o", "--out", default="rosgraph.svg", help="output .svg/.png/.pdf/.gv")
    graph.add_argument("--all", action="store_true", help="also topics without both ends, /rosout")
    graph.add_argument("--show", action="store_true", help="open the picture in the browser")


def run(args: argparse.Namespace) -> int:
    if args.verb == "list":
        return list_nodes()
    if args.verb == "info":
        return info(args.node)
    if args.verb == "ping":
        return ping(args.node, count=args.count)
    if args.verb == "kill":
        return kill(args.nodes)
    if args.verb == "cleanup":
        return cleanup()
    return graph(out=args.out, all_topics=args.all, show=args.show)


@contextlib.contextmanager
def _session() -> Iterator[tuple[Any, Any]]:
    """The tool's own node and the graph without it."""
    from workbench.introspect.session import cli_node
    from workbench.introspect.session import graph as read_graph

    node = cli_node("rosnode")
    try:
        g = read_graph(node.bus)
        _forget(g, node.name)
        yield node, g
    finally:
        node.shutdown()


def list_nodes() -> int:
    """rosnode list: the running nodes."""
    from workbench.introspect.graphtext import node_list

    with _session() as (_, g):
        print(node_list(g))
    return 0


def info(name: str) -> int:
    """rosnode info: a node's publications, subscriptions and services.

    Raises:
        BusError: No such node.
    """
    from workbench.introspect.graphtext import node_info

    with _session() as (_, g):
        print(node_info(g, name), end="")
    return 0


def ping(name: str, *, count: int = 1) -> int:
    """rosnode ping: check ``count`` times, a second apart, that a node is alive.

    Returns:
        0 when every ping was answered, else 1.

    Raises:
        BusError: No such node, or a count below 1.
    """
    from workbench.errors import BusError

    if count < 1:
        raise BusError(f"--count must be at least 1, got {count}")
    with _session() as (node, g):
        return _ping(node, g, name, count)


def kill(names: list[str]) -> int:
    """rosnode kill: shut the named nodes down.

    Raises:
        BusError: One of them does not exist (none is killed then).
    """
    with _session() as (node, g):
        return _kill(node, g, names)


def cleanup() -> int:
    """rosnode cleanup: nothing to purge, since the registry forgets nodes that leave."""
    with _session():
        print("no unreachable nodes to purge")
    return 0


def graph(*, out: str = "rosgraph.svg", all_topics: bool = False, show: bool = False) -> int:
    """rqt_graph: draw the nodes and topics into ``out`` (.svg, .png, .pdf or .gv).

    Args:
        out: The picture to write.
        all_topics: Also topics without both ends, and /rosout.
        show: Open the picture in the browser.
    """
    with _session() as (_, g):
        return _graph(g, out, all_topics, show)


def _forget(g: Any, name: str) -> None:
    g.nodes.pop(name, None)
    for topic in list(g.topics.values()):
        for ends in (topic.publishers, topic.subscribers):
            if name in ends:
                ends.remove(name)
        if not topic.publishers and not topic.subscribers:
            del g.topics[topic.name]


def _ping(node: Any, g: Any, name: str, count: int) -> int:
    from workbench.introspect.graphtext import require_node

    record = require_node(g, name)
    print(f"rosnode: node is [{record.name}]")
    print(f"pinging {record.name} with a timeout of 3.0s")
    for i in range(count):
        start = time.perf_counter()
        present = record.name in node.bus.graph().nodes
        elapsed = (time.perf_counter() - start) * 1000
        if not present:
            print(f"ERROR: connection refused to [{record.name}]")
            return 1
        where = f"pid {record.pid}" if record.pid is not None else "registered"
        print(f"reply from {record.name} ({where})     time={elapsed:.6f}ms")
        if i + 1 < count:
            time.sleep(1.0)
    return 0


def _kill(node: Any, g: Any, names: list[str]) -> int:
    from workbench.introspect.graphtext import require_node

    records = [require_node(g, n) for n in names]
    for record in records:
        print(f"killing {record.name}")
        node.bus.kill_node(record.name, "user request")
    print("killed")
    return 0


def _graph(g: Any, out: str, all_topics: bool, show: bool) -> int:
    from workbench.introspect.graphview import graph_to_dot, write_graph

    path = write_graph(graph_to_dot(g, all_topics=all_topics, hide_debug=not all_topics), out)
    print(f"wrote {path}")
    if show:
        import webbrowser

        webbrowser.open(path.resolve().as_uri())
    return 0
