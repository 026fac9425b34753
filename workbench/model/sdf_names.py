"""Gazebo's link and joint names, and the names Drake is given for them.

Gazebo flattens a model included in a model into it, naming the included
links and joints ``INCLUDED::NAME`` (``turtlebot::create::base`` is link
``create::base`` of model ``turtlebot``), and keeps a joint that shares its
name with a link. Drake's SDFormat parser reads ``::`` as a path into nested
models and refuses a joint named like a link, so Drake gets names in which
``::`` is written :data:`SCOPE` and such a joint carries :data:`JOINT_MARK`.
:func:`shown_name` turns a Drake name back into Gazebo's; :func:`drake_name`
goes the other way. Every name a user sees or types is Gazebo's.
"""

from __future__ import annotations

from typing import Any

#: Stands for Gazebo's scope separator ``::`` in Drake's names (U+2237 PROPORTION).
SCOPE = "\u2237"
#: Ends the Drake name of a joint that shares its Gazebo name with a link (U+2051).
JOINT_MARK = "\u2051"


def drake_name(name: str, *, joint_clash: bool = False) -> str:
    """The Drake name of a Gazebo link or joint name (``joint_clash``: a joint named like a link)."""
    return name.replace("::", SCOPE) + (JOINT_MARK if joint_clash else "")


def shown_name(name: str) -> str:
    """The Gazebo name of a name Drake was given (unchanged for names without the marks); also
    turns the names inside a message of Drake's into Gazebo's."""
    return name.replace(JOINT_MARK, "").replace(SCOPE, "::")


def scoped(model: str, name: str) -> str:
    """``MODEL::NAME`` of a link or joint given by its Drake name, as Gazebo writes it."""
    return f"{model}::{shown_name(name)}"


def drake_joint(plant: Any, name: str, instance: Any) -> str | None:
    """The Drake name of joint ``name`` (Gazebo's) of model ``instance`` in ``plant``, or None."""
    for candidate in (drake_name(name), drake_name(name, joint_clash=True), name):
        if plant.HasJointNamed(candidate, instance):
            return candidate
    return None


def drake_body(plant: Any, name: str, instance: Any) -> str | None:
    """The Drake name of link ``name`` (Gazebo's) of model ``instance`` in ``plant``, or None."""
    for candidate in (drake_name(name), name):
        if plant.HasBodyNamed(candidate, instance):
            return candidate
    return None
