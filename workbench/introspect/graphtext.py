"""The text of ``rosnode``, ``rostopic`` and ``rosservice`` queries on a graph snapshot.

Layouts follow the ROS 1 Noetic tools: ``rosnode info``'s dashed header and
``Publications:``/``Subscriptions:``/``Services:`` sections with `` * name
[type]`` lines; ``rostopic list -v``'s ``Published topics:``/``Subscribed
topics:`` with counts; ``rostopic info``'s ``Type:``/``Publishers:``/
``Subscribers:``. Where ROS prints XML-RPC URIs and TCPROS ports,
workbench says which process a node lives in.
"""

from __future__ import annotations

from typing import Any

from workbench.errors import BusError

RULE = "-" * 80


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def require_node(graph: Any, name: str) -> Any:
    """The node record called ``name`` (``/`` added if missing).

    Raises:
        BusError: unknown node (lists the known ones).
    """
    full = name if name.startswith("/") else "/" + name
    record = graph.nodes.get(full)
    if record is None:
        known = ", ".join(sorted(graph.nodes)) or "none"
        raise BusError(f"unknown node [{full}]", hint=f"running nodes: {known}")
    return record


def require_topic(graph: Any, name: str) -> Any:
    """The topic record called ``name``; unknown -> BusError."""
    full = name if name.startswith("/") else "/" + name
    record = graph.topics.get(full)
    if record is None:
        raise BusError(
            f"unknown topic {full}", hint="'workbench topic list' shows the topics in use"
        )
    return record


def require_service(graph: Any, name: str) -> Any:
    """The service record called ``name``; unknown -> BusError."""
    full = name if name.startswith("/") else "/" + name
    record = graph.services.get(full)
    if record is None:
        raise BusError(
            f"service {full} does not exist",
            hint="'workbench service list' shows the offered services",
        )
    return record


def node_list(graph: Any) -> str:
    return "\n".join(sorted(graph.nodes))


def node_info(graph: Any, name: str) -> str:
    """``rosnode info NODE``."""
    node = require_node(graph, name)
    lines = [RULE, f"Node [{node.name}]"]

    def section(title: str, names: list[str], typed: bool, table: dict[str, Any]) -> None:
        if not names:
            lines.append(f"{title}: None")
        else:
            lines.append(f"{title}: ")
            for item in sorted(names):
                kind = f" [{table[item].type}]" if typed and item in table else ""
                lines.append(f" * {item}{kind}")
        lines.append("")

    section("Publications", node.publications, True, graph.topics)
    section("Subscriptions", node.subscriptions, True, graph.topics)
    section("Services", node.services, False, graph.services)
    where = "this process" if node.local else "another process"
    if node.pid is not None:
        lines.append(f"Pid: {node.pid}")
    lines.append(f"Process: {where}")
    connections = []
    for topic in sorted(node.publications):
        for peer in graph.topics[topic].subscribers:
            if peer != node.name:
                connections.append((topic, peer, "outbound"))
    for topic in sorted(node.subscriptions):
        for peer in graph.topics[topic].publishers:
            if peer != node.name:
                connections.append((topic, peer, "inbound"))
    if connections:
        lines.append("Connections:")
        for topic, peer, direction in connections:
            lines += [f" * topic: {topic}", f"    * to: {peer}", f"    * direction: {direction}"]
    return "\n".join(lines).rstrip() + "\n"


def topic_list(
    graph: Any, *, verbose: bool = False, publishers_only=False, subscribers_only=False
) -> str:
    """``rostopic list [-v] [-p|-s]``."""
    topics = graph.topics
    if not verbose:
        names = [
            n
            for n, t in sorted(topics.items())
            if (not publishers_only or t.publishers) and (not subscribers_only or t.subscribers)
        ]
        return "\n".join(names)
    lines: list[str] = []
    if not subscribers_only:
        lines += ["", "Published topics:"]
        for name, t in sorted(topics.items()):
            if t.publishers:
                lines.append(f" * {name} [{t.type}] {_plural(len(t.publishers), 'publisher')}")
    if not publishers_only:
        lines += ["", "Subscribed topics:"]
        for name, t in sorted(topics.items()):
            if t.subscribers:
                lines.append(f" * {name} [{t.type}] {_plural(len(t.subscribers), 'subscriber')}")
    return "\n".join(lines) + "\n"


def topic_info(graph: Any, name: str) -> str:
    """``rostopic info TOPIC``."""
    t = require_topic(graph, name)
    lines = [f"Type: {t.type}", ""]
    for title, names in (("Publishers", t.publishers), ("Subscribers", t.subscribers)):
        if names:
            lines.append(f"{title}: ")
            lines += [f" * {n} ({_where(graph, n)})" for n in sorted(names)]
        else:
            lines.append(f"{title}: None")
        lines.append("")
    return "\n".join(lines)


def _where(graph: Any, node: str) -> str:
    record = graph.nodes.get(node)
    if record is None:
        return "unknown"
    text = "this process" if record.local else "another process"
    return f"{text}, pid {record.pid}" if record.pid is not None else text


def service_list(graph: Any, *, nodes: bool = False) -> str:
    """``rosservice list [-n]``."""
    if nodes:
        return "\n".join(f"{n} {' '.join(s.providers)}" for n, s in sorted(graph.services.items()))
    return "\n".join(sorted(graph.services))


def service_info(graph: Any, name: str) -> str:
    """``rosservice info SERVICE``."""
    from workbench.msgs import get_service

    s = require_service(graph, name)
    args = " ".join(get_service(s.type).Request.__slots__)
    return "\n".join([f"Node: {', '.join(s.providers)}", f"Type: {s.type}", f"Args: {args}"])


def service_find(graph: Any, typename: str) -> str:
    """``rosservice find TYPE``."""
    return "\n".join(n for n, s in sorted(graph.services.items()) if s.type == typename)
