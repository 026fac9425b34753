"""``check_urdf`` and more: the tree report plus workbench's own findings.

:func:`check_robot` reads a description, prints the tree the way ROS's
``check_urdf`` does, and then looks for what makes a model fail later in a
simulator or planner: missing or invalid inertia, links without collision
geometry, joints without limits, bad axes, undefined materials, missing
meshes, broken trees. It finally loads the model into Drake and reports what
Drake refuses.
"""

from __future__ import annotations

import logging
import os
from dataclasses import dataclass, field, replace
from pathlib import Path

from workbench.errors import ModelError
from workbench.model.description import RobotDescription
from workbench.model.findings import Finding
from workbench.model.rules import geometry_findings, inertia_findings, joint_findings, mesh_findings
from workbench.model.tree import KinematicTree, build_tree
from workbench.model.urdf_xml import UrdfDocument

PARSED_BANNER = "---------- Successfully Parsed XML ---------------"


@dataclass
class CheckReport:
    """The outcome of checking one description.

    Attributes:
        path: The file checked.
        robot_name: The robot's name.
        root: The root link, None when the links do not form one tree.
        tree_lines: The ``check_urdf`` lines (name, banner, root, indented children).
        findings: Errors and warnings, errors first, then in file order.
        loaded: Whether Drake loaded the model.
    """

    path: Path
    robot_name: str
    root: str | None
    tree_lines: list[str]
    findings: list[Finding] = field(default_factory=list)
    loaded: bool = False

    @property
    def errors(self) -> list[Finding]:
        return [finding for finding in self.findings if finding.severity == "error"]

    @property
    def warnings(self) -> list[Finding]:
        return [finding for finding in self.findings if finding.severity == "warning"]

    @property
    def ok(self) -> bool:
        """True when there is no error (warnings allowed)."""
        return not self.errors

    def format(self, display_path: str | None = None) -> str:
        """The text report: the tree as ``check_urdf`` prints it, then the findings."""
        shown = display_path or str(self.path)
        lines = list(self.tree_lines)
        lines.append("")
        counts = f"{len(self.errors)} error(s), {len(self.warnings)} warning(s)"
        if self.findings:
            lines.append(f"workbench found {counts}:")
            lines.extend(finding.format(shown) for finding in self.findings)
        else:
            lines.append("workbench found no problems")
        return "\n".join(lines) + "\n"

    def __str__(self) -> str:
        return self.format()

    def _repr_pretty_(self, printer, cycle: bool) -> None:  # IPython display
        printer.text(self.format())

    def to_dict(self) -> dict:
        """A JSON-ready summary."""
        return {
            "path": str(self.path),
            "robot": self.robot_name,
            "root": self.root,
            "ok": self.ok,
            "loaded": self.loaded,
            "errors": len(self.errors),
            "warnings": len(self.warnings),
            "tree": self.tree_lines,
            "findings": [finding.to_dict() for finding in self.findings],
        }


def tree_lines(name: str, root: str, tree: KinematicTree) -> list[str]:
    """``check_urdf``'s lines: children ordered by joint name, 4 more spaces per level."""
    lines = [f"robot name is: {name}", PARSED_BANNER]
    children = {
        link: sorted(joints, key=lambda j: j.name) for link, joints in tree.children.items()
    }
    lines.append(f"root Link: {root} has {len(children.get(root, []))} child(ren)")

    def walk(link: str, level: int) -> None:
        level += 2
        for count, joint in enumerate(children.get(link, []), start=1):
            lines.append("  " * level + f"child({count}):  {joint.child}")
            walk(joint.child, level)

    walk(root, 0)
    return lines


def _load_findings(
    report: CheckReport,
    document: UrdfDocument,
    existing: list[Finding],
    description: RobotDescription | None = None,
) -> list[Finding]:
    from workbench.model.loader import load_robot

    source = document.path
    assert source is not None  # check_document loads only documents read from a file
    logger = logging.getLogger("workbench.model")
    disabled, logger.disabled = logger.disabled, True
    try:
        robot = load_robot(description if description is not None else source)
    except ModelError as error:
        element = document.element_at(error.line)
        if any(f.severity == "error" and f.element == element for f in existing):
            return []  # workbench already reports why Drake refuses this element
        message = error.message.removeprefix(f"{element}: ")
        return [Finding("error", "drake-load", element, message, error.hint or "", error.line)]
    finally:
        logger.disabled = disabled
    report.loaded = True
    explained = {finding.element for finding in existing}
    findings = []
    for message in robot.load_warnings:
        line = None
        prefix = f"{source}:"
        if message.startswith(prefix):
            head, _, rest = message[len(prefix) :].partition(":")
            if head.isdigit():
                line, message = int(head), rest.strip()
        message = message.removeprefix("warning:").strip()
        element = document.element_at(line)
        if element in explained:
            continue  # workbench already explains this element
        findings.append(Finding("warning", "drake-warning", element, message, "", line))
    return findings


def check_document(
    document: UrdfDocument, *, load: bool = True, description: RobotDescription | None = None
) -> CheckReport:
    """Check a parsed URDF (see :func:`check_robot`); ``description`` saves Drake's load a re-read."""
    tree = build_tree(document)
    lines = [f"robot name is: {document.name}"]
    if tree.root is not None and not tree.problems:
        lines = tree_lines(document.name, tree.root, tree)
    report = CheckReport(document.path or Path("<string>"), document.name, tree.root, lines)
    findings = list(tree.problems)
    findings += inertia_findings(document, tree) if not tree.problems else []
    findings += joint_findings(document)
    findings += geometry_findings(document)
    findings += mesh_findings(document)
    # Drake is asked only about models workbench finds no error in: it reports the
    # first problem only, and aborts the process on some (reversed joint limits).
    if load and document.path is not None and not any(f.severity == "error" for f in findings):
        findings += _load_findings(report, document, findings, description)
    report.findings = sorted(
        findings, key=lambda f: (f.severity != "error", f.line if f.line is not None else 0)
    )
    return report


def check_robot(source: str | os.PathLike[str], *, load: bool = True) -> CheckReport:
    """Check a description file the way ``check_urdf`` does, and much more.

    Args:
        source: A path (URDF, SDF or xacro) or a name from ``urdf/``.
        load: Also load the model into Drake and report what Drake refuses.

    Returns:
        The :class:`CheckReport`; ``report.ok`` is False when there is an error.

    Raises:
        ModelError: The file cannot be found, read or parsed at all (not XML,
            empty, no ``<robot>``, bad numbers, failing xacro).
    """
    description = RobotDescription.load(source)
    if description.document is None:
        return _check_sdf(description)
    report = check_document(description.document, load=load, description=description)
    if description.expanded:
        # Line numbers would point into xacro's output, not into the file the user edits.
        report.findings = [replace(finding, line=None) for finding in report.findings]
    return report


def _check_sdf(description: RobotDescription) -> CheckReport:
    from workbench.model.loader import load_robot

    path = description.path
    robot = load_robot(description)
    tree = KinematicTree()
    for link in robot.links:
        tree.children[link.name] = [j for j in robot.joints if j.parent == link.name]
    report = CheckReport(
        path,
        robot.name,
        robot.root_link,
        tree_lines(robot.name, robot.root_link, tree),
        loaded=True,
    )
    for message in robot.load_warnings:
        report.findings.append(Finding("warning", "drake-warning", "model", message))
    return report
