"""``check_urdf`` and more: the tree report plus workbench's own findings.

:func:`check_robot` reads a description and reports what ROS's ``check_urdf``
prints: urdfdom's log lines (``report.ros_messages``, stderr) and the tree, or
no tree when urdfdom refuses the file (:mod:`workbench.model.urdfdom`). It then
looks for what makes a model fail later in a simulator or planner: missing or
invalid inertia, links without collision geometry, joints without limits, bad
axes, shape sizes, undefined materials, missing meshes, broken trees, and
everything urdfdom logs as an error. Only a model without errors is finally
loaded into Drake, whose refusals are reported too.
"""

from __future__ import annotations

import logging
import os
from dataclasses import dataclass, field, replace
from pathlib import Path

from workbench.errors import ModelError
from workbench.model.description import RobotDescription
from workbench.model.findings import Finding
from workbench.model.packages import PackageResolver
from workbench.model.rules import (
    geometry_findings,
    inertia_findings,
    joint_findings,
    mesh_findings,
    urdfdom_findings,
)
from workbench.model.sources import read_description, resolve_robot_path
from workbench.model.tree import KinematicTree, build_tree
from workbench.model.urdf_for_drake import drake_findings
from workbench.model.urdf_xml import UrdfDocument, parse_urdf_text
from workbench.model.urdfdom_reader import read_ros_model

PARSED_BANNER = "---------- Successfully Parsed XML ---------------"


@dataclass
class CheckReport:
    """The outcome of checking one description.

    Attributes:
        path: The file checked.
        robot_name: The robot's name.
        root: The root link, None when the links do not form one tree.
        tree_lines: ``check_urdf``'s stdout lines (name, banner, root, indented children);
            empty when urdfdom refuses the file, as check_urdf then prints nothing there.
        findings: Errors and warnings, errors first, then in file order.
        loaded: Whether Drake loaded the model.
        ros_messages: The lines ``check_urdf`` prints on stderr (urdfdom's log), without
            console_bridge's second line naming urdfdom's C++ source.
    """

    path: Path
    robot_name: str
    root: str | None
    tree_lines: list[str]
    findings: list[Finding] = field(default_factory=list)
    loaded: bool = False
    ros_messages: list[str] = field(default_factory=list)

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
        """The stdout report: exactly ``check_urdf``'s stdout, then workbench's findings."""
        shown = display_path or str(self.path)
        lines = list(self.tree_lines)
        if lines:
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
            "urdfdom": self.ros_messages,
            "findings": [finding.to_dict() for finding in self.findings],
        }


def tree_lines(name: str, root: str, tree: KinematicTree) -> list[str]:
    """``check_urdf``'s lines: children ordered by joint name, 4 more spaces per level."""
    lines = [f"robot name is: {name}", PARSED_BANNER]
    children = {
        link: sorted(joints, key=lambda j: j.name) for link, joints in tree.children.items()
    }
    lines.append(f"root Link: {root} has {len(children.get(root, []))} child(ren)")
    # Depth first without recursion: a chain of thousands of links is a valid model.
    stack = [(2, count, joint) for count, joint in enumerate(children.get(root, []), start=1)]
    stack.reverse()
    seen: set[str] = set()
    while stack:
        level, count, joint = stack.pop()
        lines.append("  " * level + f"child({count}):  {joint.child}")
        if joint.child in seen:
            continue  # Drake refuses loops before this; never walk one forever
        seen.add(joint.child)
        below = list(enumerate(children.get(joint.child, []), start=1))
        stack.extend((level + 2, index, child) for index, child in reversed(below))
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
    """Check a parsed URDF (see :func:`check_robot`); ``description`` saves Drake's load a re-read.

    ``document`` may come from a tolerant read (``parse_urdf_text(..., strict=False)``):
    the elements it skipped are reported as errors.
    """
    tree = build_tree(document)
    ros = read_ros_model(document.root)
    report = CheckReport(
        document.path or Path("<string>"),
        document.name,
        tree.root,
        ros.tree_lines(),
        ros_messages=ros.stderr_lines(),
    )
    findings = list(document.problems) + list(tree.problems)
    findings += inertia_findings(document, tree) if not tree.problems else []
    findings += joint_findings(document)
    findings += geometry_findings(document)
    findings += mesh_findings(document)
    findings += drake_findings(document.root)
    findings += urdfdom_findings(ros, findings)
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

    A malformed ``<visual>``, ``<collision>`` or ``<inertial>`` does not stop the
    check: ROS's parser skips it and prints the tree, and so does this report,
    with the element as an error below it.

    Args:
        source: A path (URDF, SDF or xacro) or a name from ``urdf/``.
        load: Also load the model into Drake and report what Drake refuses.

    Returns:
        The :class:`CheckReport`; ``report.ok`` is False when there is an error.

    Raises:
        ModelError: The file cannot be found, read or parsed at all (not XML,
            empty, no ``<robot>``, bad joints, failing xacro).
    """
    path = resolve_robot_path(source)
    text = read_description(path)
    if text.format != "urdf":
        return _check_sdf(RobotDescription.load(path))
    document = parse_urdf_text(text.text, path, strict=False)
    description = RobotDescription(
        path=path,
        format="urdf",
        text=text.text,
        expanded=text.expanded,
        document=document,
        packages=PackageResolver(path),
    )
    report = check_document(document, load=load, description=description)
    if text.expanded:
        # Line numbers would point into xacro's output, not into the file the user edits.
        report.findings = [replace(finding, line=None) for finding in report.findings]
    return report


def _check_sdf(description: RobotDescription) -> CheckReport:
    from workbench.model.loader import load_robot
    from workbench.model.sdf_names import shown_name

    path = description.path
    robot = load_robot(description)
    tree = KinematicTree()
    joints = [
        replace(j, name=shown_name(j.name), parent=shown_name(j.parent), child=shown_name(j.child))
        for j in robot.joints
    ]
    for link in robot.links:
        shown = shown_name(link.name)
        tree.children[shown] = [j for j in joints if j.parent == shown]
    root = shown_name(robot.root_link)
    report = CheckReport(
        path,
        robot.name,
        root,
        tree_lines(robot.name, root, tree),
        loaded=True,
    )
    for message in robot.load_warnings:
        report.findings.append(Finding("warning", "drake-warning", "model", message))
    return report
