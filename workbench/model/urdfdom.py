"""What ROS's URDF parser (urdfdom 3.0.1) makes of a description.

``check_urdf`` and ``urdf_to_graphviz`` print what urdfdom's ``parseURDF``
builds: its log lines (console_bridge ``Error:``/``Warning:`` on stderr), and
either nothing (it refused the file) or a model whose tree they print. This
module reproduces that outcome from the parsed XML, so ``workbench check``
and ``workbench graph`` print the same tree and ``.gv`` text as the ROS tools:

* materials, then links, then joints are read in file order; a malformed
  ``<inertial>``, ``<visual>`` or ``<collision>`` is logged and the rest of
  that link skipped, but the link is kept; a malformed joint, a duplicate
  name, an unknown link or a second root refuses the whole file;
* numbers are read as C++ ``std::stringstream >> double`` reads them (no
  ``inf``/``nan``, no trailing characters), vectors split on single spaces;
* children are ordered by joint name (urdfdom keeps joints in a ``std::map``),
  the root is the first parentless link by name;
* joint origins are kept as a quaternion and printed back as roll, pitch and
  yaw the way urdfdom's ``Rotation::getRPY`` recovers them, with C++ stream
  formatting (6 significant digits, ``-0`` kept).

This module holds the outcome (:class:`RosModel`: log lines, tree lines, ``.gv``
text) and urdfdom's numbers and rotations; :func:`~workbench.model.urdfdom_reader.read_ros_model`
reads a file's ``<robot>`` element into it. Nothing here loads or runs anything
from the file: it only reads the tree.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator
from dataclasses import dataclass, field

#: The line check_urdf and urdf_to_graphviz print when urdfdom refused the file.
REFUSED = "ERROR: Model Parsing the xml failed"

_DOUBLE = re.compile(r"[ \t\n\v\f\r]*[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_HALF_PI = 1.57079632679489661923


class InvalidValue(ValueError):
    """A value urdfdom cannot read; the message is urdfdom's."""


@dataclass(frozen=True)
class RosMessage:
    """One line urdfdom logs (console_bridge prints Warning and Error).

    Attributes:
        level: ``"Error"`` or ``"Warning"``.
        text: urdfdom's message.
        element: What it is about, in workbench's words (``link 'arm'``).
        line: The line of that element in the file, if known.
        tree: True for the tree urdfdom builds from the links and joints it read
            (unknown links, several roots, no root).
    """

    level: str
    text: str
    element: str
    line: int | None = None
    tree: bool = False

    @property
    def one_line(self) -> str:
        """The text with tabs and line breaks (from attribute values) shown as escapes."""
        return self.text.replace("\r", "\\r").replace("\n", "\\n").replace("\t", "\\t")

    def format(self) -> str:
        """The line as console_bridge prints it (without its C++ source location line)."""
        return f"{self.level}:{' ' * (9 - len(self.level) - 1)}{self.text}"


@dataclass(frozen=True)
class RosJoint:
    """A joint as urdfdom keeps it: its links and its origin (position and quaternion)."""

    name: str
    parent: str
    child: str
    xyz: tuple[float, float, float]
    quaternion: tuple[float, float, float, float]  # x, y, z, w

    @property
    def rpy(self) -> tuple[float, float, float]:
        """Roll, pitch and yaw as urdfdom recovers them from the quaternion."""
        return quaternion_to_rpy(self.quaternion)


@dataclass
class RosModel:
    """urdfdom's outcome for one file.

    Attributes:
        name: The robot name.
        messages: What urdfdom logs, in order.
        refused: True when urdfdom gives up on the file (the tools print the tree of nothing).
        root: The root link (None when refused).
        children: Link -> its child joints in urdfdom's order (joint name).
        endless: A link the ROS tools would reach again below itself, recursing until
            they crash; None when the tree can be walked.
    """

    name: str
    messages: list[RosMessage] = field(default_factory=list)
    refused: bool = False
    root: str | None = None
    children: dict[str, list[RosJoint]] = field(default_factory=dict)
    endless: str | None = None

    @property
    def printable(self) -> bool:
        """True when check_urdf prints a tree (it parsed, and the walk ends)."""
        return not self.refused and self.root is not None and self.endless is None

    def stderr_lines(self) -> list[str]:
        """urdfdom's log lines, then check_urdf's final error line when it refused the file."""
        lines = [message.format() for message in self.messages]
        if self.refused:
            lines.append(REFUSED)
        return lines

    def tree_lines(self) -> list[str]:
        """check_urdf's stdout: name, banner, root and the indented children (empty if refused)."""
        if not self.printable or self.root is None:
            return []
        lines = [
            f"robot name is: {self.name}",
            "---------- Successfully Parsed XML ---------------",
            f"root Link: {self.root} has {len(self.children.get(self.root, []))} child(ren)",
        ]
        for depth, index, joint in self._walk(self.root, 1):
            lines.append("    " * depth + f"child({index}):  {joint.child}")
        return lines

    def graph_source(self) -> str:
        """urdf_to_graphviz's ``.gv`` text.

        Raises:
            ValueError: urdfdom refused the file or its tree does not end.
        """
        if not self.printable or self.root is None:
            raise ValueError("urdfdom has no tree for this file")
        root = dot_quoted(self.root)
        lines = ["digraph G {", "node [shape=box];", f'"{root}" [label="{root}"];']
        walk = list(self._walk(self.root, 1))
        parent_joints = self.parent_joints()
        lines += [f'"{dot_quoted(j.child)}" [label="{dot_quoted(j.child)}"];' for _, _, j in walk]
        lines.append("node [shape=ellipse, color=blue, fontcolor=blue];")
        for _, _, joint in walk:
            # urdf_to_graphviz labels the edge with the child's parent joint: for a link
            # with two parents, the joint urdfdom read last (by name) on both edges.
            shown = parent_joints[joint.child]
            xyz = " ".join(cpp_double(value) for value in shown.xyz)
            rpy = " ".join(cpp_double(value) for value in shown.rpy)
            label = f"xyz: {xyz} \\nrpy: {rpy}"
            parent, name, child = (dot_quoted(n) for n in (joint.parent, shown.name, joint.child))
            lines.append(f'"{parent}" -> "{name}" [label="{label}"]')
            lines.append(f'"{name}" -> "{child}"')
        lines.append("}")
        return "\n".join(lines) + "\n"

    def joints_depth_first(self) -> list[RosJoint]:
        """The joints below the root, depth first, children in urdfdom's order."""
        return [joint for _, _, joint in self._walk(self.root, 1)] if self.root else []

    def parent_joints(self) -> dict[str, RosJoint]:
        """Link -> the joint urdfdom records as its parent: of several, the last by name."""
        joints = [joint for siblings in self.children.values() for joint in siblings]
        return {joint.child: joint for joint in sorted(joints, key=lambda joint: joint.name)}

    def _walk(self, link: str, depth: int) -> Iterator[tuple[int, int, RosJoint]]:
        """Depth first: (depth, 1-based index among its siblings, joint to the child)."""

        def below(parent: str, level: int) -> list[tuple[int, int, RosJoint]]:
            joints = enumerate(self.children.get(parent, []), start=1)
            return [(level, index, joint) for index, joint in joints][::-1]

        stack = below(link, depth)
        while stack:
            level, index, joint = stack.pop()
            yield level, index, joint
            stack += below(joint.child, level + 1)


def dot_quoted(name: str) -> str:
    """``name`` for the inside of a double-quoted graphviz string.

    urdf_to_graphviz writes names raw, so a link called ``x" shape=none image="/etc/passwd``
    would add attributes to the graph; here quotes and backslashes are escaped and line
    breaks written as ``\\n``. Ordinary names are unchanged, so the ``.gv`` stays ROS's.
    """
    return (
        name.replace("\\", "\\\\")
        .replace('"', '\\"')
        .replace("\r\n", "\\n")
        .replace("\n", "\\n")
        .replace("\r", "\\n")
    )


def cpp_double(value: float) -> str:
    """``value`` as a C++ ostream prints a double by default (6 significant digits, ``-0``)."""
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return f"{value:g}"


def rpy_to_quaternion(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """urdfdom's ``Rotation::setFromRPY`` (then normalised): (x, y, z, w)."""
    phi, the, psi = roll / 2.0, pitch / 2.0, yaw / 2.0
    s_phi, c_phi = math.sin(phi), math.cos(phi)
    s_the, c_the = math.sin(the), math.cos(the)
    s_psi, c_psi = math.sin(psi), math.cos(psi)
    x = s_phi * c_the * c_psi - c_phi * s_the * s_psi
    y = c_phi * s_the * c_psi + s_phi * c_the * s_psi
    z = c_phi * c_the * s_psi - s_phi * s_the * c_psi
    w = c_phi * c_the * c_psi + s_phi * s_the * s_psi
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    if norm == 0.0:
        return 0.0, 0.0, 0.0, 1.0
    return x / norm, y / norm, z / norm, w / norm


def quaternion_to_rpy(quaternion: tuple[float, float, float, float]) -> tuple[float, float, float]:
    """urdfdom's ``Rotation::getRPY``: pitch is clamped to ±pi/2 near the poles."""
    x, y, z, w = quaternion
    sine_pitch = -2 * (x * z - w * y)
    if sine_pitch <= -0.99999:
        return 0.0, -_HALF_PI, 2 * math.atan2(x, -y)
    if sine_pitch >= 0.99999:
        return 0.0, _HALF_PI, 2 * math.atan2(-x, y)
    xx, yy, zz, ww = x * x, y * y, z * z, w * w
    roll = math.atan2(2 * (y * z + w * x), ww - xx - yy + zz)
    yaw = math.atan2(2 * (x * y + w * z), ww + xx - yy - zz)
    return roll, math.asin(sine_pitch), yaw


def ros_double(text: str) -> float:
    """A number as urdfdom's ``strToDouble`` reads it (C locale stream, nothing after it).

    Raises:
        InvalidValue: Not a number there, trailing characters, or out of range.
    """
    if _DOUBLE.fullmatch(text) is None:
        raise InvalidValue(text)
    value = float(text)
    if math.isinf(value):
        raise InvalidValue(text)
    return value


def ros_vector(text: str) -> tuple[float, ...]:
    """urdfdom's ``Vector3::init``: split on single spaces, exactly three numbers."""
    values = []
    for piece in text.split(" "):
        if piece == "":
            continue
        try:
            values.append(ros_double(piece))
        except InvalidValue:
            raise InvalidValue(
                f"Unable to parse component [{piece}] to a double (while parsing a vector value)"
            ) from None
    if len(values) != 3:
        raise InvalidValue(
            f"Parser found {len(values)} elements but 3 expected while parsing vector [{text}]"
        )
    return tuple(values)
