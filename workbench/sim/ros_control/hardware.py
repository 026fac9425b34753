"""gazebo_ros_control's ``DefaultRobotHWSim`` on a workbench model: joint handles, limits, commands.

Every transmission joint gets a state handle (position, velocity, effort) and one
command handle, of the first ``<hardwareInterface>`` it names (with or without the
``hardware_interface/`` prefix). How a command moves the joint, per interface:

* **Effort**: the command is applied as the joint's effort until the next update
  (Gazebo's ``Joint::SetForce``).
* **Position**: without PID gains the joint is put at the command (Gazebo's
  ``Joint::SetPosition``): workbench sets the joint's position in the plant's state
  and gives it the velocity of the commands (their change over the control period):
  the joint moves kinematically, whatever it touches, as in Gazebo. With gains under
  ``<robotNamespace>/gazebo_ros_control/pid_gains/<joint>`` (``p``, ``i``, ``d``,
  ``i_clamp``) a PID on the position error (the shortest turn within the limits for
  a revolute joint) gives the effort, clamped to the joint's effort limit.
* **Velocity**: without PID gains a velocity motor holds the command within the
  effort limit (Gazebo's ``"vel"``/``"fmax"`` joint parameters; see
  :mod:`workbench.sim.motors`); with gains a PID on the velocity error gives the effort.

Before that, commands are saturated as joint_limits_interface's saturation handles do
(position within the limits and within ``max_velocity`` of the last command, velocity
and effort within their limits). A ``std_msgs/Bool`` true on ``<eStopTopic>`` zeroes
efforts and velocities and holds positions. Reported positions of non-prismatic joints
are unwrapped from 1.0 rad as ``readSim`` does: a revolute joint spawned beyond
1 +- pi rad reads one turn off, as it does in Gazebo.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.ros_control.angles import (
    shortest_angular_distance,
    shortest_angular_distance_with_limits,
)
from workbench.sim.ros_control.params import ParamView
from workbench.sim.ros_control.pid import Pid
from workbench.sim.ros_control.urdf_info import JointLimits, RobotInfo, limits_from_params

_LOG = logging.getLogger("workbench.sim.ros_control")

STATE_INTERFACE = "hardware_interface::JointStateInterface"
EFFORT = "hardware_interface::EffortJointInterface"
POSITION = "hardware_interface::PositionJointInterface"
VELOCITY = "hardware_interface::VelocityJointInterface"

#: ``<hardwareInterface>`` text -> the interface's C++ type name.
INTERFACE_NAMES = {
    **{
        name: EFFORT for name in ("EffortJointInterface", "hardware_interface/EffortJointInterface")
    },
    **{
        name: POSITION
        for name in ("PositionJointInterface", "hardware_interface/PositionJointInterface")
    },
    **{
        name: VELOCITY
        for name in ("VelocityJointInterface", "hardware_interface/VelocityJointInterface")
    },
}


class HardwareError(SimulationError):
    """A controller asked for a joint the hardware does not offer on that interface."""


@dataclass
class SimJoint:
    """One simulated joint: its state, its command and how the command is applied."""

    name: str
    interface: str
    type: str
    limits: JointLimits | None
    pid: Pid | None = None
    position: float = 1.0
    velocity: float = 0.0
    effort: float = 0.0
    command: float = 0.0
    last_command: float = math.nan  # the saturation handle's previous command
    written: float | None = None  # last position put on the joint (position interface)

    @property
    def effort_limit(self) -> float:
        limits = self.limits
        return limits.max_effort if limits and limits.has_effort_limits else math.inf


@dataclass
class RobotHWSim:
    """The joints of one model that ros_control drives (see the module docstring).

    Args:
        model: The plugin's ModelHandle.
        joints: The simulated joints, in transmission order.
    """

    model: Any
    joints: list[SimJoint]
    e_stop: bool = False
    _last_e_stop: bool = False
    _held: dict[str, float] = field(default_factory=dict)

    @classmethod
    def from_robot(
        cls, model: Any, info: RobotInfo, namespace: ParamView, source: str
    ) -> RobotHWSim:
        """The hardware of ``model`` from its URDF's transmissions (``initSim``).

        Raises:
            SimulationError: An unknown hardware interface, or a transmission joint the
                model lacks (gazebo_ros_control then leaves the plugin inactive).
        """
        joints: list[SimJoint] = []
        limit_params = namespace.child("joint_limits")
        for transmission in info.transmissions:
            if len(transmission.joints) > 1:
                _LOG.warning(
                    "%s: transmission '%s' has more than one joint; the default robot hardware "
                    "simulation supports one, so it is skipped",
                    source,
                    transmission.name,
                )
                continue
            joint = transmission.joints[0]
            written = joint.interfaces[0]
            interface = INTERFACE_NAMES.get(written)
            if interface is None:
                raise SimulationError(
                    f"{source}: no matching hardware interface found for '{written}' while "
                    f"loading interfaces for joint '{joint.name}'",
                    hint="use hardware_interface/EffortJointInterface, PositionJointInterface "
                    "or VelocityJointInterface",
                )
            if not model.has_joint(joint.name):
                raise SimulationError(
                    f"{source}: this robot has a joint named '{joint.name}' which is not in "
                    f"the simulated model '{model.name}'",
                    hint="joints: " + (", ".join(model.joint_names) or "none"),
                )
            urdf = info.joints.get(joint.name)
            limits = limits_from_params(
                urdf.limits if urdf else None, limit_params.get(joint.name, None)
            )
            kind = urdf.type if urdf else _inferred_type(limits)
            sim = SimJoint(joint.name, interface, kind, limits)
            if interface != EFFORT:
                sim.pid = Pid.from_params(
                    namespace.child("gazebo_ros_control/pid_gains").get(joint.name, None)
                )
            joints.append(sim)
        hardware = cls(model, joints)
        motors = {j.name: j.effort_limit for j in joints if j.interface == VELOCITY and not j.pid}
        if motors:
            model.add_velocity_motors(
                {name: limit if math.isfinite(limit) else 1e9 for name, limit in motors.items()}
            )
        return hardware

    # --- handles -----------------------------------------------------------------------

    def names(self, interface: str = STATE_INTERFACE) -> list[str]:
        """The joints an interface offers, sorted (a ``HardwareResourceManager``'s order)."""
        return sorted(j.name for j in self.joints if interface in (STATE_INTERFACE, j.interface))

    def interfaces(self) -> list[str]:
        """The interfaces this hardware offers."""
        return [STATE_INTERFACE] + sorted({j.interface for j in self.joints})

    def handle(self, interface: str, joint: str) -> SimJoint:
        """The joint ``joint`` on ``interface``.

        Raises:
            HardwareError: The interface does not offer that joint.
        """
        for candidate in self.joints:
            if candidate.name == joint and interface in (STATE_INTERFACE, candidate.interface):
                return candidate
        raise HardwareError(f"could not find resource '{joint}' in '{interface}'")

    # --- the control loop --------------------------------------------------------------

    def read(self) -> None:
        """Joint states from the simulation (``readSim``)."""
        motor_efforts = (
            self.model.motor_efforts()
            if any(j.interface == VELOCITY and not j.pid for j in self.joints)
            else {}
        )
        for joint in self.joints:
            position = self.model.joint_position(joint.name)
            if joint.type == "prismatic":
                joint.position = position
            else:
                joint.position += shortest_angular_distance(joint.position, position)
            joint.velocity = self.model.joint_velocity(joint.name)
            if joint.name in motor_efforts:
                joint.effort = motor_efforts[joint.name]

    def write(self, period: float) -> None:
        """Apply the commands to the simulation (``writeSim``), ``period`` s after the last."""
        if self.e_stop and not self._last_e_stop:
            self._held = {j.name: j.position for j in self.joints}
        self._last_e_stop = self.e_stop
        efforts: dict[str, float] = {}
        positions: dict[str, float] = {}
        velocities: dict[str, float] = {}
        motors: dict[str, float] = {}
        for joint in self.joints:
            if self.e_stop and joint.interface == POSITION:
                joint.command = self._held.get(joint.name, joint.position)
            _saturate(joint, period)
            if joint.interface == EFFORT:
                efforts[joint.name] = 0.0 if self.e_stop else joint.command
            elif joint.interface == POSITION and joint.pid is None:
                before = joint.written
                positions[joint.name] = joint.command
                step = joint.command - before if before is not None else 0.0
                velocities[joint.name] = step / period if period > 0 else 0.0
                joint.written = joint.command
            elif joint.interface == POSITION and joint.pid is not None:
                efforts[joint.name] = _clamp(
                    joint.pid.command_from_error(_position_error(joint), period), joint.effort_limit
                )
            elif joint.pid is None:
                motors[joint.name] = 0.0 if self.e_stop else joint.command
            else:
                error = -joint.velocity if self.e_stop else joint.command - joint.velocity
                efforts[joint.name] = _clamp(
                    joint.pid.command_from_error(error, period), joint.effort_limit
                )
        for name, value in efforts.items():
            self.handle(STATE_INTERFACE, name).effort = value
        self.model.set_joint_efforts(efforts)
        if positions:
            self.model.set_joint_states(positions, velocities)
        if motors:
            self.model.set_motor_velocities(motors)


def _saturate(joint: SimJoint, period: float) -> None:
    """joint_limits_interface's saturation handle of the joint's interface."""
    limits = joint.limits
    if limits is None:
        return
    if joint.interface == EFFORT and limits.has_effort_limits:
        joint.command = _clamp(joint.command, limits.max_effort)
    elif joint.interface == VELOCITY and limits.has_velocity_limits:
        joint.command = _clamp(joint.command, limits.max_velocity)
    elif joint.interface == POSITION:
        low, high = (
            (limits.min_position, limits.max_position)
            if limits.has_position_limits
            else (-math.inf, math.inf)
        )
        if limits.has_velocity_limits:
            previous = joint.position if math.isnan(joint.last_command) else joint.last_command
            step = limits.max_velocity * period
            low, high = max(previous - step, low), min(previous + step, high)
        joint.command = min(max(joint.command, low), high)
        joint.last_command = joint.command


def _position_error(joint: SimJoint) -> float:
    limits = joint.limits
    if joint.type == "revolute" and limits is not None and limits.has_position_limits:
        return shortest_angular_distance_with_limits(
            joint.position, joint.command, limits.min_position, limits.max_position
        )
    if joint.type == "continuous":
        return shortest_angular_distance(joint.position, joint.command)
    return joint.command - joint.position


def _clamp(value: float, bound: float) -> float:
    return min(max(value, -bound), bound)


def _inferred_type(limits: JointLimits | None) -> str:
    if limits is None:
        return "unknown"
    if limits.has_position_limits:
        return "revolute"
    return "continuous" if limits.angle_wraparound else "prismatic"
