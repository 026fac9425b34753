"""``urdf_to_graphviz``: the link/joint tree as a graphviz graph.

Links are boxes, joints blue ellipses, and each parent-link -> joint edge
carries the joint origin (``xyz`` in metres, ``rpy`` in radians). The ``.gv``
text is byte for byte what ROS's ``urdf_to_graphviz`` writes: the tree and
numbers are urdfdom's (:mod:`workbench.model.urdfdom`), so rpy is printed back
from the quaternion urdfdom keeps (``-4.71239`` reads ``1.5708``) and ``-0``
keeps its sign.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pydot

from workbench.errors import ModelError
from workbench.model.sources import read_description, resolve_robot_path
from workbench.model.tree import build_tree, checked_tree
from workbench.model.urdf_xml import UrdfDocument, UrdfSyntaxError, parse_urdf_text
from workbench.model.urdfdom import RosJoint, RosModel, cpp_double
from workbench.model.urdfdom_reader import read_ros_model
from workbench.optional import require_program
from workbench.output_files import check_output, write_output

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


def ros_tree(document: UrdfDocument) -> RosModel:
    """urdfdom's tree of ``document``, which urdf_to_graphviz draws.

    Raises:
        ModelError: ROS's parser refuses the file, or its tree never ends (a loop
            below the root); the message names the element and what to do.
    """
    ros = read_ros_model(document.root)
    if ros.printable:
        return ros
    if build_tree(document).problems:
        checked_tree(document)  # raises workbench's explanation of the broken tree
    errors = [message for message in ros.messages if message.level == "Error"]
    if not errors:
        raise ModelError("ROS's URDF parser cannot walk this tree", path=document.path)
    cause = next(message for message in errors if message.element == errors[-1].element)
    raise ModelError(
        f"{cause.element}: ROS's URDF parser refuses the file: {cause.one_line}",
        path=document.path,
        line=cause.line,
        hint="fix that element; 'workbench check' lists every problem",
    )


def graph_source(document: UrdfDocument) -> str:
    """The ``.gv`` text of ``document``, byte for byte what urdf_to_graphviz writes."""
    return ros_tree(document).graph_source()


def robot_graph(document: UrdfDocument) -> RobotGraph:
    """A :class:`RobotGraph` (pydot) of ``document``."""
    ros = ros_tree(document)
    graph = RobotGraph("G", graph_type="digraph")
    graph.source = ros.graph_source()
    graph.robot_name = document.name
    assert ros.root is not None  # ros_tree returns printable trees only
    joints: list[RosJoint] = ros.joints_depth_first()
    order = [ros.root] + [joint.child for joint in joints]
    for link in order:
        graph.add_node(pydot.Node(link, label=link, shape="box"))
    parent_joints = ros.parent_joints()
    for joint in joints:
        shown = parent_joints[joint.child]  # as in the .gv, see RosModel.graph_source
        graph.add_node(pydot.Node(shown.name, shape="ellipse", color="blue", fontcolor="blue"))
        xyz = " ".join(cpp_double(v) for v in shown.xyz)
        rpy = " ".join(cpp_double(v) for v in shown.rpy)
        graph.add_edge(pydot.Edge(joint.parent, shown.name, label=f"xyz: {xyz} \\nrpy: {rpy}"))
        graph.add_edge(pydot.Edge(shown.name, joint.child))
    return graph


def render_source(source: str, fmt: str, gv_path: Path | None = None) -> bytes:
    """Run graphviz ``dot`` on ``.gv`` text and return the ``fmt`` (pdf, svg, png) bytes.

    Args:
        source: The ``.gv`` text.
        fmt: ``pdf``, ``svg`` or ``png``.
        gv_path: The ``.gv`` file the text was written to (named in errors).

    Raises:
        MissingDependencyError: graphviz is not installed.
        ModelError: dot failed or took longer than :data:`DOT_SECONDS`; the message names
            the ``.gv`` file, its line and the link or joint there.
    """
    if fmt not in FORMATS:
        raise ModelError(f"unknown graph format '{fmt}'", hint="use " + ", ".join(FORMATS))
    dot = require_program("dot")
    try:
        result = subprocess.run(
            [dot, f"-T{fmt}"],
            input=source.encode(),
            capture_output=True,
            timeout=DOT_SECONDS,
            check=False,
        )
    except subprocess.TimeoutExpired:
        raise ModelError(
            f"graphviz dot took more than {DOT_SECONDS} s",
            path=gv_path,
            hint="draw a smaller model",
        ) from None
    if result.returncode != 0:
        raise dot_failure(result.stderr.decode(errors="replace"), source, gv_path)
    return result.stdout


#: Longest a ``dot`` run may take, seconds.
DOT_SECONDS = 120
_LINE = re.compile(r"\bline (\d+)")
_QUOTED = re.compile(r'\s*"((?:[^"\\]|\\.)*)"')


def dot_failure(stderr: str, source: str, gv_path: Path | None = None) -> ModelError:
    """dot's complaint as one line: the ``.gv`` file and line, and the link or joint there."""
    lines = [line for line in stderr.strip().splitlines() if line.strip()]
    reason = lines[0] if lines else "no output"
    match = _LINE.search(stderr)
    line = int(match.group(1)) if match else None
    text = source.splitlines()
    where = ""
    if line is not None and 1 <= line <= len(text):
        name = _QUOTED.match(text[line - 1])
        if name is not None:
            ellipses = text.index("node [shape=ellipse, color=blue, fontcolor=blue];")
            boxes = {m.group(1) for t in text[2:ellipses] if (m := _QUOTED.match(t))}
            kind = "link" if name.group(1) in boxes else "joint"
            where = f" at {kind} '{name.group(1)}'"
    return ModelError(
        f"graphviz dot failed{where}: {reason}",
        path=gv_path,
        line=line if gv_path is not None else None,
        hint="the .gv file is kept; fix that name in the model",
    )


def write_graph(
    document: UrdfDocument,
    gv_path: str | os.PathLike[str],
    out_path: str | os.PathLike[str] | None,
    fmt: str | None = None,
) -> list[Path]:
    """Write the ``.gv`` file and, unless ``out_path`` is None, its rendering.

    Neither folder is created, and an existing file is replaced only by one of its
    kind (:mod:`workbench.output_files`).

    Returns:
        The files written, ``.gv`` first.

    Raises:
        ModelError: A missing folder, someone else's file, a failed write or a failed dot.
    """
    gv_path = check_output(gv_path, "graphviz", error=ModelError)
    source = graph_source(document)
    if out_path is not None:
        out_path = Path(out_path)
        fmt = fmt or out_path.suffix.lstrip(".").lower() or "pdf"
        if fmt not in FORMATS:
            raise ModelError(f"unknown graph format '{fmt}'", hint="use " + ", ".join(FORMATS))
        out_path = check_output(out_path, fmt, error=ModelError)
    written = [write_output(gv_path, source, error=ModelError)]
    if out_path is not None:
        data = render_source(source, fmt or "pdf", gv_path)
        written.append(write_output(out_path, data, error=ModelError))
    return written


def read_graph_document(source: str | os.PathLike[str]) -> UrdfDocument:
    """Find and read a URDF (or xacro) for drawing, as urdf_to_graphviz reads it.

    Malformed shapes or inertia do not matter to the graph (ROS's parser skips
    them too), so they are not errors here; ``workbench check`` reports them.

    Raises:
        ModelError: Not found, unreadable, SDF, or not a readable URDF.
    """
    path = resolve_robot_path(source)
    text = read_description(path)
    if text.format != "urdf":
        raise UrdfSyntaxError("this is an SDF file; only URDF can be drawn", path=path)
    return parse_urdf_text(text.text, path, strict=False)
