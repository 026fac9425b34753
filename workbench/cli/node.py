"""``workbench node``: rosnode (list, info, ping, kill, cleanup) and rqt_graph (graph)."""

from __future__ import annotations

import argparse
import time
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
    from workbench.introspect.session import cli_node, graph

    node = cli_node("rosnode")
    try:
        g = graph(node.bus)
        _forget(g, node.name)
        if args.verb == "list":
            from workbench.introspect.graphtext import node_list

            print(node_list(g))
        elif args.verb == "info":
            from workbench.introspect.graphtext import node_info

            print(node_info(g, args.node), end="")
        elif args.verb == "ping":
            return _ping(node, g, args)
        elif args.verb == "kill":
            return _kill(node, g, args.nodes)
        elif args.verb == "cleanup":
            print("no unreachable nodes to purge")
        else:
            return _graph(g, args)
        return 0
    finally:
        node.shutdown()


def _forget(g: Any, name: str) -> None:
    g.nodes.pop(name, None)
    for topic in list(g.topics.values()):
        for ends in (topic.publishers, topic.subscribers):
            if name in ends:
                ends.remove(name)
        if not topic.publishers and not topic.subscribers:
            del g.topics[topic.name]


def _ping(node: Any, g: Any, args: argparse.Namespace) -> int:
    from workbench.introspect.graphtext import require_node

    record = require_node(g, args.node)
    print(f"rosnode: node is [{record.name}]")
    print(f"pinging {record.name} with a timeout of 3.0s")
    for i in range(args.count):
        start = time.perf_counter()
        present = record.name in node.bus.graph().nodes
        elapsed = (time.perf_counter() - start) * 1000
        if not present:
            print(f"ERROR: connection refused to [{record.name}]")
            return 1
        where = f"pid {record.pid}" if record.pid is not None else "registered"
        print(f"reply from {record.name} ({where})     time={elapsed:.6f}ms")
        if i + 1 < args.count:
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


def _graph(g: Any, args: argparse.Namespace) -> int:
    from workbench.introspect.graphview import graph_to_dot, write_graph

    path = write_graph(graph_to_dot(g, all_topics=args.all, hide_debug=not args.all), args.out)
    print(f"wrote {path}")
    if args.show:
        import webbrowser

        webbrowser.open(path.resolve().as_uri())
    return 0
