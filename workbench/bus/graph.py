"""A snapshot of the computation graph: nodes, topics and services.

``Bus.graph()`` returns a :class:`Graph` built from every endpoint the bus
knows (its own nodes, plus every other process's when joined to a core).
Introspection tools (``workbench node/topic/service``) read it.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Endpoint:
    """One publisher, subscriber or service server of one node.

    Attributes:
        node: Global node name (``/talker``).
        kind: ``pub``, ``sub`` or ``srv``.
        name: Global topic or service name.
        type: ROS type name (``std_msgs/String``); ``*`` for a type-agnostic subscriber.
        md5: The type's md5sum (``*`` for type-agnostic).
        local: Whether it lives in this process.
    """

    node: str
    kind: str
    name: str
    type: str
    md5: str
    local: bool = True


@dataclass
class NodeRecord:
    """A node and what it offers (``rosnode info``)."""

    name: str
    local: bool
    pid: int | None = None
    publications: list[str] = field(default_factory=list)
    subscriptions: list[str] = field(default_factory=list)
    services: list[str] = field(default_factory=list)


@dataclass
class TopicRecord:
    """A topic, its type(s) and its ends (``rostopic info``)."""

    name: str
    types: list[str] = field(default_factory=list)
    publishers: list[str] = field(default_factory=list)
    subscribers: list[str] = field(default_factory=list)

    @property
    def type(self) -> str:
        """The topic's type (the first one seen if the ends disagree)."""
        concrete = [t for t in self.types if t != "*"]
        return concrete[0] if concrete else "*"


@dataclass
class ServiceRecord:
    """A service, its type and the node(s) offering it (``rosservice info``)."""

    name: str
    type: str
    md5: str
    providers: list[str] = field(default_factory=list)


@dataclass
class Graph:
    """Nodes, topics and services, each keyed by global name."""

    nodes: dict[str, NodeRecord] = field(default_factory=dict)
    topics: dict[str, TopicRecord] = field(default_factory=dict)
    services: dict[str, ServiceRecord] = field(default_factory=dict)

    @classmethod
    def from_endpoints(
        cls, nodes: dict[str, tuple[bool, int | None]], endpoints: list[Endpoint]
    ) -> Graph:
        """Build the graph.

        Args:
            nodes: Node name -> (local, pid).
            endpoints: Every endpoint of those nodes.
        """
        graph = cls()
        for name, (local, pid) in sorted(nodes.items()):
            graph.nodes[name] = NodeRecord(name, local, pid)
        for ep in sorted(endpoints, key=lambda e: (e.name, e.kind, e.node)):
            record = graph.nodes.setdefault(ep.node, NodeRecord(ep.node, ep.local))
            if ep.kind == "srv":
                _add(record.services, ep.name)
                service = graph.services.setdefault(
                    ep.name, ServiceRecord(ep.name, ep.type, ep.md5)
                )
                _add(service.providers, ep.node)
                continue
            topic = graph.topics.setdefault(ep.name, TopicRecord(ep.name))
            _add(topic.types, ep.type)
            if ep.kind == "pub":
                _add(record.publications, ep.name)
                _add(topic.publishers, ep.node)
            else:
                _add(record.subscriptions, ep.name)
                _add(topic.subscribers, ep.node)
        return graph


def _add(items: list[str], item: str) -> None:
    if item not in items:
        items.append(item)
