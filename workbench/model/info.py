"""Plain descriptions of a robot's joints and links, read from its file."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: URDF joint types that move along or about one axis (one position each).
ONE_DOF_TYPES = ("revolute", "continuous", "prismatic")


@dataclass(frozen=True, eq=False)
class JointInfo:
    """One joint as the description states it.

    Attributes:
        name: Joint name.
        type: URDF type: revolute, continuous, prismatic, fixed, floating or planar.
        parent: Parent link name.
        child: Child link name.
        axis: Joint axis in the joint frame (unit vector as written; default +x).
        xyz: Translation of the joint frame in the parent link frame, metres.
        rpy: Fixed-axis roll, pitch, yaw of the joint frame in the parent frame, radians.
        lower: Lower position limit (rad or m), None if not given.
        upper: Upper position limit (rad or m), None if not given.
        velocity: Velocity limit (rad/s or m/s), None if not given.
        effort: Effort limit (N m or N), None if not given.
        line: Line of the ``<joint>`` element in the file, if known.
    """

    name: str
    type: str
    parent: str
    child: str
    axis: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    xyz: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rpy: np.ndarray = field(default_factory=lambda: np.zeros(3))
    lower: float | None = None
    upper: float | None = None
    velocity: float | None = None
    effort: float | None = None
    line: int | None = None

    @property
    def is_movable(self) -> bool:
        """True for one-degree-of-freedom joints (revolute, continuous, prismatic)."""
        return self.type in ONE_DOF_TYPES

    def __repr__(self) -> str:
        return (
            f"JointInfo(name={self.name!r}, type={self.type!r}, parent={self.parent!r}, "
            f"child={self.child!r}, lower={self.lower}, upper={self.upper})"
        )


@dataclass(frozen=True)
class LinkInfo:
    """One link as the description states it.

    Attributes:
        name: Link name.
        has_visual: The link has at least one ``<visual>``.
        has_collision: The link has at least one ``<collision>``.
        mass: Mass in kg from ``<inertial>``, None when the link has none.
        line: Line of the ``<link>`` element in the file, if known.
    """

    name: str
    has_visual: bool
    has_collision: bool
    mass: float | None
    line: int | None = None
