"""Read a URDF file into plain records, keeping the line of every element.

This is workbench's own reading of the XML (with lxml), used for the
``check`` report, the graph, and the :class:`JointInfo`/:class:`LinkInfo`
lists of a loaded robot. Drake reads the same text separately to build the
plant. Only problems that make the file unreadable raise here; everything a
model can get *wrong* while still being readable is left to
:mod:`workbench.model.check`.
"""

from __future__ import annotations

import contextlib
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from lxml import etree

from workbench import spatial
from workbench.errors import ModelError
from workbench.model.findings import Finding
from workbench.model.info import JointInfo, LinkInfo
from workbench.model.limits import shown_name, xml_error_text

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")


class UrdfSyntaxError(ModelError):
    """The file is not a readable URDF (bad XML, missing names, bad numbers)."""


class _Dropped(Exception):
    """A malformed element inside a link, skipped when reading tolerantly."""


@dataclass
class Geometry:
    """A ``<geometry>`` child: box, cylinder, sphere, capsule or mesh (sizes in metres)."""

    kind: str
    line: int | None
    size: tuple[float, ...] = ()
    filename: str | None = None
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def to_shape(self) -> spatial.Shape | None:
        """The geometry in the :mod:`workbench.spatial` vocabulary (None for a capsule).

        A mesh keeps the file name as written (``package://`` URIs are not resolved).

        Raises:
            SpatialError: Sizes that are not positive.
        """
        if self.kind == "box":
            return spatial.make_shape("box", size=self.size)
        if self.kind == "cylinder":
            return spatial.make_shape("cylinder", radius=self.size[0], length=self.size[1])
        if self.kind == "sphere":
            return spatial.make_shape("sphere", radius=self.size[0])
        if self.kind == "mesh":
            return spatial.make_shape("mesh", filename=self.filename, scale=self.scale)
        return None


@dataclass
class Shape:
    """A ``<visual>`` or ``<collision>`` element."""

    line: int | None
    geometry: Geometry | None
    xyz: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rpy: np.ndarray = field(default_factory=lambda: np.zeros(3))
    material: str | None = None
    rgba: tuple[float, float, float, float] | None = None
    material_line: int | None = None


@dataclass
class Inertial:
    """An ``<inertial>`` element: mass (kg) and inertia (kg m^2) about the centre of mass."""

    line: int | None
    mass: float | None
    inertia: np.ndarray | None
    xyz: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rpy: np.ndarray = field(default_factory=lambda: np.zeros(3))
    mass_line: int | None = None
    inertia_line: int | None = None


@dataclass
class Link:
    """A ``<link>`` element."""

    name: str
    line: int | None
    visuals: list[Shape] = field(default_factory=list)
    collisions: list[Shape] = field(default_factory=list)
    inertial: Inertial | None = None

    def info(self) -> LinkInfo:
        mass = self.inertial.mass if self.inertial is not None else None
        return LinkInfo(self.name, bool(self.visuals), bool(self.collisions), mass, self.line)


@dataclass
class Material:
    """A named ``<material>`` at robot level."""

    name: str
    line: int | None
    rgba: tuple[float, float, float, float] | None
    texture: str | None = None


@dataclass
class UrdfDocument:
    """Everything workbench reads from one URDF file.

    ``problems`` lists the malformed elements inside links that a tolerant read
    (``parse_urdf_text(..., strict=False)``) skipped, as ROS's parser skips them.
    """

    path: Path | None
    name: str
    links: list[Link]
    joints: list[JointInfo]
    materials: dict[str, Material]
    root: etree._Element
    duplicate_materials: list[Material] = field(default_factory=list)
    problems: list[Finding] = field(default_factory=list)

    def link(self, name: str) -> Link | None:
        return next((link for link in self.links if link.name == name), None)

    def joint(self, name: str) -> JointInfo | None:
        return next((joint for joint in self.joints if joint.name == name), None)

    def element_at(self, line: int | None) -> str:
        """``link 'x'`` or ``joint 'y'`` for the element on ``line`` (``model`` if none)."""
        if line is None:
            return "model"
        elements = [e for e in self.root.iter() if isinstance(e.tag, str) and e.sourceline]
        # lxml gives the line a start tag ends on, Drake the one it starts on: a tag whose
        # attributes span lines is the first element at or after ``line``.
        at = [e for e in elements if e.sourceline == line] or [
            e for e in elements if e.sourceline > line
        ][:1]
        for element in at:
            if element.tag in ("link", "joint"):
                return f"{element.tag} '{element.get('name')}'"
            for ancestor in element.iterancestors():
                if ancestor.tag in ("link", "joint"):
                    return f"{ancestor.tag} '{ancestor.get('name')}'"
        return "model"

    def link_infos(self) -> list[LinkInfo]:
        return [link.info() for link in self.links]

    def to_string(self) -> str:
        return etree.tostring(self.root, encoding="unicode")


class _Reader:
    def __init__(self, path: Path | None, strict: bool = True) -> None:
        self.path = path
        self.strict = strict
        self.problems: list[Finding] = []
        self.link_label: str | None = None  # set while reading the inside of a link

    def fail(self, message: str, element: etree._Element | None, hint: str | None = None):
        """Raise :class:`UrdfSyntaxError`; inside a link when tolerant, record and drop instead."""
        line = element.sourceline if element is not None else None
        if self.strict or self.link_label is None:
            raise UrdfSyntaxError(message, path=self.path, line=line, hint=hint)
        label = self.link_label
        if hint is None:
            hint = (
                "ROS's parser skips this element and the rest of the link; fix it"
                if label.startswith("link")
                else "ROS's parser ignores this colour; fix it"
            )
        problem = Finding(
            "error", "malformed-element", label, message.removeprefix(label).strip(), hint, line
        )
        self.problems.append(problem)
        raise _Dropped(message)

    def finite(self, element, what: str, values: dict[str, float]) -> None:
        """Sizes must be finite numbers (ROS cannot read inf either); a size of zero or
        less is read as ROS reads it, and left out of what Drake gets
        (:mod:`workbench.model.urdf_for_drake`)."""
        for key, value in values.items():
            if not math.isfinite(value):
                self.fail(
                    f"{what}: {key} {value:g} is not a finite number",
                    element,
                    hint="give the shape's real size in metres",
                )

    def floats(self, element, attribute: str, count: int | None, what: str, default=None):
        text = element.get(attribute)
        if text is None:
            if default is not None:
                return default
            self.fail(f"{what} has no '{attribute}' attribute", element)
        parts = text.split()
        try:
            values = tuple(float(part) for part in parts)
        except ValueError:
            self.fail(
                f'{what}: {attribute}="{text}" is not a number',
                element,
                hint="write plain decimal numbers separated by spaces",
            )
        if count is not None and len(values) != count:
            self.fail(
                f'{what}: {attribute}="{text}" needs {count} numbers, found {len(values)}',
                element,
            )
        if any(math.isnan(value) for value in values):
            self.fail(f'{what}: {attribute}="{text}" contains NaN', element)
        if self.strict and any(math.isinf(value) for value in values):
            self.fail(
                f'{what}: {attribute}="{text}" is not a finite number',
                element,
                hint="write finite numbers; ROS cannot read inf either",
            )
        return values

    def origin(self, parent, what: str) -> tuple[np.ndarray, np.ndarray]:
        origin = parent.find("origin")
        if origin is None:
            return np.zeros(3), np.zeros(3)
        xyz = self.floats(origin, "xyz", 3, f"{what} <origin>", default=(0.0, 0.0, 0.0))
        rpy = self.floats(origin, "rpy", 3, f"{what} <origin>", default=(0.0, 0.0, 0.0))
        return np.array(xyz), np.array(rpy)

    def rgba(self, material, what: str):
        """The colour; as in urdfdom, an ``rgba`` without four numbers is opaque black."""
        color = material.find("color")
        if color is None:
            return None
        values = self.floats(color, "rgba", None, f"{what} <color>")
        return values if len(values) == 4 else (0.0, 0.0, 0.0, 1.0)

    def geometry(self, shape, what: str) -> Geometry | None:
        geometry = shape.find("geometry")
        if geometry is None:
            return None
        children = [child for child in geometry if isinstance(child.tag, str)]
        if not children:
            self.fail(
                f"{what} <geometry> is empty", geometry, hint="add a box, cylinder, sphere or mesh"
            )
        child = children[0]
        kind = child.tag
        where = f"{what} <{kind}>"
        if kind == "box":
            size = self.floats(child, "size", 3, where)
            self.finite(child, where, dict(zip(("width", "depth", "height"), size, strict=True)))
            return Geometry(kind, child.sourceline, size)
        if kind in ("cylinder", "capsule"):
            radius = self.floats(child, "radius", 1, where)[0]
            length = self.floats(child, "length", 1, where)[0]
            self.finite(child, where, {"radius": radius, "length": length})
            return Geometry(kind, child.sourceline, (radius, length))
        if kind == "sphere":
            radius = self.floats(child, "radius", 1, where)
            self.finite(child, where, {"radius": radius[0]})
            return Geometry(kind, child.sourceline, radius)
        if kind == "mesh":
            filename = child.get("filename")
            if not filename:
                self.fail(f"{where} has no 'filename' attribute", child)
            scale = self.floats(child, "scale", 3, where, default=(1.0, 1.0, 1.0))
            if not all(math.isfinite(value) for value in scale):
                self.fail(
                    f'{where}: scale="{child.get("scale")}" is not a finite number',
                    child,
                    hint="scale every axis by a finite, non-zero factor",
                )
            return Geometry(kind, child.sourceline, (), filename, scale)
        self.fail(
            f"{what}: unknown geometry <{kind}>",
            child,
            hint="use box, cylinder, sphere or mesh",
        )
        return None

    def shape(self, element, what: str) -> Shape:
        xyz, rpy = self.origin(element, what)
        shape = Shape(element.sourceline, self.geometry(element, what), xyz, rpy)
        material = element.find("material")
        if material is not None:
            shape.material = material.get("name")
            shape.material_line = material.sourceline
            shape.rgba = self.rgba(material, f"{what} <material>")
        return shape

    def inertial(self, element, what: str) -> Inertial:
        xyz, rpy = self.origin(element, f"{what} <inertial>")
        result = Inertial(element.sourceline, None, None, xyz, rpy)
        mass = element.find("mass")
        if mass is not None:
            result.mass = self.floats(mass, "value", 1, f"{what} <mass>")[0]
            result.mass_line = mass.sourceline
        inertia = element.find("inertia")
        if inertia is not None:
            names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
            values = {
                name: self.floats(inertia, name, 1, f"{what} <inertia>", default=(0.0,))[0]
                for name in names
            }
            result.inertia = np.array(
                [
                    [values["ixx"], values["ixy"], values["ixz"]],
                    [values["ixy"], values["iyy"], values["iyz"]],
                    [values["ixz"], values["iyz"], values["izz"]],
                ]
            )
            result.inertia_line = inertia.sourceline
        return result

    def link(self, element) -> Link:
        name = element.get("name")
        if not name:
            self.fail("<link> has no name", element, hint='add name="..."')
        what = f"link '{shown_name(name, 80)}'"
        link = Link(name, element.sourceline)
        self.link_label = what
        try:
            for index, visual in enumerate(element.iterchildren("visual")):
                with contextlib.suppress(_Dropped):
                    link.visuals.append(self.shape(visual, f"{what} <visual> #{index + 1}"))
            for index, collision in enumerate(element.iterchildren("collision")):
                with contextlib.suppress(_Dropped):
                    link.collisions.append(
                        self.shape(collision, f"{what} <collision> #{index + 1}")
                    )
            inertial = element.find("inertial")
            if inertial is not None:
                with contextlib.suppress(_Dropped):
                    link.inertial = self.inertial(inertial, what)
        finally:
            self.link_label = None
        return link

    def joint(self, element) -> JointInfo:
        name = element.get("name")
        if not name:
            self.fail("<joint> has no name", element, hint='add name="..."')
        what = f"joint '{shown_name(name, 80)}'"
        kind = element.get("type")
        if kind not in JOINT_TYPES:
            self.fail(
                f"{what} has type {kind!r}" if kind else f"{what} has no type",
                element,
                hint="use one of " + ", ".join(JOINT_TYPES),
            )
        ends = {}
        for end in ("parent", "child"):
            tag = element.find(end)
            if tag is None or not tag.get("link"):
                self.fail(
                    f'{what} has no <{end} link="..."/>',
                    tag if tag is not None else element,
                    hint=f"every joint names its {end} link",
                )
            ends[end] = tag.get("link")
        xyz, rpy = self.origin(element, what)
        axis = np.array([1.0, 0.0, 0.0])
        axis_element = element.find("axis")
        # A fixed or floating joint has no axis: ROS never reads it.
        if axis_element is not None and kind not in ("fixed", "floating"):
            axis = np.array(self.floats(axis_element, "xyz", 3, f"{what} <axis>", (1.0, 0.0, 0.0)))
        limits: dict[str, float | None] = dict.fromkeys(("lower", "upper", "velocity", "effort"))
        limit = element.find("limit")
        if limit is not None:
            for key in limits:
                if limit.get(key) is not None:
                    limits[key] = self.floats(limit, key, 1, f"{what} <limit>")[0]
            # As Drake gets them (workbench.model.urdf_for_drake): ROS ignores a continuous
            # joint's bounds, reversed ones are swapped, speeds and efforts are magnitudes.
            if kind == "continuous":
                limits["lower"] = limits["upper"] = None
            else:
                lower = 0.0 if limits["lower"] is None else limits["lower"]
                upper = 0.0 if limits["upper"] is None else limits["upper"]
                limits["lower"], limits["upper"] = min(lower, upper), max(lower, upper)
            for key in ("velocity", "effort"):
                value = limits[key]
                limits[key] = abs(value) if value is not None else None
        return JointInfo(
            name,
            kind,
            ends["parent"],
            ends["child"],
            axis,
            xyz,
            rpy,
            limits["lower"],
            limits["upper"],
            limits["velocity"],
            limits["effort"],
            element.sourceline,
        )


_DECLARATION_START = re.compile(rb"<\?xml[\s?]")
_STANDARD_DECLARATION = re.compile(rb"<\?xml\s+version\s*=\s*[\"']1\.[0-9]+[\"']")


def _lenient_prolog(data: bytes) -> tuple[bytes, int]:
    """Blank the XML declarations lxml refuses but ROS's parser (TinyXML) reads past.

    A declaration after a comment, or with a version other than 1.x (PyBullet's
    URDFs begin ``<?xml version="0.0"?>``), is replaced by spaces before the
    first element; newlines are kept, so line numbers stay those of the file.

    Returns:
        The text, and where its first element (or doctype) starts.
    """
    index = 3 if data.startswith(b"\xef\xbb\xbf") else 0
    while index < len(data):
        while index < len(data) and data[index : index + 1].isspace():
            index += 1
        if data.startswith(b"<!--", index):
            end = data.find(b"-->", index + 4)
            index = len(data) if end < 0 else end + 3
        elif _DECLARATION_START.match(data, index):
            end = data.find(b"?>", index)
            if end < 0:
                break
            end += 2
            at_start = index == (3 if data.startswith(b"\xef\xbb\xbf") else 0)
            if not (at_start and _STANDARD_DECLARATION.match(data, index)):
                blank = bytes(b if b in b"\r\n" else 32 for b in data[index:end])
                data = data[:index] + blank + data[end:]
            index = end
        elif data.startswith(b"<?", index):
            end = data.find(b"?>", index)
            index = len(data) if end < 0 else end + 2
        else:
            break
    return data, index


_START_TAG = re.compile(
    rb"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<[?!][^>]*>"
    rb"|<[A-Za-z_:][^\s/>]*(?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*\s*/?>",
    re.DOTALL,
)
_ATTRIBUTE_VALUE = re.compile(rb"\"[^\"]*\"|'[^']*'")


def _keep_attribute_whitespace(data: bytes) -> bytes:
    """Keep tabs and line breaks inside attribute values, as ROS's parser does.

    An XML parser turns them into spaces, so ``xyz="0<newline>0 1"`` would read
    as three numbers where ROS finds "0<newline>0" and refuses the joint. They
    become character references (which XML keeps), and each line break moves
    just behind the value, so line numbers stay those of the file.
    """

    def value(match: re.Match[bytes]) -> bytes:
        text = match.group()
        if not any(c in text for c in b"\t\n\r"):
            return text
        kept = text.replace(b"\t", b"&#9;").replace(b"\r", b"&#13;").replace(b"\n", b"&#10;")
        return kept + b"\n" * text.count(b"\n")

    def tag(match: re.Match[bytes]) -> bytes:
        text = match.group()
        if text.startswith((b"<!", b"<?")):
            return text
        return _ATTRIBUTE_VALUE.sub(value, text)

    return _START_TAG.sub(tag, data)


_UNDECLARED = re.compile(r"Namespace prefix ([A-Za-z_][\w.-]*) (?:on|for) ")
_ROOT_TAG = re.compile(rb"<[^\s/>?!]+")


def _parse_xml(data: bytes, start: int, parser: etree.XMLParser) -> etree._Element:
    """Parse the XML; prefixes never declared (``<sensor:camera>``) are declared on the root.

    ROS's parser does not know namespaces, so old URDFs with Gazebo's undeclared
    ``sensor:`` or ``controller:`` tags load in ROS; the tags keep their prefix here.
    """
    for _ in range(32):
        try:
            return etree.fromstring(data, parser)
        except etree.XMLSyntaxError as error:
            match = _UNDECLARED.match(str(error.msg or ""))
            root = _ROOT_TAG.match(data, start)
            if match is None or root is None:
                raise
            prefix = match.group(1).encode()
            declaration = b' xmlns:%s="urn:undeclared:%s"' % (prefix, prefix)
            data = data[: root.end()] + declaration + data[root.end() :]
    return etree.fromstring(data, parser)


def parse_urdf_text(
    text: str | bytes, path: Path | None = None, *, strict: bool = True
) -> UrdfDocument:
    """Parse URDF text into a :class:`UrdfDocument`.

    Args:
        text: The XML.
        path: The file it came from, used in error messages and to resolve meshes.
        strict: Raise on the first malformed element. When False, a malformed
            ``<visual>``, ``<collision>``, ``<inertial>`` or robot-level ``<material>``
            is skipped and listed in ``document.problems``, as ROS's parser skips it;
            everything else still raises.

    Raises:
        UrdfSyntaxError: Empty text, bad XML, no ``<robot>``, missing names, bad numbers,
            shape sizes Drake cannot build.
    """
    reader = _Reader(path, strict)
    data = text.encode() if isinstance(text, str) else text
    if not data.strip():
        raise UrdfSyntaxError(
            "the file is empty", path=path, hint='a URDF starts with <robot name="...">'
        )
    parser = etree.XMLParser(
        remove_blank_text=False, huge_tree=True, resolve_entities=False, no_network=True
    )
    try:
        root = _parse_xml(*_lenient_prolog(_keep_attribute_whitespace(data)), parser)
    except etree.XMLSyntaxError as error:
        message = xml_error_text(str(error.msg or error))
        raise UrdfSyntaxError(
            f"not well-formed XML: {message}",
            path=path,
            line=error.lineno,
            hint="fix the XML syntax at that line",
        ) from None
    if root.tag != "robot":
        raise UrdfSyntaxError(
            f"the top element is <{root.tag}>, not <robot>",
            path=path,
            line=root.sourceline,
            hint='a URDF file has one <robot name="..."> element around its links and joints',
        )
    name = root.get("name")
    if not name:
        reader.fail("<robot> has no name", root, hint='write <robot name="my_robot">')
    materials: dict[str, Material] = {}
    duplicates: list[Material] = []
    for element in root.iterchildren("material"):
        material_name = element.get("name") or ""
        texture = element.find("texture")
        reader.link_label = f"material '{shown_name(material_name, 80)}'"
        try:
            if element.get("name") is None:
                reader.fail("<material> has no name", element, hint='add name="..."')
            rgba = reader.rgba(element, f"material '{shown_name(material_name, 80)}'")
        except _Dropped:
            if element.get("name") is None:
                continue
            rgba = None
        finally:
            reader.link_label = None
        material = Material(
            material_name,
            element.sourceline,
            rgba,
            texture.get("filename") if texture is not None else None,
        )
        if material_name in materials:
            duplicates.append(material)
        else:
            materials[material_name] = material
    links = [reader.link(element) for element in root.iterchildren("link")]
    joints = [reader.joint(element) for element in root.iterchildren("joint")]
    # Materials defined inside a visual are usable by later links too.
    for link in links:
        for shape in link.visuals:
            if shape.material and shape.rgba is not None and shape.material not in materials:
                materials[shape.material] = Material(
                    shape.material, shape.material_line, shape.rgba
                )
    return UrdfDocument(path, name, links, joints, materials, root, duplicates, reader.problems)


def parse_urdf_file(path: str | Path, *, strict: bool = True) -> UrdfDocument:
    """Read and parse a URDF file (see :func:`parse_urdf_text`)."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as error:
        raise ModelError(f"cannot read the file: {error.strerror}", path=path) from None
    return parse_urdf_text(data, path, strict=strict)
