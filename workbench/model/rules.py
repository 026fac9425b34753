"""The rules ``workbench check`` applies to a URDF, each returning findings.

Physics (mass and inertia of moving links), joints (limits, axes), looks
(collision geometry, materials), files (meshes, packages) and what ROS's
parser refuses. The tree problems (roots, loops, dangling links, duplicates)
come from :mod:`workbench.model.tree`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workbench.errors import ModelError
from workbench.model.findings import Finding
from workbench.model.meshes import check_mesh
from workbench.model.packages import PackageResolver
from workbench.model.tree import KinematicTree
from workbench.model.urdf_xml import UrdfDocument
from workbench.model.urdfdom import RosModel

_TOLERANCE = 1e-9

#: The codes of :func:`workbench.model.tree.build_tree`'s findings.
TREE_CODES = frozenset(
    (
        "duplicate-link",
        "duplicate-joint",
        "no-links",
        "undefined-link",
        "loop",
        "two-parents",
        "multiple-roots",
    )
)


def _moving_links(document: UrdfDocument, tree: KinematicTree) -> dict[str, str]:
    """Link -> the nearest movable joint above it, for every link that can move."""
    moving: dict[str, str] = {}
    for link in document.links:
        name, seen = link.name, set()
        while name in tree.parent_joint and name not in seen:
            seen.add(name)
            joint = tree.parent_joint[name]
            if joint.type != "fixed":
                moving[link.name] = joint.name
                break
            name = joint.parent
    return moving


def _moves_itself(link: str, tree: KinematicTree) -> bool:
    """Whether ``link`` hangs on a movable joint of its own (a massless link welded to its
    parent, such as a tool frame, merges into the parent: ROS and Drake accept it)."""
    joint = tree.parent_joint.get(link)
    return joint is not None and joint.type != "fixed"


def inertia_findings(document: UrdfDocument, tree: KinematicTree) -> list[Finding]:
    """Missing, non-positive and unphysical masses and inertias.

    Only what ROS's parser cannot read is an error (a ``<mass>`` missing, a value that is
    not a finite number); masses and inertias no real body has are warnings, as ROS and
    Drake load them (a simulator then misbehaves).
    """
    findings = []
    moving = _moving_links(document, tree)
    for link in document.links:
        what = f"link '{link.name}'"
        inertial = link.inertial
        if inertial is None:
            if link.name in moving:
                findings.append(
                    Finding(
                        "warning",
                        "missing-inertial",
                        what,
                        f"moves (joint '{moving[link.name]}') but has no <inertial>; "
                        "a simulator treats it as massless",
                        "add <inertial> with <mass> and <inertia>",
                        link.line,
                    )
                )
            continue
        if inertial.mass is None:
            findings.append(
                Finding(
                    "error",
                    "missing-mass",
                    what,
                    "<inertial> has no <mass>",
                    'add <mass value="..."/> in kg',
                    inertial.line,
                )
            )
        elif inertial.mass < 0 or (inertial.mass == 0 and _moves_itself(link.name, tree)):
            findings.append(
                Finding(
                    "warning",
                    "non-positive-mass",
                    what,
                    f"mass is {inertial.mass:g} kg",
                    "a link's mass must be positive",
                    inertial.mass_line or inertial.line,
                )
            )
        if inertial.inertia is None:
            findings.append(
                Finding(
                    "warning",
                    "missing-inertia",
                    what,
                    "<inertial> has no <inertia>",
                    "add <inertia ixx=... izz=.../> in kg m^2",
                    inertial.line,
                )
            )
            continue
        line = inertial.inertia_line or inertial.line
        if not np.all(np.isfinite(inertial.inertia)):
            findings.append(
                Finding(
                    "error",
                    "inertia-not-finite",
                    what,
                    "inertia holds a value that is not a finite number",
                    "use the inertia of the link's shape about its centre of mass, in kg m^2",
                    line,
                )
            )
            continue
        moments = np.linalg.eigvalsh(inertial.inertia)
        scale = max(float(np.abs(moments).max()), 1e-300)
        if np.allclose(inertial.inertia, 0.0):
            if _moves_itself(link.name, tree):
                findings.append(
                    Finding(
                        "warning",
                        "zero-inertia",
                        what,
                        "inertia is all zero (a point mass)",
                        "give the link the inertia of its shape",
                        line,
                    )
                )
            continue
        text = ", ".join(f"{value:g}" for value in moments)
        if moments.min() < -_TOLERANCE * scale:
            findings.append(
                Finding(
                    "warning",
                    "inertia-not-positive-definite",
                    what,
                    f"inertia is not positive definite (principal moments {text})",
                    "use the inertia of the link's shape about its centre of mass",
                    line,
                )
            )
            continue
        a, b, c = sorted(moments)
        if a + b < c * (1 - 1e-6):
            findings.append(
                Finding(
                    "warning",
                    "inertia-triangle-inequality",
                    what,
                    f"principal moments {text} violate the triangle inequality "
                    f"({a:g} + {b:g} < {c:g}); no real body has this inertia",
                    "use the inertia of the link's shape about its centre of mass",
                    line,
                )
            )
    return findings


def joint_findings(document: UrdfDocument) -> list[Finding]:
    findings = []
    for joint in document.joints:
        what = f"joint '{joint.name}'"
        if joint.type in ("revolute", "prismatic"):
            if joint.lower is None and joint.upper is None and joint.velocity is None:
                findings.append(
                    Finding(
                        "error",
                        "missing-limits",
                        what,
                        f"is {joint.type} but has no <limit>",
                        'add <limit lower="..." upper="..." effort="..." velocity="..."/>, '
                        "or make it continuous",
                        joint.line,
                    )
                )
            else:
                missing = [key for key in ("effort", "velocity") if getattr(joint, key) is None]
                if missing:
                    findings.append(
                        Finding(
                            "warning",
                            "incomplete-limits",
                            what,
                            f"<limit> has no {' or '.join(missing)}",
                            "ROS requires both; planners use the velocity limit",
                            joint.line,
                        )
                    )
        if joint.type in ("revolute", "continuous", "prismatic", "planar"):
            norm = float(np.linalg.norm(joint.axis))
            axis = " ".join(f"{value:g}" for value in joint.axis)
            if norm < 1e-12:
                findings.append(
                    Finding(
                        "error",
                        "zero-axis",
                        what,
                        f'axis "{axis}" is zero',
                        'give a unit axis such as xyz="0 0 1"',
                        joint.line,
                    )
                )
            elif abs(norm - 1.0) > 1e-6:
                findings.append(
                    Finding(
                        "warning",
                        "non-unit-axis",
                        what,
                        f'axis "{axis}" has length {norm:g}; it is used normalized',
                        "write a unit vector",
                        joint.line,
                    )
                )
    return findings


def geometry_findings(document: UrdfDocument) -> list[Finding]:
    findings = []
    robot_materials = {element.get("name") for element in document.root.iterchildren("material")}
    coloured_later: dict[str, int | None] = {}
    for link in document.links:
        for shape in link.visuals:
            if shape.material and shape.rgba is not None:
                coloured_later.setdefault(shape.material, shape.material_line)
    defined = set(robot_materials)
    for link in document.links:
        what = f"link '{link.name}'"
        if link.visuals and not link.collisions:
            findings.append(
                Finding(
                    "warning",
                    "no-collision",
                    what,
                    "has a visual but no collision geometry",
                    "add a <collision>, usually with the visual's geometry, so it can touch things",
                    link.line,
                )
            )
        for shape in link.visuals:
            name = shape.material
            if not name:
                continue
            if shape.rgba is not None:
                defined.add(name)
            elif name not in defined:
                if name in coloured_later:
                    findings.append(
                        Finding(
                            "warning",
                            "material-before-colour",
                            what,
                            f"uses material '{name}' before its colour is given "
                            f"(line {coloured_later[name]})",
                            "define the material at the top of the robot",
                            shape.material_line,
                        )
                    )
                else:
                    findings.append(
                        Finding(
                            "warning",
                            "undefined-material",
                            what,
                            f"uses material '{name}', which is never given a colour",
                            f'define <material name="{name}"><color rgba="..."/></material>',
                            shape.material_line,
                        )
                    )
    for duplicate in document.duplicate_materials:
        first = document.materials[duplicate.name]
        if first.rgba != duplicate.rgba:
            findings.append(
                Finding(
                    "warning",
                    "duplicate-material",
                    f"material '{duplicate.name}'",
                    f"defined again with another colour (first on line {first.line}); "
                    "the first definition wins",
                    "give the second one another name",
                    duplicate.line,
                )
            )
    return findings


def mesh_findings(document: UrdfDocument) -> list[Finding]:
    findings = []
    path = document.path
    resolver = PackageResolver(path)
    base = path.parent if path is not None else Path.cwd()
    for mesh in document.root.iter("mesh"):
        filename = mesh.get("filename")
        if not filename:
            continue
        link = next((el for el in mesh.iterancestors("link")), None)
        what = f"link '{link.get('name')}'" if link is not None else "mesh"
        try:
            resolved = resolver.resolve(filename, base)
            check_mesh(resolved)
        except ModelError as error:
            code = (
                "unknown-package"
                if "package" in error.message.split(" ")[:2]
                else ("unsupported-mesh" if "format" in error.message else "mesh-not-found")
            )
            findings.append(
                Finding("error", code, what, error.message, error.hint or "", mesh.sourceline)
            )
    return findings


def urdfdom_findings(ros: RosModel, existing: list[Finding]) -> list[Finding]:
    """An error for each element urdfdom logs an error about that no other finding explains.

    Every element ROS's parser skips or refuses is then an error of the report, also
    where workbench itself would read it (a number with trailing spaces, a robot-level
    material without colour, a ``<mimic>`` without joint, a ``version`` other than 1.0).
    """
    explained = {finding.element for finding in existing if finding.severity == "error"}
    broken_tree = any(finding.code in TREE_CODES for finding in existing)
    findings: list[Finding] = []
    for message in ros.messages:
        if message.level != "Error" or message.element in explained:
            continue
        if message.tree and broken_tree:
            continue  # workbench's tree findings say what is wrong, and where
        explained.add(message.element)
        refused = ros.refused and any(
            later.element == message.element for later in ros.messages[-1:]
        )
        verb = "refuses the file" if refused else "skips part of it"
        findings.append(
            Finding(
                "error",
                "urdfdom-refuses" if refused else "urdfdom-error",
                message.element,
                f"ROS's URDF parser {verb}: {message.one_line}",
                "fix this element so that ROS reads the robot as you wrote it",
                message.line,
            )
        )
    if ros.endless is not None and not any(f.severity == "error" for f in existing + findings):
        findings.append(
            Finding(
                "error",
                "loop",
                f"link '{ros.endless}'",
                "is reached again below itself; ROS's tools recurse until they crash",
                "URDF describes trees; break the loop by removing a joint",
            )
        )
    return findings
