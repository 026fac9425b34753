"""What ros_control reads from a robot's URDF: its ``<transmission>`` blocks and its joints' limits.

Transmissions are read as ``transmission_interface::TransmissionParser`` (noetic) reads
them: a ``<transmission name>`` needs a non-empty ``name`` and ``<type>``; each
``<joint name>`` in it needs at least one ``<hardwareInterface>`` (a joint without one
is left out, and a transmission left without joints or without any ``<actuator
name>`` is dropped). Each dropped element is one line in ``problems``.

Joint limits follow ``joint_limits_interface::getJointLimits`` for a URDF joint: a
joint with ``<limit>`` has velocity and effort limits, and position limits unless it
is continuous; parameters ``joint_limits/<joint>/...`` override them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

from lxml import etree

from workbench.errors import SimulationError


@dataclass(frozen=True)
class TransmissionJoint:
    """A joint of a transmission and the hardware interfaces it offers."""

    name: str
    interfaces: tuple[str, ...]


@dataclass(frozen=True)
class Transmission:
    """One ``<transmission>``."""

    name: str
    type: str
    joints: tuple[TransmissionJoint, ...]
    actuators: tuple[str, ...]


@dataclass(frozen=True)
class JointLimits:
    """``joint_limits_interface::JointLimits`` (m or rad, m/s or rad/s, N or N m)."""

    has_position_limits: bool = False
    min_position: float = -math.inf
    max_position: float = math.inf
    has_velocity_limits: bool = False
    max_velocity: float = math.inf
    has_effort_limits: bool = False
    max_effort: float = math.inf
    angle_wraparound: bool = False


@dataclass(frozen=True)
class UrdfJoint:
    """A URDF joint: its type (``revolute``, ``continuous``, ``prismatic``, ...) and limits."""

    name: str
    type: str
    limits: JointLimits | None = None


@dataclass
class RobotInfo:
    """The transmissions and joints of one URDF, and what was dropped while reading them."""

    transmissions: list[Transmission] = field(default_factory=list)
    joints: dict[str, UrdfJoint] = field(default_factory=dict)
    problems: list[str] = field(default_factory=list)


def read_robot_info(urdf: str, source: str) -> RobotInfo:
    """Transmissions and joints of the URDF text ``urdf`` (``source`` names it in messages).

    Raises:
        SimulationError: The text is not XML.
    """
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    try:
        root = etree.fromstring(urdf.encode(), parser)
    except etree.XMLSyntaxError as error:
        raise SimulationError(
            f"{source}: cannot parse the robot description for its transmissions: {error}"
        ) from None
    info = RobotInfo()
    for joint in root.iter("joint"):
        if joint.getparent() is not root or not joint.get("name"):
            continue
        info.joints[joint.get("name")] = UrdfJoint(
            joint.get("name"), str(joint.get("type", "")), _urdf_limits(joint)
        )
    for element in root.findall("transmission"):
        transmission = _transmission(element, source, info.problems)
        if transmission is not None:
            info.transmissions.append(transmission)
    return info


def _transmission(element: Any, source: str, problems: list[str]) -> Transmission | None:
    line = f"{source}:{element.sourceline}"
    name = element.get("name")
    if not name:
        problems.append(f"{line}: <transmission> without a name is skipped")
        return None
    kind = element.find("type")
    if kind is None or not (kind.text or "").strip():
        problems.append(f"{line}: transmission '{name}' has no <type>; it is skipped")
        return None
    joints = []
    for joint in element.findall("joint"):
        interfaces = tuple(
            (h.text or "").strip()
            for h in joint.findall("hardwareInterface")
            if (h.text or "").strip()
        )
        if not joint.get("name"):
            problems.append(f"{line}: transmission '{name}' has a <joint> without a name")
            return None
        if not interfaces:
            problems.append(
                f"{line}: joint '{joint.get('name')}' of transmission '{name}' has no "
                "<hardwareInterface> (it belongs inside <joint>); the joint is left out"
            )
            continue
        joints.append(TransmissionJoint(joint.get("name"), interfaces))
    actuators = tuple(a.get("name", "") for a in element.findall("actuator"))
    if not joints or not actuators or not all(actuators):
        problems.append(
            f"{line}: transmission '{name}' has no usable <joint> or <actuator name>; it is skipped"
        )
        return None
    return Transmission(name, kind.text.strip(), tuple(joints), actuators)


def _urdf_limits(joint: Any) -> JointLimits | None:
    limit = joint.find("limit")
    if limit is None:
        return None
    kind = joint.get("type", "")
    bounded = kind in ("revolute", "prismatic")
    return JointLimits(
        has_position_limits=bounded,
        min_position=_float(limit.get("lower"), 0.0) if bounded else -math.inf,
        max_position=_float(limit.get("upper"), 0.0) if bounded else math.inf,
        has_velocity_limits=True,
        max_velocity=_float(limit.get("velocity"), 0.0),
        has_effort_limits=True,
        max_effort=_float(limit.get("effort"), 0.0),
        angle_wraparound=kind == "continuous",
    )


def limits_from_params(limits: JointLimits | None, values: Any) -> JointLimits | None:
    """``limits`` overridden by a ``joint_limits/<joint>`` parameter dict (None: unchanged)."""
    if not isinstance(values, dict):
        return limits
    result = limits or JointLimits()
    pairs = (
        ("has_position_limits", ("min_position", "max_position")),
        ("has_velocity_limits", ("max_velocity",)),
        ("has_effort_limits", ("max_effort",)),
    )
    for flag, keys in pairs:
        if flag not in values:
            continue
        enabled = bool(values[flag])
        updates: dict[str, Any] = {flag: enabled}
        for key in keys:
            if enabled and isinstance(values.get(key), (int, float)):
                updates[key] = float(values[key])
        result = replace(result, **updates)
    if "angle_wraparound" in values and not result.has_position_limits:
        result = replace(result, angle_wraparound=bool(values["angle_wraparound"]))
    return result


def _float(text: str | None, default: float) -> float:
    try:
        return float(text) if text is not None else default
    except ValueError:
        return default
