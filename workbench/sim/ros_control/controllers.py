"""ros_controllers' joint controllers (noetic), by their type names.

Each controller reads its parameters from ``<robot namespace>/<name>/`` and claims the
joints it commands on one hardware interface:

* ``joint_state_controller/JointStateController``: ``sensor_msgs/JointState`` on
  ``<robot namespace>/joint_states`` every ``1 / publish_rate`` s (required; the
  first message at once), of every joint (sorted by name) or of ``joints``, plus
  ``extra_joints`` (``name``, ``position``, ``velocity``, ``effort``) with fixed values.
* ``{position,velocity,effort}_controllers/JointPositionController`` /
  ``JointVelocityController`` / ``JointEffortController`` of the matching interface:
  forward a ``std_msgs/Float64`` on ``<name>/command`` (``joint``) to the joint;
  they start at the current position (position) or 0 (velocity, effort).
* ``{position,velocity,effort}_controllers/JointGroup*Controller``: the same with
  ``joints`` and a ``std_msgs/Float64MultiArray`` (a wrong length is refused).
* ``effort_controllers/JointPositionController``: a PID (``<name>/pid/{p,i,d,i_clamp}``)
  from the position error (the shortest turn for revolute and continuous joints;
  commands outside a revolute or prismatic joint's limits are clamped to them) to
  the effort, ``control_msgs/JointControllerState`` on ``<name>/state`` every 10th update.
* ``effort_controllers/JointVelocityController``: a PID from the velocity error to the effort.
* ``velocity_controllers/JointPositionController``: a PID from the position error to
  the velocity command.
* ``{position,velocity,effort}_controllers/JointTrajectoryController``: see
  :mod:`.trajectory_controller`.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.ros_control.angles import shortest_angular_distance
from workbench.sim.ros_control.hardware import (
    EFFORT,
    POSITION,
    STATE_INTERFACE,
    VELOCITY,
    HardwareError,
    RobotHWSim,
    SimJoint,
)
from workbench.sim.ros_control.params import ParamView
from workbench.sim.ros_control.pid import Pid

_LOG = logging.getLogger("workbench.sim.ros_control")


class ControllerError(SimulationError):
    """A controller cannot be loaded with its parameters (one line: controller and what)."""


class Controller:
    """Base of the controllers: ``init``, ``starting``, ``update``, ``stopping``.

    After :meth:`setup`: ``name``, ``type``, ``params`` (its namespace), ``root``
    (the robot namespace), ``node`` (the bus node, or None) and ``hardware``.
    ``state`` is ``initialized``, ``running`` or ``stopped`` (controller_manager's words).
    """

    interface = STATE_INTERFACE

    def setup(self, name: str, kind: str, hardware: RobotHWSim, root: ParamView, node: Any) -> None:
        self.name = name
        self.type = kind
        self.hardware = hardware
        self.root = root
        self.params = root.child(name)
        self.node = node
        self.state = "initialized"
        self._endpoints: list[Any] = []
        self.init()

    # --- what a controller implements ------------------------------------------------

    def init(self) -> None:
        """Read parameters and get handles (raise ControllerError to refuse)."""

    def claimed(self) -> list[str]:
        """The joints this controller commands (its claimed resources)."""
        return []

    def starting(self, time: float) -> None:
        """Called in the update that starts the controller (simulated time, s)."""

    def update(self, time: float, period: float) -> None:
        """One control step at ``time`` (s), ``period`` s after the last."""

    def stopping(self, time: float) -> None:
        """Called in the update that stops the controller."""

    # --- helpers -------------------------------------------------------------------

    def topic(self, name: str) -> str:
        """``<robot ns>/<controller>/<name>``."""
        return self.params.name(name)

    def joint(self, joint: str) -> SimJoint:
        try:
            return self.hardware.handle(self.interface, joint)
        except HardwareError as error:
            raise ControllerError(f"controller '{self.name}': {error.message}") from None

    def required(self, key: str) -> Any:
        if not self.params.has(key):
            raise ControllerError(
                f"controller '{self.name}': parameter '{self.params.name(key)}' is not set"
            )
        return self.params.get(key)

    def joint_list(self, key: str = "joints") -> list[str]:
        value = self.required(key)
        if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
            raise ControllerError(
                f"controller '{self.name}': '{self.params.name(key)}' must be a non-empty list "
                "of joint names"
            )
        return list(value)

    def advertise(self, topic: str, kind: str, queue_size: int = 1) -> Any:
        if self.node is None:
            return None
        publisher = self.node.create_publisher(self.topic(topic), kind, queue_size)
        self._endpoints.append(publisher)
        return publisher

    def subscribe(self, topic: str, kind: str, callback: Callable[[Any], None]) -> None:
        if self.node is None:
            return
        self._endpoints.append(
            self.node.create_subscription(self.topic(topic), kind, callback, 1, inline=True)
        )

    def shutdown(self) -> None:
        """Close the controller's topics (it is unloaded)."""
        for endpoint in self._endpoints:
            endpoint.unregister()
        self._endpoints.clear()


class JointStateController(Controller):
    """``joint_state_controller/JointStateController``."""

    def init(self) -> None:
        joints = self.params.get("joints", None)
        names = list(joints) if isinstance(joints, list) else self.hardware.names()
        self.joints = [self.joint(n) for n in names]
        rate = self.required("publish_rate")
        if not isinstance(rate, (int, float)) or isinstance(rate, bool):
            raise ControllerError(f"controller '{self.name}': publish_rate must be a number")
        self.rate = float(rate)
        self.extra = _extra_joints(self.params.get("extra_joints", None), names, self.name)
        self.publisher = None
        if self.node is not None:
            self.publisher = self.node.create_publisher(
                self.root.name("joint_states"), "sensor_msgs/JointState", 4
            )
            self._endpoints.append(self.publisher)
        self.last_publish: float | None = None

    def starting(self, time: float) -> None:
        if self.last_publish is None and self.rate > 0:
            self.last_publish = time - 1.001 / self.rate

    def update(self, time: float, period: float) -> None:
        if self.rate <= 0 or self.last_publish is None:
            return
        if not self.last_publish + 1.0 / self.rate < time - 1e-12:
            return
        self.last_publish += 1.0 / self.rate
        if self.publisher is None:
            return
        from workbench.msgs.sensor_msgs import JointState
        from workbench.sim.gazebo_ros_plugins.ros_context import ros_stamp

        message = JointState()
        message.header.stamp = ros_stamp(time)
        message.name = [j.name for j in self.joints] + [e[0] for e in self.extra]
        message.position = [j.position for j in self.joints] + [e[1] for e in self.extra]
        message.velocity = [j.velocity for j in self.joints] + [e[2] for e in self.extra]
        message.effort = [j.effort for j in self.joints] + [e[3] for e in self.extra]
        self.publisher.publish(message)


def _extra_joints(value: Any, names: list[str], controller: str) -> list[tuple[str, ...]]:
    if value is None:
        return []
    if not isinstance(value, list):
        _LOG.error("controller '%s': extra_joints is not a list; ignored", controller)
        return []
    extra: list[Any] = []
    for item in value:
        if not isinstance(item, dict) or not isinstance(item.get("name"), str):
            _LOG.error("controller '%s': an extra joint without a name is ignored", controller)
            continue
        if item["name"] in names:
            _LOG.warning("controller '%s': extra joint '%s' is a real joint", controller, item)
            continue
        values = [item.get(k, 0.0) for k in ("position", "velocity", "effort")]
        if not all(isinstance(v, float) for v in values):
            _LOG.error("controller '%s': extra joint '%s' needs float values", controller, item)
            continue
        extra.append((item["name"], *values))
    return extra


class ForwardCommandController(Controller):
    """A ``Joint{Position,Velocity,Effort}Controller`` of its own interface."""

    def init(self) -> None:
        self.handle = self.joint(self.required("joint"))
        self.command = 0.0
        self.subscribe("command", "std_msgs/Float64", self._on_command)

    def _on_command(self, message: Any) -> None:
        self.command = float(message.data)

    def claimed(self) -> list[str]:
        return [self.handle.name]

    def starting(self, time: float) -> None:
        self.command = self.handle.position if self.interface == POSITION else 0.0

    def update(self, time: float, period: float) -> None:
        self.handle.command = self.command


class ForwardGroupCommandController(Controller):
    """A ``JointGroup{Position,Velocity,Effort}Controller`` of its own interface."""

    def init(self) -> None:
        self.handles = [self.joint(n) for n in self.joint_list()]
        self.commands = [0.0] * len(self.handles)
        self.subscribe("command", "std_msgs/Float64MultiArray", self._on_command)

    def _on_command(self, message: Any) -> None:
        if len(message.data) != len(self.handles):
            _LOG.error(
                "controller '%s': dimension of command (%d) does not match number of joints "
                "(%d)! Not executing!",
                self.name,
                len(message.data),
                len(self.handles),
            )
            return
        self.commands = [float(v) for v in message.data]

    def claimed(self) -> list[str]:
        return [h.name for h in self.handles]

    def starting(self, time: float) -> None:
        if self.interface == POSITION:
            self.commands = [h.position for h in self.handles]
        else:
            self.commands = [0.0] * len(self.handles)

    def update(self, time: float, period: float) -> None:
        for handle, command in zip(self.handles, self.commands, strict=True):
            handle.command = command


class PidPositionController(Controller):
    """``effort_controllers/JointPositionController`` (or ``velocity_controllers/...``: the
    PID's output is a velocity command)."""

    def init(self) -> None:
        self.handle = self.joint(self.required("joint"))
        pid = Pid.from_params(self.params.get("pid", None))
        if pid is None:
            raise ControllerError(
                f"controller '{self.name}': no p gain specified for pid (namespace: "
                f"{self.params.name('pid')})"
            )
        self.pid = pid
        self.target = 0.0
        self.target_velocity: float | None = None
        self.count = 0
        self.subscribe("command", "std_msgs/Float64", self._on_command)
        self.state_publisher = self.advertise("state", "control_msgs/JointControllerState")

    def _on_command(self, message: Any) -> None:
        self.target = float(message.data)
        self.target_velocity = None

    def claimed(self) -> list[str]:
        return [self.handle.name]

    def starting(self, time: float) -> None:
        self.target = self.handle.position
        self.target_velocity = None
        self.pid.reset()

    def update(self, time: float, period: float) -> None:
        joint = self.handle
        target = self.target
        limits = joint.limits
        if joint.type in ("revolute", "prismatic") and limits and limits.has_position_limits:
            target = min(max(target, limits.min_position), limits.max_position)
        if joint.type in ("revolute", "continuous"):
            error = shortest_angular_distance(joint.position, target)
        else:
            error = target - joint.position
        if self.target_velocity is not None:
            command = self.pid.command(error, self.target_velocity - joint.velocity, period)
        else:
            command = self.pid.command_from_error(error, period)
        joint.command = command
        self.count += 1
        if self.state_publisher is not None and self.count % 10 == 0:
            self._publish_state(time, target, error, period, command)

    def _publish_state(
        self, time: float, target: float, error: float, period: float, command: float
    ) -> None:
        from workbench.msgs.control_msgs import JointControllerState
        from workbench.sim.gazebo_ros_plugins.ros_context import ros_stamp

        message = JointControllerState(
            set_point=target,
            process_value=self.handle.position,
            process_value_dot=self.handle.velocity,
            error=error,
            time_step=period,
            command=command,
            p=self.pid.p,
            i=self.pid.i,
            d=self.pid.d,
            i_clamp=self.pid.i_max,
            antiwindup=self.pid.antiwindup,
        )
        message.header.stamp = ros_stamp(time)
        self.state_publisher.publish(message)


class PidVelocityController(Controller):
    """``effort_controllers/JointVelocityController``: velocity error -> effort."""

    interface = EFFORT

    def init(self) -> None:
        self.handle = self.joint(self.required("joint"))
        pid = Pid.from_params(self.params.get("pid", None))
        if pid is None:
            raise ControllerError(
                f"controller '{self.name}': no p gain specified for pid (namespace: "
                f"{self.params.name('pid')})"
            )
        self.pid = pid
        self.target = 0.0
        self.subscribe("command", "std_msgs/Float64", self._on_command)

    def _on_command(self, message: Any) -> None:
        self.target = float(message.data)

    def claimed(self) -> list[str]:
        return [self.handle.name]

    def starting(self, time: float) -> None:
        self.target = 0.0
        self.pid.reset()

    def update(self, time: float, period: float) -> None:
        error = self.target - self.handle.velocity
        self.handle.command = self.pid.command_from_error(error, period)


def _kind(base: type[Controller], interface: str) -> type[Controller]:
    return type(base.__name__, (base,), {"interface": interface, "__module__": __name__})


def controller_types() -> dict[str, type[Controller]]:
    """Every controller type workbench provides, by its ros_controllers name."""
    from workbench.sim.ros_control.trajectory_controller import JointTrajectoryController

    types: dict[str, type[Controller]] = {
        "joint_state_controller/JointStateController": JointStateController,
        "effort_controllers/JointPositionController": _kind(PidPositionController, EFFORT),
        "effort_controllers/JointVelocityController": PidVelocityController,
        "velocity_controllers/JointPositionController": _kind(PidPositionController, VELOCITY),
    }
    for package, interface in (
        ("position_controllers", POSITION),
        ("velocity_controllers", VELOCITY),
        ("effort_controllers", EFFORT),
    ):
        word = {POSITION: "Position", VELOCITY: "Velocity", EFFORT: "Effort"}[interface]
        if f"{package}/Joint{word}Controller" not in types:
            types[f"{package}/Joint{word}Controller"] = _kind(ForwardCommandController, interface)
        types[f"{package}/JointGroup{word}Controller"] = _kind(
            ForwardGroupCommandController, interface
        )
        types[f"{package}/JointTrajectoryController"] = _kind(JointTrajectoryController, interface)
    return dict(sorted(types.items()))
