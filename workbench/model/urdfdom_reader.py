"""urdfdom 3.0.1's ``parseURDF``, step by step, over an lxml tree (see :mod:`.urdfdom`).

Each element is read in urdfdom's order with urdfdom's checks, and every line
urdfdom logs is collected with the element it concerns. The outcome is a
:class:`~workbench.model.urdfdom.RosModel`.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator

from lxml import etree

from workbench.model.urdfdom import (
    InvalidValue,
    RosJoint,
    RosMessage,
    RosModel,
    ros_double,
    ros_vector,
    rpy_to_quaternion,
)

_LONG = re.compile(r"[ \t\n\v\f\r]*[+-]?[0-9]+")


class _Refused(Exception):
    """urdfdom gives up on the whole file."""


def _tag(element: etree._Element) -> str:
    """The element name as TinyXML sees it (``prefix:name``)."""
    local = etree.QName(element).localname
    return f"{element.prefix}:{local}" if element.prefix else local


def _elements(parent: etree._Element, name: str | None = None) -> Iterator[etree._Element]:
    for child in parent:
        if isinstance(child.tag, str) and (name is None or _tag(child) == name):
            yield child


def _first(parent: etree._Element, name: str | None = None) -> etree._Element | None:
    return next(_elements(parent, name), None)


class _Parser:
    """One run of urdfdom's parseURDF over an lxml tree, collecting its log."""

    def __init__(self, robot: etree._Element, name: str) -> None:
        self.robot = robot
        self.model = RosModel(name)
        self.element = f"robot '{name}'"
        self.line: int | None = robot.sourceline
        self.building_tree = False

    def log(self, text: str, level: str = "Error") -> None:
        message = RosMessage(level, text, self.element, self.line, self.building_tree)
        self.model.messages.append(message)

    def about(self, element: str, xml: etree._Element) -> None:
        self.element, self.line = element, xml.sourceline

    def refuse(self, text: str) -> _Refused:
        self.log(text)
        return _Refused(text)

    # --- numbers and poses ----------------------------------------------------------

    def number(self, xml: etree._Element, attribute: str, message: str) -> float | None:
        """The attribute as a double; logs ``message`` (``{}`` = the text) when invalid."""
        text = xml.get(attribute)
        if text is None:
            return None
        try:
            return ros_double(text)
        except InvalidValue:
            self.log(message.format(text))
            raise

    def pose(self, xml: etree._Element | None) -> tuple[tuple[float, ...], tuple[float, ...]]:
        xyz: tuple[float, ...] = (0.0, 0.0, 0.0)
        quaternion: tuple[float, ...] = (0.0, 0.0, 0.0, 1.0)
        if xml is None:
            return xyz, quaternion
        try:
            if xml.get("xyz") is not None:
                xyz = ros_vector(xml.get("xyz", ""))
            if xml.get("rpy") is not None:
                roll, pitch, yaw = ros_vector(xml.get("rpy", ""))
                quaternion = rpy_to_quaternion(roll, pitch, yaw)
        except InvalidValue as error:
            self.log(str(error))
            raise
        return xyz, quaternion

    # --- materials ------------------------------------------------------------------

    def material(self, xml: etree._Element, only_name_is_ok: bool) -> bool:
        name = xml.get("name")
        if name is None:
            self.log("Material must contain a name attribute")
            return False
        texture = _first(xml, "texture")
        has_texture = texture is not None and texture.get("filename") is not None
        has_colour = False
        color = _first(xml, "color")
        if color is not None and color.get("rgba") is not None:
            for piece in color.get("rgba", "").split(" "):
                if piece == "":
                    continue
                try:
                    value = ros_double(piece)
                    if not 0 <= value <= 1:
                        raise InvalidValue(piece)
                except InvalidValue:
                    self.log(
                        f"Material [{name}] has malformed color rgba values: Unable to parse "
                        f"component [{piece}] to a double (while parsing a color value)"
                    )
                    break
            else:
                has_colour = True
        if not has_colour and not has_texture:
            if not only_name_is_ok:
                self.log(f"Material [{name}] color has no rgba")
                self.log(f"Material [{name}] not defined in file")
            return False
        return True

    # --- links ----------------------------------------------------------------------

    def geometry(self, xml: etree._Element | None) -> None:
        if xml is None:
            raise InvalidValue("no geometry")
        shape = _first(xml)
        if shape is None:
            self.log("Geometry tag contains no child element.")
            raise InvalidValue("empty geometry")
        kind = _tag(shape)
        if kind == "sphere":
            if shape.get("radius") is None:
                self.log("Sphere shape must have a radius attribute")
                raise InvalidValue(kind)
            self.number(shape, "radius", "radius [{}] is not a valid float")
        elif kind == "box":
            if shape.get("size") is None:
                self.log("Box shape has no size attribute")
                raise InvalidValue(kind)
            try:
                ros_vector(shape.get("size", ""))
            except InvalidValue as error:
                self.log(str(error))
                raise
        elif kind == "cylinder":
            if shape.get("length") is None or shape.get("radius") is None:
                self.log("Cylinder shape must have both length and radius attributes")
                raise InvalidValue(kind)
            self.number(shape, "length", "length [{}] is not a valid float")
            self.number(shape, "radius", "radius [{}] is not a valid float")
        elif kind == "mesh":
            if shape.get("filename") is None:
                self.log("Mesh must contain a filename attribute")
                raise InvalidValue(kind)
            if shape.get("scale") is not None:
                try:
                    ros_vector(shape.get("scale", ""))
                except InvalidValue as error:
                    self.log(f"Mesh scale was specified, but could not be parsed: {error}")
                    raise
        else:
            self.log(f"Unknown geometry type '{kind}'")
            raise InvalidValue(kind)

    def inertial(self, xml: etree._Element) -> None:
        self.pose(_first(xml, "origin"))
        mass = _first(xml, "mass")
        if mass is None:
            self.log("Inertial element must have a mass element")
            raise InvalidValue("mass")
        if mass.get("value") is None:
            self.log("Inertial: mass element must have value attribute")
            raise InvalidValue("mass")
        self.number(mass, "value", "Inertial: mass [{}] is not a float")
        inertia = _first(xml, "inertia")
        if inertia is None:
            self.log("Inertial element must have inertia element")
            raise InvalidValue("inertia")
        for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            if inertia.get(key) is None:
                self.log(f"Inertial: inertia element missing {key} attribute")
                raise InvalidValue(key)
            self.number(inertia, key, f"Inertial: inertia element {key} is not a valid double")

    def shape(self, xml: etree._Element, visual: bool) -> tuple[str, bool]:
        """Parse a visual or collision: its material name and whether it is defined in place.

        Raises:
            InvalidValue: urdfdom drops this visual or collision (already logged).
        """
        self.pose(_first(xml, "origin"))
        self.geometry(_first(xml, "geometry"))
        material = _first(xml, "material") if visual else None
        if material is None:
            return "", False
        if material.get("name") is None:
            self.log("Visual material must contain a name attribute")
            raise InvalidValue("material")
        return material.get("name", ""), self.material(material, True)

    def link(self, xml: etree._Element) -> tuple[str, list[tuple[str, bool]]]:
        """The link name and the material reference of each visual urdfdom keeps."""
        name = xml.get("name")
        if name is None:
            self.log("No name given for the link.")
            return "", []
        materials: list[tuple[str, bool]] = []
        inertial = _first(xml, "inertial")
        try:
            if inertial is not None:
                try:
                    self.inertial(inertial)
                except InvalidValue:
                    self.log(f"Could not parse inertial element for Link [{name}]")
                    raise
            for kind in ("visual", "collision"):
                for shape in _elements(xml, kind):
                    try:
                        material = self.shape(shape, kind == "visual")
                    except InvalidValue:
                        self.log(f"Could not parse {kind} element for Link [{name}]")
                        raise
                    if kind == "visual":
                        materials.append(material)
        except InvalidValue:
            pass  # urdfdom keeps the link with what it read so far
        return name, materials

    # --- joints ---------------------------------------------------------------------

    def limits(self, xml: etree._Element) -> None:
        for key in ("lower", "upper"):
            self.number(xml, key, key + " value ({}) is not a valid float")
        for key in ("effort", "velocity"):
            if xml.get(key) is None:
                self.log(f"joint limit: no {key}")
                raise InvalidValue(key)
            self.number(xml, key, key + " value ({}) is not a valid float")

    def safety(self, xml: etree._Element) -> None:
        for key in ("soft_lower_limit", "soft_upper_limit", "k_position"):
            self.number(xml, key, key + " value ({}) is not a valid float")
        if xml.get("k_velocity") is None:
            self.log("joint safety: no k_velocity")
            raise InvalidValue("k_velocity")
        self.number(xml, "k_velocity", "k_velocity value ({}) is not a valid float")

    def calibration(self, xml: etree._Element) -> None:
        for key in ("rising", "falling"):
            self.number(xml, key, key + " value ({}) is not a valid float")

    def mimic(self, xml: etree._Element) -> None:
        if xml.get("joint") is None:
            self.log("joint mimic: no mimic joint specified")
            raise InvalidValue("joint")
        for key in ("multiplier", "offset"):
            self.number(xml, key, key + " value ({}) is not a valid float")

    def dynamics(self, xml: etree._Element) -> None:
        for key in ("damping", "friction"):
            self.number(xml, key, key + " value ({}) is not a valid float")
        if xml.get("damping") is None and xml.get("friction") is None:
            self.log("joint dynamics element specified with no damping and no friction")
            raise InvalidValue("dynamics")

    def joint(self, xml: etree._Element) -> RosJoint:
        name = xml.get("name")
        if name is None:
            self.log("unnamed joint found")
            raise InvalidValue("name")
        try:
            xyz, quaternion = self.pose(_first(xml, "origin"))
        except InvalidValue:
            self.log(f"Malformed parent origin element for joint [{name}]")
            raise
        ends = []
        for end in ("parent", "child"):
            tag = _first(xml, end)
            ends.append(tag.get("link", "") if tag is not None else "")
        kind = xml.get("type")
        if kind is None:
            self.log(f"joint [{name}] has no type, check to see if it's a reference.")
            raise InvalidValue("type")
        if kind not in ("planar", "floating", "revolute", "continuous", "prismatic", "fixed"):
            self.log(f"Joint [{name}] has no known type [{kind}]")
            raise InvalidValue("type")
        axis = _first(xml, "axis")
        if kind not in ("floating", "fixed") and axis is not None and axis.get("xyz") is not None:
            try:
                ros_vector(axis.get("xyz", ""))
            except InvalidValue as error:
                self.log(f"Malformed axis element for joint [{name}]: {error}")
                raise
        limit = _first(xml, "limit")
        if limit is not None:
            self.part(limit, self.limits, f"Could not parse limit element for joint [{name}]")
        elif kind == "revolute":
            self.log(f"Joint [{name}] is of type REVOLUTE but it does not specify limits")
            raise InvalidValue("limit")
        elif kind == "prismatic":
            self.log(f"Joint [{name}] is of type PRISMATIC without limits")
            raise InvalidValue("limit")
        parts = (
            ("safety_controller", self.safety, "Could not parse safety element for joint [{}]"),
            (
                "calibration",
                self.calibration,
                "Could not parse calibration element for joint  [{}]",
            ),
            ("mimic", self.mimic, "Could not parse mimic element for joint  [{}]"),
            ("dynamics", self.dynamics, "Could not parse joint_dynamics element for joint [{}]"),
        )
        for tag_name, parse, failure in parts:
            part = _first(xml, tag_name)
            if part is not None:
                self.part(part, parse, failure.format(name))
        return RosJoint(name, ends[0], ends[1], tuple(xyz), tuple(quaternion))  # type: ignore[arg-type]

    def part(
        self, xml: etree._Element, parse: Callable[[etree._Element], None], failure: str
    ) -> None:
        try:
            parse(xml)
        except InvalidValue:
            self.log(failure)
            raise

    # --- the whole robot ------------------------------------------------------------

    def version(self) -> None:
        text = self.robot.get("version")
        if text is None:
            return
        pieces = _split(text, ".")
        if len(pieces) != 2:
            raise self.refuse("The version attribute should be in the form 'x.y'")
        numbers = []
        for piece in pieces:
            if piece == "":
                raise self.refuse("One of the fields of the version attribute is blank")
            match = _LONG.match(piece)
            if match is None:
                raise self.refuse("Version attribute is not an integer")
            if match.end() != len(piece):
                raise self.refuse("Extra characters after the version number")
            value = int(match.group())
            if value < 0:
                raise self.refuse("Version number must be positive")
            numbers.append(min(value, 2**63 - 1) % 2**32)
        if numbers != [1, 0]:
            raise self.refuse(
                "Invalid 'version' specified; only version 1.0 is currently supported"
            )

    def run(self) -> RosModel:
        model = self.model
        try:
            self.version()
            materials: set[str] = set()
            for xml in _elements(self.robot, "material"):
                name = xml.get("name", "")
                self.about(f"material '{name}'", xml)
                self.material(xml, False)
                if name in materials:
                    raise self.refuse(f"material '{name}' is not unique.")
                materials.add(name)
            links: set[str] = set()
            for xml in _elements(self.robot, "link"):
                self.about(f"link '{xml.get('name', '')}'", xml)
                name, references = self.link(xml)
                if name in links:
                    raise self.refuse(f"link '{name}' is not unique.")
                links.add(name)
                # urdfdom assigns the first visual's material twice.
                for material, in_place in references[:1] + references:
                    if not material or material in materials:
                        continue
                    if in_place:
                        materials.add(material)
                    else:
                        self.log(f"link '{name}' material '{material}' undefined.", "Warning")
            if not links:
                self.about(self.element, self.robot)
                raise self.refuse("No link elements found in urdf file")
            joints: dict[str, RosJoint] = {}
            for xml in _elements(self.robot, "joint"):
                self.about(f"joint '{xml.get('name', '')}'", xml)
                try:
                    joint = self.joint(xml)
                except InvalidValue:
                    raise self.refuse("joint xml is not initialized correctly") from None
                if joint.name in joints:
                    raise self.refuse(f"joint '{joint.name}' is not unique.")
                joints[joint.name] = joint
            self.tree(links, joints)
        except _Refused:
            model.refused = True
            model.children = {}
            model.root = None
        return model

    def tree(self, links: set[str], joints: dict[str, RosJoint]) -> None:
        model = self.model
        self.building_tree = True
        children: dict[str, list[RosJoint]] = {}
        has_parent: set[str] = set()
        lines = {j.get("name"): j.sourceline for j in _elements(self.robot, "joint")}
        for name in sorted(joints):
            joint = joints[name]
            self.element, self.line = f"joint '{name}'", lines.get(name)
            if not joint.parent or not joint.child:
                reason = f"Joint [{name}] is missing a parent and/or child link specification."
            elif joint.child not in links:
                reason = f"child link [{joint.child}] of joint [{name}] not found"
            elif joint.parent not in links:
                reason = (
                    f"parent link [{joint.parent}] of joint [{name}] not found.  This is not "
                    "valid according to the URDF spec. Every link you refer to from a joint "
                    f"needs to be explicitly defined in the robot description. To fix this "
                    f"problem you can either remove this joint [{name}] from your urdf file, "
                    f'or add "<link name="{joint.parent}" />" to your urdf file.'
                )
            else:
                children.setdefault(joint.parent, []).append(joint)
                has_parent.add(joint.child)
                continue
            raise self.refuse(f"Failed to build tree: {reason}")
        roots = [name for name in sorted(links) if name not in has_parent]
        self.element, self.line = f"robot '{model.name}'", self.robot.sourceline
        if len(roots) > 1:
            raise self.refuse(
                f"Failed to find root link: Two root links found: [{roots[0]}] and [{roots[1]}]"
            )
        if not roots:
            raise self.refuse(
                "Failed to find root link: No root link found. The robot xml is not a valid tree."
            )
        model.root, model.children = roots[0], children
        model.endless = _endless(roots[0], children)


def _split(text: str, separator: str) -> list[str]:
    """urdfdom's ``split_string``: no empty piece after a trailing separator."""
    pieces = text.split(separator)
    if pieces and pieces[-1] == "":
        pieces.pop()
    return pieces


def _endless(root: str, children: dict[str, list[RosJoint]]) -> str | None:
    """The first link met again below itself on a walk from ``root`` (None when none is)."""
    on_path = {root}
    stack: list[tuple[str, Iterator[RosJoint]]] = [(root, iter(children.get(root, [])))]
    while stack:
        link, below = stack[-1]
        joint = next(below, None)
        if joint is None:
            on_path.discard(link)
            stack.pop()
        elif joint.child in on_path:
            return joint.child
        else:
            on_path.add(joint.child)
            stack.append((joint.child, iter(children.get(joint.child, []))))
    return None


def read_ros_model(robot: etree._Element) -> RosModel:
    """What urdfdom 3.0.1 makes of the ``<robot>`` element ``robot`` (see the module doc)."""
    return _Parser(robot, robot.get("name", "")).run()
