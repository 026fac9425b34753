"""``urdf_to_graphviz``: the link/joint tree as a graphviz graph.

Links are boxes, joints blue ellipses, and each parent-link -> joint edge
carries the joint origin (``xyz`` in metres, ``rpy`` in radians), exactly
as ROS's ``urdf_to_graphviz`` writes its ``.gv`` file.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pydot

from workbench.errors import ModelError
from workbench.model.tree import KinematicTree, checked_tree
from workbench.model.urdf_xml import UrdfDocument
from workbench.optional import require_program

FORMATS = ("pdf", "svg", "png")


class RobotGraph(pydot.Dot):
    """A pydot graph of a robot that Jupyter shows as SVG (needs graphviz ``dot``).

    Attributes:
        source: The ``.gv`` text, as ``urdf_to_graphviz`` writes it.
        robot_name: The robot's name (the default output file stem).
    """

    source: str = ""
    robot_name: str = ""

    def _repr_svg_(self) -> str | None:
        from workbench.optional import find_program

        if find_program("dot") is None:
            return None  # Jupyter falls back to the text form
        return render_source(self.source, "svg").decode("utf-8")

    def __str__(self) -> str:
        return self.source


def _number(value: float) -> str:
    # C++ ostream's default formatting (6 significant digits), without "-0".
    text = f"{value:g}"
    return "0" if text == "-0" else text


def _ordered_children(tree: KinematicTree) -> dict:
    return {link: sorted(joints, key=lambda j: j.name) for link, joints in tree.children.items()}


def graph_source(document: UrdfDocument) -> str:
    """The ``.gv`` text of ``document`` (children ordered by joint name, as urdfdom does)."""
    root, tree = checked_tree(document)
    children = _ordered_children(tree)
    lines = ["digraph G {", "node [shape=box];"]

    def links(link: str) -> None:
        lines.append(f'"{link}" [label="{link}"];')
        for joint in children.get(link, []):
            links(joint.child)

    def joints(link: str) -> None:
        for joint in children.get(link, []):
            xyz = " ".join(_number(v) for v in joint.xyz)
            rpy = " ".join(_number(v) for v in joint.rpy)
            lines.append(f'"{link}" -> "{joint.name}" [label="xyz: {xyz} \\nrpy: {rpy}"]')
            lines.append(f'"{joint.name}" -> "{joint.child}"')
            joints(joint.child)

    links(root)
    lines.append("node [shape=ellipse, color=blue, fontcolor=blue];")
    joints(root)
    lines.append("}")
    return "\n".join(lines) + "\n"


def robot_graph(document: UrdfDocument) -> RobotGraph:
    """A :class:`RobotGraph` (pydot) of ``document``."""
    root, tree = checked_tree(document)
    children = _ordered_children(tree)
    graph = RobotGraph("G", graph_type="digraph")
    graph.source = graph_source(document)
    graph.robot_name = document.name
    order: list[str] = []

    def walk(link: str) -> None:
        order.append(link)
        for joint in children.get(link, []):
            walk(joint.child)

    walk(root)
    for link in order:
        graph.add_node(pydot.Node(link, label=link, shape="box"))
    for link in order:
        for joint in children.get(link, []):
            graph.add_node(pydot.Node(joint.name, shape="ellipse", color="blue", fontcolor="blue"))
            xyz = " ".join(_number(v) for v in joint.xyz)
            rpy = " ".join(_number(v) for v in joint.rpy)
            graph.add_edge(pydot.Edge(link, joint.name, label=f"xyz: {xyz} \\nrpy: {rpy}"))
            graph.add_edge(pydot.Edge(joint.name, joint.child))
    return graph


def render_source(source: str, fmt: str) -> bytes:
    """Run graphviz ``dot`` on ``.gv`` text and return the ``fmt`` (pdf, svg, png) bytes.

    Raises:
        MissingDependencyError: graphviz is not installed.
        ModelError: dot failed.
    """
    if fmt not in FORMATS:
        raise ModelError(f"unknown graph format '{fmt}'", hint="use " + ", ".join(FORMATS))
    dot = require_program("dot")
    result = subprocess.run(
        [dot, f"-T{fmt}"], input=source.encode(), capture_output=True, timeout=120, check=False
    )
    if result.returncode != 0:
        reason = result.stderr.decode(errors="replace").strip().splitlines()[:1] or ["no output"]
        raise ModelError(f"graphviz dot failed: {reason[0]}")
    return result.stdout


def write_graph(
    document: UrdfDocument,
    gv_path: str | os.PathLike[str],
    out_path: str | os.PathLike[str] | None,
    fmt: str | None = None,
) -> list[Path]:
    """Write the ``.gv`` file and, unless ``out_path`` is None, its rendering.

    Returns:
        The files written, ``.gv`` first.
    """
    gv_path = Path(gv_path)
    source = graph_source(document)
    try:
        gv_path.write_text(source, encoding="utf-8")
        written = [gv_path]
        if out_path is not None:
            out_path = Path(out_path)
            fmt = fmt or out_path.suffix.lstrip(".").lower() or "pdf"
            data = render_source(source, fmt)
            out_path.write_bytes(data)
            written.append(out_path)
    except OSError as error:
        raise ModelError(f"cannot write the graph: {error.strerror}", path=error.filename) from None
    return written
