"""rqt_graph as a picture: nodes (ellipses) and topics (boxes) drawn with pydot.

Like rqt_graph's default view ("Nodes/Topics (active)", "Hide debug"), it
leaves out ``/rosout`` and topics nobody both publishes and subscribes to
unless ``all_topics`` is set.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

DEBUG_TOPICS = ("/rosout", "/rosout_agg", "/statistics", "/clock")
DEBUG_NODES = ("/rosout",)


def graph_to_dot(graph: Any, *, all_topics: bool = False, hide_debug: bool = True):
    """A ``pydot.Dot`` of a ``workbench.bus`` graph snapshot.

    Args:
        graph: ``bus.graph()`` (nodes/topics dicts of records).
        all_topics: Also draw topics with only publishers or only subscribers.
        hide_debug: Leave out /rosout and friends (rqt_graph's "Hide: Debug").
    """
    import pydot

    dot = pydot.Dot("rosgraph", graph_type="digraph", rankdir="LR")
    dot.set_node_defaults(fontname="Helvetica", fontsize="11")
    shown_nodes: set[str] = set()
    for name, topic in sorted(graph.topics.items()):
        if hide_debug and name in DEBUG_TOPICS:
            continue
        pubs = [n for n in topic.publishers if not (hide_debug and n in DEBUG_NODES)]
        subs = [n for n in topic.subscribers if not (hide_debug and n in DEBUG_NODES)]
        if not all_topics and not (pubs and subs):
            continue
        topic_id = _id("t", name)
        dot.add_node(pydot.Node(topic_id, label=name, shape="box"))
        for node in pubs:
            shown_nodes.add(node)
            dot.add_edge(pydot.Edge(_id("n", node), topic_id))
        for node in subs:
            shown_nodes.add(node)
            dot.add_edge(pydot.Edge(topic_id, _id("n", node)))
    for name in sorted(graph.nodes):
        if hide_debug and name in DEBUG_NODES:
            continue
        dot.add_node(pydot.Node(_id("n", name), label=name, shape="ellipse"))
    return dot


def _id(prefix: str, name: str) -> str:
    return '"' + prefix + ":" + name + '"'


def write_graph(dot: Any, path: str | os.PathLike[str]) -> Path:
    """Write ``dot`` as ``.svg``, ``.png``, ``.pdf`` (graphviz ``dot``) or ``.gv`` text.

    Raises:
        MissingDependencyError: graphviz ``dot`` is not installed (for pictures).
    """
    from workbench.errors import ViewerError
    from workbench.optional import require_program

    path = Path(path)
    fmt = path.suffix.lstrip(".").lower() or "svg"
    if fmt in ("gv", "dot"):
        path.write_text(dot.to_string())
        return path
    if fmt not in ("svg", "png", "pdf"):
        raise ViewerError(
            f"cannot write a graph as '.{fmt}'", path=path, hint="use .svg, .png, .pdf or .gv"
        )
    program = require_program("dot")
    try:
        dot.write(str(path), format=fmt, prog=program)
    except OSError as error:
        raise ViewerError(f"cannot write the graph: {error}", path=path) from None
    return path
