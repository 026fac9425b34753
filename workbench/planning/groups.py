"""Infer planning groups from a robot's kinematic tree: the arm chain and the hand.

Rules (each can be overridden by the setup's arguments):

* **hand** -- movable joints whose joint or child-link name contains
  ``finger``, ``gripper``, ``jaw`` or ``claw``. The hand group lists the links
  below those joints; it hangs from the deepest link that is an ancestor of
  all of them (the arm's tip).
* **arm** -- the chain from the root link to the tip. Without a hand, the tip
  is the link reached through the most movable joints (ties go to the
  deepest link, so a tool link fixed to the last link is the tip).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from workbench.planning.srdf import SrdfError, chain_joints

_HAND_WORDS = re.compile(r"finger|gripper|jaw|claw", re.IGNORECASE)
_MOVABLE = ("revolute", "continuous", "prismatic")


@dataclass
class GroupGuess:
    """The inferred (or given) arm chain and hand.

    Attributes:
        base_link: Root of the arm chain.
        tip_link: Tip of the arm chain (the end effector's parent link).
        arm_joints: Movable joints of the chain, base to tip.
        hand_links: Links of the hand group (empty: no hand).
        hand_joints: Movable joints of the hand.
    """

    base_link: str
    tip_link: str
    arm_joints: list[str]
    hand_links: list[str] = field(default_factory=list)
    hand_joints: list[str] = field(default_factory=list)


def infer_groups(
    robot: Any,
    *,
    base_link: str | None = None,
    tip_link: str | None = None,
    hand_links: list[str] | None = None,
) -> GroupGuess:
    """Guess the arm chain and hand of ``robot`` (any object with ``joints``, ``root_link``).

    Args:
        robot: The robot (``workbench.model.Robot`` or alike).
        base_link: Force the chain's base (default: the root link).
        tip_link: Force the chain's tip.
        hand_links: Force the hand's links (``[]`` for no hand).

    Raises:
        SrdfError: A given link does not exist, the chain has no movable joint,
            or the tip is not below the base.
    """
    joints = list(robot.joints)
    parent_joint = {j.child: j for j in joints}
    children: dict[str, list[Any]] = {}
    for j in joints:
        children.setdefault(j.parent, []).append(j)
    root = robot.root_link

    if hand_links is None:
        hand_roots = [
            j for j in joints if j.type in _MOVABLE and _HAND_WORDS.search(j.name + " " + j.child)
        ]
        # keep only the topmost hand joints (not below another hand joint)
        hand_children = {j.child for j in hand_roots}
        hand_roots = [
            j for j in hand_roots if not (_ancestors(j.parent, parent_joint) & hand_children)
        ]
        hand_links = []
        for j in hand_roots:
            hand_links += _subtree(j.child, children)
    else:
        hand_links = list(hand_links)
    links = _links(robot)
    for name in [*hand_links, base_link, tip_link]:
        if name is not None and name not in links:
            raise SrdfError(f"robot '{robot.name}' has no link '{name}'", path=robot.path)
    hand_joints = [
        parent_joint[link].name
        for link in hand_links
        if link in parent_joint and parent_joint[link].type in _MOVABLE
    ]

    base = base_link or root
    if tip_link is None:
        if hand_links:
            tip_link = _common_ancestor(
                [parent_joint[link].parent for link in hand_links if link in parent_joint],
                parent_joint,
            )
        else:
            tip_link = _deepest_movable(base, children)
    arm = [
        name
        for name in chain_joints(robot, base, tip_link, path=robot.path)
        if _type(joints, name) in _MOVABLE
    ]
    if not arm:
        raise SrdfError(
            f"the chain {base} -> {tip_link} of robot '{robot.name}' has no movable joint",
            path=robot.path,
            hint="give --base and --tip of the arm",
        )
    return GroupGuess(base, tip_link, arm, hand_links, hand_joints)


def _type(joints: list[Any], name: str) -> str:
    return next(j.type for j in joints if j.name == name)


def _links(robot: Any) -> set[str]:
    names = {link.name for link in robot.links}
    for j in robot.joints:
        names.update((j.parent, j.child))
    return names


def _ancestors(link: str, parent_joint: dict[str, Any]) -> set[str]:
    out = {link}
    while link in parent_joint:
        link = parent_joint[link].parent
        out.add(link)
    return out


def _path_to_root(link: str, parent_joint: dict[str, Any]) -> list[str]:
    path = [link]
    while link in parent_joint:
        link = parent_joint[link].parent
        path.append(link)
    return path


def _common_ancestor(links: list[str], parent_joint: dict[str, Any]) -> str:
    paths = [_path_to_root(link, parent_joint) for link in links]
    common = set(paths[0]).intersection(*map(set, paths[1:]))
    return next(link for link in paths[0] if link in common)


def _subtree(link: str, children: dict[str, list[Any]]) -> list[str]:
    out = [link]
    for j in children.get(link, []):
        out += _subtree(j.child, children)
    return out


def _deepest_movable(base: str, children: dict[str, list[Any]]) -> str:
    best = (0, 0, base)
    stack = [(base, 0, 0)]
    while stack:
        link, movable, depth = stack.pop()
        if (movable, depth) > best[:2]:
            best = (movable, depth, link)
        for j in children.get(link, []):
            stack.append((j.child, movable + (j.type in _MOVABLE), depth + 1))
    return best[2]
