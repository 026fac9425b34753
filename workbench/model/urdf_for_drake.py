"""The URDF Drake is given: what ROS reads from a file, in a form Drake's parser takes.

ROS's URDF parser (urdfdom 3.0.1, behind ``check_urdf``, RViz, robot_state_publisher
and MoveIt) accepts files that Drake's parser refuses, or aborts the whole process
on. :func:`adapt_for_drake` rewrites a copy of the ``<robot>`` element into what ROS
makes of it, and returns one warning for each change that alters the model:

* materials: colours are settled as urdfdom settles them (robot-level materials
  first, then each visual in file order; the first definition of a name wins, a
  ``<material name="">`` only colours its own visual, an ``rgba`` without four
  numbers is opaque black) and written into each visual without a name, so
  empty or repeated names never reach Drake. A name only given a colour later in
  the file takes that colour; a texture is not drawn.
* shapes with a size of zero or less, or a mesh scaled by zero, are left out
  (Drake aborts on them; ROS draws nothing or a mirrored shape); a blank
  ``name`` of a visual or collision is dropped (Drake refuses it);
* joint limits: a continuous joint's ``lower``/``upper`` are dropped (ROS ignores
  them, Drake would bound the joint), reversed ``lower``/``upper`` are swapped and
  a negative ``velocity`` or ``effort`` is used as its magnitude;
* a ``<mimic>`` naming no joint of the file, its own joint, or a joint with another
  number of degrees of freedom is dropped (urdfdom does not look);
* a ``<transmission>`` Drake cannot read (no type, actuator or joint name, an
  unknown joint, a second actuator of one name) is dropped: urdfdom never reads
  transmissions, and Drake crashes on an empty ``<type/>``.
"""

from __future__ import annotations

import copy
import math
from typing import Any

from lxml import etree

from workbench.model.findings import Finding
from workbench.model.limits import shown_name
from workbench.model.urdfdom import InvalidValue, ros_double

#: Degrees of freedom Drake gives each URDF joint type (a floating joint is left out).
_JOINT_DOFS = {"revolute": 1, "continuous": 1, "prismatic": 1, "fixed": 0, "planar": 3}
#: What each shape's sizes are called, and whether zero is a size Drake takes.
_SIZES = {"box": (("size",), False), "cylinder": (("radius", "length"), False)}
_SIZES |= {"sphere": (("radius",), True), "capsule": (("radius", "length"), False)}


def _numbers(text: str | None) -> list[float] | None:
    """The numbers in ``text`` (None when there is none or one is not a number)."""
    if text is None:
        return None
    try:
        values = [float(piece) for piece in text.split()]
    except ValueError:
        return None
    return values or None


def _name(element: Any) -> str:
    return shown_name(element.get("name", ""), 80)


def _warning(code: str, element: str, message: str, hint: str, xml: Any) -> Finding:
    return Finding("warning", code, element, message, hint, xml.sourceline)


def _replace(element: Any, replacement: Any = None) -> None:
    """Put ``replacement`` (or nothing) where ``element`` was, every later line where it was.

    Drake's messages give lines of the text it reads, which must stay the file's.
    """
    filler = "\n" * etree.tostring(element, with_tail=False, encoding="unicode").count("\n")
    filler += element.tail or ""
    parent = element.getparent()
    if replacement is not None:
        replacement.tail = filler
        parent.replace(element, replacement)
        return
    previous = element.getprevious()
    if previous is not None:
        previous.tail = (previous.tail or "") + filler
    else:
        parent.text = (parent.text or "") + filler
    parent.remove(element)


def urdfdom_colour(material: Any) -> tuple[float, ...] | str | None:
    """What urdfdom's ``parseMaterial`` makes of a ``<material>``'s own colour.

    Returns:
        ``(r, g, b, a)``; ``"texture"`` for a texture without a colour; None when the
        element gives neither (or a colour urdfdom cannot read). An ``rgba`` that does
        not hold four numbers is read as opaque black (urdfdom_headers' ``Color::init``
        fails without raising, and the colour stays cleared).
    """
    color = material.find("color")
    if color is not None and color.get("rgba") is not None:
        try:
            values = [ros_double(piece) for piece in color.get("rgba").split(" ") if piece]
        except InvalidValue:
            values = None
        if values is not None and all(0 <= value <= 1 for value in values):
            return tuple(values) if len(values) == 4 else (0.0, 0.0, 0.0, 1.0)
    texture = material.find("texture")
    if texture is not None and texture.get("filename") is not None:
        return "texture"
    return None


def _colour_findings(root: Any) -> list[Finding]:
    findings = []
    for color in root.iter("color"):
        material = color.getparent()
        values = _numbers(color.get("rgba"))
        if material is None or material.tag != "material" or values is None or len(values) == 4:
            continue
        if not all(0 <= value <= 1 for value in values):
            continue
        owner = next((el for el in material.iterancestors("link")), material)
        findings.append(
            _warning(
                "rgba-not-four-numbers",
                f"{owner.tag} '{_name(owner)}'",
                f'<color rgba="{color.get("rgba")}"> has {len(values)} numbers; ROS draws '
                "it opaque black",
                "write red, green, blue and alpha, each from 0 to 1",
                color,
            )
        )
    return findings


def _settle_materials(root: Any) -> None:
    """Write each visual's colour into it, as urdfdom assigns it; drop robot-level materials."""
    known: dict[str, tuple[float, ...] | str] = {}
    for material in root.findall("material"):
        name = material.get("name")
        colour = urdfdom_colour(material)
        if name is not None and colour is not None and name not in known:
            known[name] = colour
        _replace(material)
    given_later: dict[str, tuple[float, ...]] = {}
    for material in root.iter("material"):
        colour = urdfdom_colour(material)
        name = material.get("name")
        if isinstance(colour, tuple) and name and name not in given_later:
            given_later[name] = colour
    for link in root.iterchildren("link"):
        for visual in link.iterchildren("visual"):
            material = visual.find("material")
            if material is None:
                continue
            name = material.get("name")
            own = urdfdom_colour(material)
            if name is None:
                colour = None  # urdfdom drops the visual; its error is reported elsewhere
            elif not name:
                colour = own
            elif name in known:
                colour = known[name]
            elif own is not None:
                known[name] = colour = own
            else:
                colour = given_later.get(name)  # ROS leaves it uncoloured until then
            replacement = None
            if isinstance(colour, tuple):
                replacement = material.makeelement("material", {})
                rgba = " ".join(repr(float(value)) for value in colour)
                replacement.append(material.makeelement("color", {"rgba": rgba}))
            _replace(material, replacement)


def _degenerate(shape: Any) -> str | None:
    """Why Drake cannot build this ``<geometry>`` child (None when it can)."""
    if shape.tag == "mesh":
        scale = _numbers(shape.get("scale"))
        if scale is not None and any(value == 0 for value in scale):
            return f'is scaled by "{shape.get("scale")}"'
        return None
    fields, zero_ok = _SIZES.get(shape.tag, ((), True))
    for field in fields:
        values = _numbers(shape.get(field)) or []
        if any(value < 0 or (value == 0 and not zero_ok) for value in values):
            return f'has {field}="{shape.get(field)}"'
    return None


def _shape_findings(root: Any) -> list[Finding]:
    findings = []
    for link in root.iterchildren("link"):
        for kind in ("visual", "collision"):
            for number, element in enumerate(link.findall(kind), start=1):
                if not element.get("name", "x").strip():
                    del element.attrib["name"]  # Drake names it; it refuses a blank name
                geometry = element.find("geometry")
                shapes = (
                    [c for c in geometry if isinstance(c.tag, str)] if geometry is not None else []
                )
                reason = _degenerate(shapes[0]) if shapes else None
                if reason is None:
                    continue
                shape = shapes[0]
                _replace(element)
                findings.append(
                    _warning(
                        "degenerate-shape",
                        f"link '{_name(link)}'",
                        f"<{kind}> #{number} <{shape.tag}> {reason}, so it has no volume "
                        "(ROS reads it); workbench leaves it out",
                        "give the shape's real size in metres",
                        shape,
                    )
                )
    return findings


def _limit_findings(joint: Any) -> list[Finding]:
    limit = joint.find("limit")
    kind = joint.get("type")
    what = f"joint '{_name(joint)}'"
    if limit is None:
        return []
    findings = []
    if kind == "continuous":
        for key in ("lower", "upper"):
            limit.attrib.pop(key, None)  # ROS and MoveIt ignore them; Drake would not
    elif kind in ("revolute", "prismatic"):
        lower, upper = _numbers(limit.get("lower")), _numbers(limit.get("upper"))
        if lower and upper and len(lower) == len(upper) == 1 and lower[0] > upper[0]:
            limit.set("lower", limit.get("upper"))
            limit.set("upper", " ".join(str(value) for value in lower))
            findings.append(
                _warning(
                    "bad-limits",
                    what,
                    f"lower limit {lower[0]:g} is above upper limit {upper[0]:g}; "
                    "workbench uses them swapped",
                    "swap them",
                    limit,
                )
            )
    for key in ("velocity", "effort"):
        values = _numbers(limit.get(key))
        if values and len(values) == 1 and values[0] < 0 and math.isfinite(values[0]):
            limit.set(key, repr(-values[0]))
            findings.append(
                _warning(
                    f"negative-{key}",
                    what,
                    f"{key} limit {values[0]:g} is negative; workbench uses {-values[0]:g}",
                    f"a {key} limit is a magnitude",
                    limit,
                )
            )
    return findings


def _mimic_findings(root: Any) -> list[Finding]:
    kinds = {joint.get("name"): joint.get("type", "") for joint in root.iterchildren("joint")}
    findings = []
    for joint in root.iterchildren("joint"):
        mimic = joint.find("mimic")
        target = mimic.get("joint") if mimic is not None else None
        if target is None:
            continue
        kind = joint.get("type", "")
        dofs = _JOINT_DOFS.get(kind)
        if target not in kinds:
            reason = f"names joint '{shown_name(target, 80)}', which the file does not have"
        elif target == joint.get("name"):
            reason = "names the joint itself"
        elif dofs is None or dofs != _JOINT_DOFS.get(kinds[target]):
            reason = f"makes a {kind} joint follow a {kinds[target]} joint"
        else:
            continue
        _replace(mimic)
        findings.append(
            _warning(
                "bad-mimic",
                f"joint '{_name(joint)}'",
                f"<mimic> {reason}; workbench ignores it",
                "name another joint with as many degrees of freedom",
                mimic,
            )
        )
    return findings


def _transmission_problem(transmission: Any, joints: set[str], actuators: set[str]) -> str | None:
    kind = transmission.find("type")
    text = (kind.text or "").strip() if kind is not None else transmission.get("type", "")
    if not text:
        return "has no type"
    if "SimpleTransmission" not in text:
        return None  # Drake skips the other types itself
    actuator, joint = transmission.find("actuator"), transmission.find("joint")
    if actuator is None or actuator.get("name") is None:
        return "has no <actuator name=...>"
    if joint is None or joint.get("name") is None:
        return "has no <joint name=...>"
    if joint.get("name") not in joints:
        return f"names joint '{shown_name(joint.get('name'), 80)}', which the file does not have"
    if actuator.get("name") in actuators:
        return f"repeats actuator name '{shown_name(actuator.get('name'), 80)}'"
    actuators.add(actuator.get("name"))
    return None


def _transmission_findings(root: Any) -> list[Finding]:
    joints = {joint.get("name") for joint in root.iterchildren("joint")}
    actuators: set[str] = set()
    findings = []
    for transmission in root.findall("transmission"):
        problem = _transmission_problem(transmission, joints, actuators)
        if problem is None:
            continue
        _replace(transmission)
        findings.append(
            _warning(
                "bad-transmission",
                f"transmission '{_name(transmission)}'",
                f"{problem}; workbench ignores it (ROS's URDF parser never reads transmissions)",
                "give it a <type>, a <joint name> of the robot and a unique <actuator name>",
                transmission,
            )
        )
    return findings


def drake_findings(root: Any) -> list[Finding]:
    """The warnings :func:`adapt_for_drake` gives for ``root``, which is left unchanged."""
    return adapt_for_drake(copy.deepcopy(root))


def adapt_for_drake(root: Any) -> list[Finding]:
    """Rewrite ``root`` (a copy of a URDF's ``<robot>`` element) for Drake, as ROS reads it.

    Args:
        root: The element to change in place; never the document's own tree.

    Returns:
        One warning for each change that alters what the model is (settled colours
        and dropped textures are not reported).
    """
    findings = _colour_findings(root)
    _settle_materials(root)
    findings += _shape_findings(root)
    for joint in root.iterchildren("joint"):
        findings += _limit_findings(joint)
    findings += _mimic_findings(root)
    findings += _transmission_findings(root)
    return findings
