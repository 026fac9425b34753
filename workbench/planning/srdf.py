"""Read and write the Semantic Robot Description Format (SRDF) as MoveIt uses it.

An SRDF adds meaning to a URDF: the virtual joint that fixes the robot to the
``world`` frame, planning groups (kinematic chains, joint lists, link lists or
subgroups), named group states (``home``), end effectors, passive joints and
the link pairs whose collision checks are disabled, each with the reason
(``Adjacent``, ``Default``, ``Always``, ``Never`` or a user reason).

The reader accepts any MoveIt SRDF (ROS 1 and ROS 2 flavours, e.g. the
Panda's); elements it does not model (``link_sphere_approximation``,
``joint_property`` ...) are kept verbatim and written back. Malformed files
raise :class:`SrdfError` naming the file and line. Nothing here imports
pydrake; functions that resolve groups take any robot object with a
``joints`` list of ``JointInfo``-like items (``name``, ``type``, ``parent``,
``child``), such as :class:`workbench.model.Robot`.
"""

from __future__ import annotations

import difflib
import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lxml import etree

from workbench.errors import PlanningError

#: Reasons MoveIt's setup assistant writes for disabled collision pairs.
REASONS = ("Adjacent", "Default", "Always", "Never", "User")

#: Largest SRDF read, bytes.
MAX_SRDF_BYTES = 16 * 1024 * 1024

_HEADER = (
    "Semantic description of the robot for planning: groups, named states, end effectors\n"
    "    and the self-collision pairs that need no checking. The URDF stays the source of\n"
    "    kinematics and geometry; every joint and link named here is defined there."
)


class SrdfError(PlanningError):
    """An SRDF file is malformed or names a group, state, link or joint that does not exist."""


@dataclass
class VirtualJoint:
    """A joint between a frame outside the robot (``world``) and the robot's root link.

    Attributes:
        name: Joint name (``virtual_joint``).
        type: ``fixed``, ``floating`` or ``planar``.
        parent_frame: The outside frame, usually ``world``.
        child_link: The robot link it attaches (the URDF root).
    """

    name: str
    type: str
    parent_frame: str
    child_link: str


@dataclass
class Group:
    """A planning group: the union of its chains, joints, links and subgroups.

    Attributes:
        name: Group name.
        chains: ``(base_link, tip_link)`` pairs; the joints between them belong to the group.
        joints: Joint names.
        links: Link names (a link brings its parent joint).
        subgroups: Names of other groups included whole.
        extra: Other child elements (ignored, as MoveIt does), kept as XML text.
    """

    name: str
    chains: list[tuple[str, str]] = field(default_factory=list)
    joints: list[str] = field(default_factory=list)
    links: list[str] = field(default_factory=list)
    subgroups: list[str] = field(default_factory=list)
    extra: list[str] = field(default_factory=list)


@dataclass
class GroupState:
    """A named set of joint values for a group, e.g. ``home``.

    Attributes:
        name: State name.
        group: The group it belongs to.
        values: Joint name to position (rad or m); multi-dof joints keep a list.
    """

    name: str
    group: str
    values: dict[str, Any] = field(default_factory=dict)


@dataclass
class EndEffector:
    """A group designated as end effector, attached to ``parent_link``.

    Attributes:
        name: End effector name.
        group: The group forming the end effector.
        parent_link: The link of the arm it is attached to.
        parent_group: The arm group, if given.
    """

    name: str
    group: str
    parent_link: str
    parent_group: str | None = None


@dataclass(frozen=True)
class DisabledCollision:
    """A link pair that is never collision-checked, and why.

    Attributes:
        link1: First link (alphabetically first when written by the setup).
        link2: Second link.
        reason: ``Adjacent``, ``Default``, ``Always``, ``Never`` or free text.
    """

    link1: str
    link2: str
    reason: str


@dataclass
class Srdf:
    """The semantic description of one robot.

    Attributes:
        name: Robot name (must match the URDF's).
        virtual_joints: Usually one fixed joint to ``world``.
        groups: Planning groups in file order.
        group_states: Named states in file order.
        end_effectors: End effectors in file order.
        passive_joints: Names of unactuated joints.
        disabled_collisions: Self-collision pairs that need no checking.
        disable_default_collisions: Links whose collisions are all off by default (ROS 2).
        enable_collisions: Pairs re-enabled after ``disable_default_collisions`` (ROS 2).
        extra: Unmodelled elements, kept as XML text and written back.
        path: The file it was read from, if any.
    """

    name: str
    virtual_joints: list[VirtualJoint] = field(default_factory=list)
    groups: list[Group] = field(default_factory=list)
    group_states: list[GroupState] = field(default_factory=list)
    end_effectors: list[EndEffector] = field(default_factory=list)
    passive_joints: list[str] = field(default_factory=list)
    disabled_collisions: list[DisabledCollision] = field(default_factory=list)
    disable_default_collisions: list[str] = field(default_factory=list)
    enable_collisions: list[tuple[str, str]] = field(default_factory=list)
    extra: list[str] = field(default_factory=list)
    path: Path | None = None
    _lines: dict[tuple[str, str], int] = field(default_factory=dict, repr=False, compare=False)

    # --- lookups ---------------------------------------------------------------

    @property
    def group_names(self) -> list[str]:
        """Names of all groups, in file order."""
        return [g.name for g in self.groups]

    def group(self, name: str) -> Group:
        """The group called ``name``; unknown names raise :class:`SrdfError` with close matches."""
        for group in self.groups:
            if group.name == name:
                return group
        raise SrdfError(
            f"unknown planning group '{name if len(name) <= 60 else name[:57] + '...'}'",
            path=self.path,
            hint=_choices("groups", name, self.group_names),
        )

    def group_state(self, group: str, name: str) -> GroupState:
        """The named state ``name`` of ``group`` (e.g. ``home``).

        A state of a group that includes ``group`` whole (e.g. ``default`` of
        ``arm_and_hand`` for ``arm``) serves too; the group's own states come first.
        """
        self.group(group)
        names = self.group_state_names(group)
        for owner in self._state_owners(group):
            for state in self.group_states:
                if state.group == owner and state.name == name:
                    return state
        raise SrdfError(
            f"group '{group}' has no named state '{name}'",
            path=self.path,
            hint=_choices("states", name, names),
        )

    def group_state_names(self, group: str) -> list[str]:
        """Names of the states of ``group`` and of the groups that include it whole."""
        names: list[str] = []
        for owner in self._state_owners(group):
            names.extend(
                s.name for s in self.group_states if s.group == owner and s.name not in names
            )
        return names

    def _state_owners(self, group: str) -> list[str]:
        """``group``, then every group that includes it as a subgroup (at any depth)."""
        owners = [group]
        for name in owners:
            for other in self.groups:
                if name in other.subgroups and other.name not in owners:
                    owners.append(other.name)
        return owners

    def end_effector_of(self, group: str) -> EndEffector | None:
        """The end effector whose ``parent_group`` is ``group``, or attached to its tip."""
        for ee in self.end_effectors:
            if ee.parent_group == group:
                return ee
        return None

    def disabled_pairs(self) -> set[frozenset[str]]:
        """The disabled pairs as a set of two-link frozensets, for fast membership tests."""
        return {frozenset((d.link1, d.link2)) for d in self.disabled_collisions}

    def line_of(self, kind: str, name: str) -> int | None:
        """The source line of element ``kind`` (``group``, ``group_state`` ...) called ``name``."""
        return self._lines.get((kind, name))

    # --- resolution against a robot --------------------------------------------

    def group_joints(self, group: str, robot: Any, *, movable_only: bool = True) -> list[str]:
        """The joints of ``group`` in the order of ``robot.joints`` (the URDF's order).

        Args:
            group: Group name.
            robot: An object with ``joints`` (``JointInfo``-like: name, type, parent, child).
            movable_only: Drop fixed joints (the joints a planner moves).

        Raises:
            SrdfError: Unknown group, or a chain/joint/link the robot does not have.
        """
        names = self._collect_joints(group, robot, set())
        order = [j for j in robot.joints if j.name in names]
        if movable_only:
            order = [j for j in order if j.type not in ("fixed",)]
        passive = set(self.passive_joints)
        return [j.name for j in order if j.name not in passive or not movable_only]

    def group_links(self, group: str, robot: Any) -> list[str]:
        """The links of ``group``: the children of its joints, plus its listed links and chain bases."""
        joints = set(self._collect_joints(group, robot, set()))
        links: list[str] = []
        seen: set[str] = set()

        def add(link: str) -> None:
            if link not in seen:
                seen.add(link)
                links.append(link)

        for base, _ in self._chains(group, set()):
            add(base)
        for j in robot.joints:
            if j.name in joints:
                add(j.child)
        for name in self._listed_links(group, set()):
            add(name)
        return links

    def group_tip(self, group: str, robot: Any) -> str:
        """The tip link of ``group``: its (first) chain's tip, else its deepest link."""
        g = self.group(group)
        if g.chains:
            return g.chains[0][1]
        for sub in g.subgroups:
            sub_group = self.group(sub)
            if sub_group.chains:
                return sub_group.chains[0][1]
        links = self.group_links(group, robot)
        if not links:
            raise SrdfError(f"group '{group}' has no links", path=self.path)
        depth = _link_depths(robot)
        return max(links, key=lambda name: depth.get(name, -1))

    def _chains(self, group: str, visiting: set[str]) -> list[tuple[str, str]]:
        g = self.group(group)
        if group in visiting:
            raise SrdfError(
                f"group '{group}' includes itself through its subgroups", path=self.path
            )
        chains = list(g.chains)
        for sub in g.subgroups:
            chains += self._chains(sub, visiting | {group})
        return chains

    def _listed_links(self, group: str, visiting: set[str]) -> list[str]:
        g = self.group(group)
        links = list(g.links)
        for sub in g.subgroups:
            if sub not in visiting:
                links += self._listed_links(sub, visiting | {group})
        return links

    def _collect_joints(self, group: str, robot: Any, visiting: set[str]) -> list[str]:
        g = self.group(group)
        if group in visiting:
            raise SrdfError(
                f"group '{group}' includes itself through its subgroups", path=self.path
            )
        by_name = {j.name: j for j in robot.joints}
        parent_joint = {j.child: j for j in robot.joints}
        line = self.line_of("group", group)
        out: list[str] = []
        for base, tip in g.chains:
            out += chain_joints(robot, base, tip, path=self.path, line=line)
        for name in g.joints:
            if name not in by_name and not any(v.name == name for v in self.virtual_joints):
                raise SrdfError(
                    f"group '{group}' names joint '{name}', which the robot does not have",
                    path=self.path,
                    line=line,
                    hint=_choices("joints", name, list(by_name)),
                )
            if name in by_name:
                out.append(name)
        for name in g.links:
            if name not in parent_joint:
                if name in _all_links(robot):
                    continue  # the root link has no parent joint
                raise SrdfError(
                    f"group '{group}' names link '{name}', which the robot does not have",
                    path=self.path,
                    line=line,
                    hint=_choices("links", name, sorted(_all_links(robot))),
                )
            out.append(parent_joint[name].name)
        for sub in g.subgroups:
            out += self._collect_joints(sub, robot, visiting | {group})
        return out

    def validate(self, robot: Any) -> None:
        """Check every name against ``robot``; raise :class:`SrdfError` at the first bad one."""
        links = _all_links(robot)
        joints = {j.name for j in robot.joints}
        for vj in self.virtual_joints:
            if vj.child_link not in links:
                raise SrdfError(
                    f"virtual joint '{vj.name}' attaches link '{vj.child_link}', which the robot "
                    "does not have",
                    path=self.path,
                    line=self.line_of("virtual_joint", vj.name),
                    hint=_choices("links", vj.child_link, sorted(links)),
                )
        for g in self.groups:
            self.group_joints(g.name, robot)
        for state in self.group_states:
            group_joints = set(self.group_joints(state.group, robot, movable_only=False))
            for joint in state.values:
                if joint not in joints or joint not in group_joints:
                    raise SrdfError(
                        f"state '{state.name}' of group '{state.group}' sets joint '{joint}', "
                        "which is not in the group",
                        path=self.path,
                        line=self.line_of("group_state", f"{state.group}/{state.name}"),
                    )
        for ee in self.end_effectors:
            self.group(ee.group)
            if ee.parent_link not in links:
                raise SrdfError(
                    f"end effector '{ee.name}' has parent link '{ee.parent_link}', which the "
                    "robot does not have",
                    path=self.path,
                    line=self.line_of("end_effector", ee.name),
                )
        for d in self.disabled_collisions:
            for link in (d.link1, d.link2):
                if link not in links:
                    raise SrdfError(
                        f"disable_collisions names link '{link}', which the robot does not have",
                        path=self.path,
                        line=self.line_of("disable_collisions", f"{d.link1}/{d.link2}"),
                        hint=_choices("links", link, sorted(links)),
                    )

    # --- writing ----------------------------------------------------------------

    def to_xml(self) -> str:
        """The SRDF as MoveIt-style XML text (4-space indent, trailing newline)."""
        root = etree.Element("robot", name=self.name)
        for g in self.groups:
            el = etree.SubElement(root, "group", name=g.name)
            for link in g.links:
                etree.SubElement(el, "link", name=link)
            for joint in g.joints:
                etree.SubElement(el, "joint", name=joint)
            for base, tip in g.chains:
                etree.SubElement(el, "chain", base_link=base, tip_link=tip)
            for sub in g.subgroups:
                etree.SubElement(el, "group", name=sub)
            for text in g.extra:
                el.append(etree.fromstring(text))
        for s in self.group_states:
            el = etree.SubElement(root, "group_state", name=s.name, group=s.group)
            for joint, value in s.values.items():
                etree.SubElement(el, "joint", name=joint, value=_format_value(value))
        for ee in self.end_effectors:
            attrs = {"name": ee.name, "parent_link": ee.parent_link, "group": ee.group}
            if ee.parent_group:
                attrs["parent_group"] = ee.parent_group
            etree.SubElement(root, "end_effector", attrs)
        for vj in self.virtual_joints:
            etree.SubElement(
                root,
                "virtual_joint",
                name=vj.name,
                type=vj.type,
                parent_frame=vj.parent_frame,
                child_link=vj.child_link,
            )
        for joint in self.passive_joints:
            etree.SubElement(root, "passive_joint", name=joint)
        for link in self.disable_default_collisions:
            etree.SubElement(root, "disable_default_collisions", link=link)
        for link1, link2 in self.enable_collisions:
            etree.SubElement(root, "enable_collisions", link1=link1, link2=link2)
        for d in self.disabled_collisions:
            etree.SubElement(
                root, "disable_collisions", link1=d.link1, link2=d.link2, reason=d.reason
            )
        for text in self.extra:
            root.append(etree.fromstring(text))
        etree.indent(root, space="    ")
        body = etree.tostring(root, encoding="unicode")
        head = '<?xml version="1.0" encoding="UTF-8"?>\n<!--\n    ' + _HEADER + "\n-->\n"
        return head + body + "\n"


def read_srdf(path: str | os.PathLike[str]) -> Srdf:
    """Read an SRDF file.

    Args:
        path: The ``.srdf`` file (MoveIt format).

    Returns:
        The parsed :class:`Srdf`, with ``path`` set.

    Raises:
        SrdfError: Missing file, malformed XML, or an element lacking a required
            attribute or with a bad value (message names the file and line).
    """
    from workbench.errors import ModelError
    from workbench.model.limits import check_input_file
    from workbench.paths import exists

    path = Path(path)
    if not exists(path):
        raise SrdfError(
            "SRDF file not found", path=path, hint="check the path or run workbench setup"
        )
    try:
        data = check_input_file(path, "SRDF", MAX_SRDF_BYTES).read_bytes()
    except ModelError as error:
        raise SrdfError(error.message, path=path, hint=error.hint) from None
    except OSError as error:
        raise SrdfError(f"cannot read the SRDF: {error.strerror}", path=path) from None
    return parse_srdf(data, path=path)


def parse_srdf(text: str | bytes, *, path: str | os.PathLike[str] | None = None) -> Srdf:
    """Parse SRDF text; ``path`` only labels error messages. See :func:`read_srdf`."""
    data = text.encode() if isinstance(text, str) else text
    where = Path(path) if path is not None else None
    label = where if where is not None else "<srdf>"
    parser = etree.XMLParser(remove_comments=True, resolve_entities=False, no_network=True)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if exc.lineno else None
        msg = exc.msg.split(", line ")[0] if exc.msg else "malformed XML"
        raise SrdfError(f"malformed SRDF: {msg}", path=label, line=line) from None
    if root.tag != "robot":
        raise SrdfError(
            f"the root element is <{root.tag}>, expected <robot>", path=label, line=root.sourceline
        )
    srdf = Srdf(name=_attr(root, "name", label), path=where)
    for el in root:
        if not isinstance(el.tag, str):
            continue
        _read_element(srdf, el, label)
    return srdf


def write_srdf(srdf: Srdf, path: str | os.PathLike[str]) -> Path:
    """Write ``srdf`` to ``path`` (parent directories are created); returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(srdf.to_xml())
    return path


def chain_joints(
    robot: Any,
    base: str,
    tip: str,
    *,
    path: str | os.PathLike[str] | None = None,
    line: int | None = None,
) -> list[str]:
    """The joints on the kinematic path from link ``base`` down to link ``tip``.

    Raises:
        SrdfError: A link is unknown or ``tip`` is not below ``base`` (the group
            is not a chain).
    """
    links = _all_links(robot)
    for link in (base, tip):
        if link not in links:
            raise SrdfError(
                f"chain link '{link}' is not a link of the robot",
                path=path,
                line=line,
                hint=_choices("links", link, sorted(links)),
            )
    parent_joint = {j.child: j for j in robot.joints}
    out: list[str] = []
    link = tip
    while link != base:
        joint = parent_joint.get(link)
        if joint is None:
            raise SrdfError(
                f"'{tip}' is not below '{base}' in the kinematic tree, so base_link -> tip_link "
                "is not a chain",
                path=path,
                line=line,
                hint="swap base and tip, or list the joints instead",
            )
        out.append(joint.name)
        link = joint.parent
    return out[::-1]


# --- helpers -----------------------------------------------------------------------


def _read_element(srdf: Srdf, el: Any, label: Any) -> None:
    tag = el.tag
    line = el.sourceline
    if tag == "group":
        group = Group(name=_attr(el, "name", label))
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "chain":
                group.chains.append(
                    (_attr(child, "base_link", label), _attr(child, "tip_link", label))
                )
            elif child.tag == "joint":
                group.joints.append(_attr(child, "name", label))
            elif child.tag == "link":
                group.links.append(_attr(child, "name", label))
            elif child.tag == "group":
                group.subgroups.append(_attr(child, "name", label))
            else:
                # MoveIt ignores other children (e.g. a stray <passive_joint>); keep them.
                group.extra.append(_compact(child))
        if group.name in srdf.group_names:
            raise SrdfError(f"group '{group.name}' is defined twice", path=label, line=line)
        srdf.groups.append(group)
        srdf._lines[("group", group.name)] = line
    elif tag == "group_state":
        state = GroupState(name=_attr(el, "name", label), group=_attr(el, "group", label))
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag != "joint":
                continue  # MoveIt reads only <joint> here
            state.values[_attr(child, "name", label)] = _parse_value(child, label)
        srdf.group_states.append(state)
        srdf._lines[("group_state", f"{state.group}/{state.name}")] = line
    elif tag == "end_effector":
        ee = EndEffector(
            name=_attr(el, "name", label),
            group=_attr(el, "group", label),
            parent_link=_attr(el, "parent_link", label),
            parent_group=el.get("parent_group") or None,
        )
        srdf.end_effectors.append(ee)
        srdf._lines[("end_effector", ee.name)] = line
    elif tag == "virtual_joint":
        vj = VirtualJoint(
            name=_attr(el, "name", label),
            type=_attr(el, "type", label),
            parent_frame=_attr(el, "parent_frame", label),
            child_link=_attr(el, "child_link", label),
        )
        if vj.type not in ("fixed", "floating", "planar"):
            raise SrdfError(
                f"virtual joint '{vj.name}' has type '{vj.type}'",
                path=label,
                line=line,
                hint="use fixed, floating or planar",
            )
        srdf.virtual_joints.append(vj)
        srdf._lines[("virtual_joint", vj.name)] = line
    elif tag == "passive_joint":
        srdf.passive_joints.append(_attr(el, "name", label))
    elif tag == "disable_collisions":
        d = DisabledCollision(
            link1=_attr(el, "link1", label),
            link2=_attr(el, "link2", label),
            reason=el.get("reason", "User"),
        )
        srdf.disabled_collisions.append(d)
        srdf._lines[("disable_collisions", f"{d.link1}/{d.link2}")] = line
    elif tag == "disable_default_collisions":
        srdf.disable_default_collisions.append(_attr(el, "link", label))
    elif tag == "enable_collisions":
        srdf.enable_collisions.append((_attr(el, "link1", label), _attr(el, "link2", label)))
    else:
        srdf.extra.append(_compact(el))


def _compact(el: Any) -> str:
    """An element as XML text without layout whitespace (re-indented when written)."""
    copy = etree.fromstring(etree.tostring(el))
    for node in copy.iter():
        if node.text is not None and not node.text.strip():
            node.text = None
        node.tail = None
    return etree.tostring(copy, encoding="unicode")


def _attr(el: Any, name: str, label: Any) -> str:
    value = el.get(name)
    if value is None or value == "":
        raise SrdfError(f"<{el.tag}> lacks the attribute '{name}'", path=label, line=el.sourceline)
    return value


def _parse_value(el: Any, label: Any) -> Any:
    text = _attr(el, "value", label)
    try:
        numbers = [float(tok) for tok in text.split()]
    except ValueError:
        raise SrdfError(
            f"joint '{el.get('name')}' has value '{text}', which is not a number",
            path=label,
            line=el.sourceline,
        ) from None
    if not numbers:
        raise SrdfError(
            f"joint '{el.get('name')}' has an empty value", path=label, line=el.sourceline
        )
    if not all(math.isfinite(number) for number in numbers):
        raise SrdfError(
            f"joint '{el.get('name')}' has value '{text}', which is not a finite number",
            path=label,
            line=el.sourceline,
            hint="give the joint position in rad, or in m for a prismatic joint",
        )
    return numbers[0] if len(numbers) == 1 else numbers


def _format_value(value: Any) -> str:
    if isinstance(value, (list, tuple)):
        return " ".join(_format_value(v) for v in value)
    return f"{float(value):.12g}"


def _all_links(robot: Any) -> set[str]:
    links = {link.name for link in getattr(robot, "links", [])}
    for j in robot.joints:
        links.add(j.parent)
        links.add(j.child)
    root = getattr(robot, "root_link", None)
    if root:
        links.add(root)
    return links


def _link_depths(robot: Any) -> dict[str, int]:
    parent = {j.child: j.parent for j in robot.joints}
    depth: dict[str, int] = {}
    for link in _all_links(robot):
        d, cur = 0, link
        while cur in parent and d <= len(parent):
            cur = parent[cur]
            d += 1
        depth[link] = d
    return depth


def _choices(kind: str, name: str, names: list[str]) -> str:
    close = difflib.get_close_matches(name, names, n=3)
    if close:
        return "did you mean " + ", ".join(f"'{c}'" for c in close) + "?"
    shown = ", ".join(names[:12]) + (" ..." if len(names) > 12 else "")
    return f"known {kind}: {shown}" if names else f"no {kind} are defined"
