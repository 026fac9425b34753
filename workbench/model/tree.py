"""The link/joint tree of a URDF: roots, children, and what breaks the tree."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from workbench.errors import ModelError
from workbench.model.findings import Finding
from workbench.model.info import JointInfo
from workbench.model.urdf_xml import UrdfDocument


@dataclass
class KinematicTree:
    """Parent/child structure of a URDF.

    Attributes:
        roots: Links that are nobody's child, in file order.
        children: Link name -> joints whose parent it is, in file order.
        parent_joint: Link name -> the joint whose child it is.
        problems: Errors that keep the description from being a tree.
    """

    roots: list[str] = field(default_factory=list)
    children: dict[str, list[JointInfo]] = field(default_factory=dict)
    parent_joint: dict[str, JointInfo] = field(default_factory=dict)
    problems: list[Finding] = field(default_factory=list)

    @property
    def root(self) -> str | None:
        return self.roots[0] if len(self.roots) == 1 else None

    def subtree(self, link: str) -> list[str]:
        """Links below ``link`` (depth first, itself first)."""
        order, stack, seen = [], [link], set()
        while stack:
            name = stack.pop()
            if name in seen:
                continue
            seen.add(name)
            order.append(name)
            stack.extend(joint.child for joint in reversed(self.children.get(name, [])))
        return order


def build_tree(document: UrdfDocument) -> KinematicTree:
    """Work out the tree of ``document`` and every way it fails to be one."""
    tree = KinematicTree()
    problems = tree.problems
    link_names = [link.name for link in document.links]
    known = set(link_names)
    for name, count in Counter(link_names).items():
        if count > 1:
            lines = [link.line for link in document.links if link.name == name]
            problems.append(
                Finding(
                    "error",
                    "duplicate-link",
                    f"link '{name}'",
                    f"defined {count} times (lines {', '.join(map(str, lines))})",
                    "give every link a unique name",
                    lines[1],
                )
            )
    for name, count in Counter(joint.name for joint in document.joints).items():
        if count > 1:
            lines = [joint.line for joint in document.joints if joint.name == name]
            problems.append(
                Finding(
                    "error",
                    "duplicate-joint",
                    f"joint '{name}'",
                    f"defined {count} times (lines {', '.join(map(str, lines))})",
                    "give every joint a unique name",
                    lines[1],
                )
            )
    if not document.links:
        problems.append(
            Finding(
                "error",
                "no-links",
                f"robot '{document.name}'",
                "has no <link> elements",
                'add at least one <link name="base_link">',
                document.root.sourceline,
            )
        )
    for name in dict.fromkeys(link_names):
        tree.children[name] = []
    for joint in document.joints:
        for end, link in (("parent", joint.parent), ("child", joint.child)):
            if link not in known:
                problems.append(
                    Finding(
                        "error",
                        "undefined-link",
                        f"joint '{joint.name}'",
                        f"{end} link '{link}' is not defined",
                        f'define <link name="{link}"> or fix the joint\'s <{end}>',
                        joint.line,
                    )
                )
        if joint.parent == joint.child:
            problems.append(
                Finding(
                    "error",
                    "loop",
                    f"joint '{joint.name}'",
                    f"connects link '{joint.parent}' to itself",
                    "a joint joins two different links",
                    joint.line,
                )
            )
            continue
        if joint.child in tree.parent_joint:
            first = tree.parent_joint[joint.child]
            problems.append(
                Finding(
                    "error",
                    "two-parents",
                    f"joint '{joint.name}'",
                    f"link '{joint.child}' already has parent joint '{first.name}' "
                    f"(line {first.line}); a URDF must be a tree",
                    "remove one of the joints",
                    joint.line,
                )
            )
            continue
        tree.parent_joint[joint.child] = joint
        if joint.parent in known:
            tree.children.setdefault(joint.parent, []).append(joint)
    tree.roots = [name for name in dict.fromkeys(link_names) if name not in tree.parent_joint]
    if len(tree.roots) > 1:
        root_lines = {link.name: link.line for link in document.links}
        problems.append(
            Finding(
                "error",
                "multiple-roots",
                f"robot '{document.name}'",
                f"has {len(tree.roots)} root links ({', '.join(tree.roots)}); "
                "every link but one must be a joint's child",
                "connect the extra roots with joints",
                root_lines.get(tree.roots[1]),
            )
        )
    reached = set()
    dangling = [j.child for j in tree.parent_joint.values() if j.parent not in known]
    for start in tree.roots + dangling:
        reached.update(tree.subtree(start))
    cyclic = [name for name in dict.fromkeys(link_names) if name not in reached]
    if cyclic:
        loop_joint = tree.parent_joint.get(cyclic[0])
        problems.append(
            Finding(
                "error",
                "loop",
                f"link '{cyclic[0]}'",
                f"links {', '.join(cyclic)} form a closed loop with no root",
                "URDF describes trees; break the loop by removing a joint",
                loop_joint.line if loop_joint else None,
            )
        )
    return tree


def checked_tree(document: UrdfDocument) -> tuple[str, KinematicTree]:
    """The root link and tree of ``document``, which must form one tree.

    Raises:
        ModelError: The first problem ``build_tree`` found, with its file and line.
    """
    tree = build_tree(document)
    if tree.problems or tree.root is None:
        first = tree.problems[0]
        raise ModelError(
            f"{first.element}: {first.message}",
            path=document.path,
            line=first.line,
            hint=first.hint or None,
        )
    return tree.root, tree
