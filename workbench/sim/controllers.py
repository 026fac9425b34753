"""Joint-level controllers of ``workbench.sim``: a trajectory command source and its tracker.

For each fixed-base robot the World wires::

    TrajectoryCommand --desired state/acceleration--> controller --> effort limits
        --> plant applied generalized force (the robot's velocity indices)

Controller types (``planning.yaml`` ``controller.type``):

* ``inverse_dynamics`` -- Drake's ``InverseDynamicsController``:
  ``tau = M(q) (qdd_ref + kp e + kd e_dot + ki int e) + C(q, v) v - tau_g(q)``,
  so ``kp``, ``kd``, ``ki`` are in 1/s^2, 1/s and 1/s^3 for every joint alike.
* ``pid`` -- Drake's ``PidController`` on the joint errors with the same gains
  scaled by the diagonal of the mass matrix at the initial state (N m/rad ...),
  without model feedforward, like a ros_control effort PID.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.sim.trajectory import JointTrajectory

CONTROLLER_TYPES = ("inverse_dynamics", "pid")
DEFAULT_GAINS = {"kp": 100.0, "ki": 0.0, "kd": 20.0}


@dataclass
class Command:
    """What a :class:`TrajectoryCommand` outputs: hold ``q_hold``, or follow a spline.

    Attributes:
        q_hold: Positions of all the robot's joints outside the trajectory (and
            before/after it when ``spline`` is None), rad or m.
        t0: Simulation time at which the trajectory starts, s.
        columns: For each trajectory column, the index in the robot's q vector.
        spline: Position spline (pydrake PiecewisePolynomial) over [0, duration], or None.
        duration: Length of the trajectory, s.
    """

    q_hold: np.ndarray
    t0: float = 0.0
    columns: np.ndarray | None = None
    spline: Any = None
    duration: float = 0.0

    @classmethod
    def follow(
        cls, q_hold: np.ndarray, t0: float, columns: np.ndarray, trajectory: JointTrajectory
    ) -> Command:
        """A command following ``trajectory`` from time ``t0`` (its own time shifted to 0)."""
        duration = trajectory.duration
        shifted = JointTrajectory(
            trajectory.joint_names,
            trajectory.t - trajectory.t[0],
            trajectory.q,
            trajectory.qd,
        )
        spline = shifted.to_piecewise()
        hold = np.array(q_hold, dtype=float)
        hold[columns] = trajectory.q[-1]
        return cls(hold, float(t0), np.asarray(columns), spline, duration)

    def evaluate(self, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Desired ``(q, qd, qdd)`` of all the robot's joints at simulation time ``t``."""
        q = self.q_hold.copy()
        qd = np.zeros_like(q)
        qdd = np.zeros_like(q)
        if self.spline is None:
            return q, qd, qdd
        s = t - self.t0
        if s >= self.duration:
            return q, qd, qdd
        s = max(s, 0.0)
        q[self.columns] = self.spline.value(s).ravel()
        if self.duration > 0:
            qd[self.columns] = self.spline.EvalDerivative(s, 1).ravel()
            qdd[self.columns] = self.spline.EvalDerivative(s, 2).ravel()
        return q, qd, qdd


def make_command_system(n: int, q_hold: np.ndarray) -> Any:
    """A pydrake LeafSystem with outputs ``desired_state`` (2n) and ``desired_acceleration`` (n).

    The active :class:`Command` lives in the context as an abstract parameter
    (index 0), so replacing it invalidates the outputs.
    """
    from pydrake.common.value import AbstractValue
    from pydrake.systems.framework import BasicVector, LeafSystem

    class TrajectoryCommand(LeafSystem):
        def __init__(self) -> None:
            super().__init__()
            self.DeclareAbstractParameter(AbstractValue.Make(Command(np.array(q_hold, float))))
            tickets = {self.time_ticket(), self.all_parameters_ticket()}
            self.DeclareVectorOutputPort(
                "desired_state", BasicVector(2 * n), self._state, prerequisites_of_calc=tickets
            )
            self.DeclareVectorOutputPort(
                "desired_acceleration", BasicVector(n), self._accel, prerequisites_of_calc=tickets
            )

        def _command(self, context: Any) -> Command:
            return context.get_abstract_parameter(0).get_value()

        def _state(self, context: Any, output: Any) -> None:
            q, qd, _ = self._command(context).evaluate(context.get_time())
            output.SetFromVector(np.concatenate([q, qd]))

        def _accel(self, context: Any, output: Any) -> None:
            _, _, qdd = self._command(context).evaluate(context.get_time())
            output.SetFromVector(qdd)

    system = TrajectoryCommand()
    system.set_name("trajectory_command")
    return system


def gains_vectors(
    gains: dict[str, Any] | None, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(kp, ki, kd)`` as length-n vectors from scalars or per-joint lists."""
    merged = dict(DEFAULT_GAINS)
    merged.update(gains or {})
    out = []
    for key in ("kp", "ki", "kd"):
        value = np.asarray(merged[key], dtype=float)
        if value.ndim == 0:
            value = np.full(n, float(value))
        if value.shape != (n,) or np.any(value < 0) or not np.all(np.isfinite(value)):
            raise SimulationError(
                f"controller gain {key} must be a non-negative number or {n} numbers, got "
                f"{merged[key]!r}"
            )
        out.append(value)
    return out[0], out[1], out[2]


def add_controller(
    builder: Any,
    control_plant: Any,
    kind: str,
    gains: dict[str, Any] | None,
    name: str,
) -> Any:
    """Add a controller for ``control_plant`` (the robot alone) to ``builder``.

    Returns:
        The controller system. Its ports: ``estimated_state`` input (2n),
        ``desired_state`` input (2n), ``desired_acceleration`` input (n, only for
        ``inverse_dynamics``), and the generalized force output (n) via
        :func:`controller_output`.
    """
    from pydrake.systems.controllers import InverseDynamicsController, PidController

    n = control_plant.num_positions()
    kp, ki, kd = gains_vectors(gains, n)
    controller: InverseDynamicsController | PidController
    if kind == "inverse_dynamics":
        # pydrake's stubs give numpy arrays a float64 shape; any float array is right here
        controller = InverseDynamicsController(
            control_plant,
            kp,  # type: ignore[arg-type]
            ki,  # type: ignore[arg-type]
            kd,  # type: ignore[arg-type]
            has_reference_acceleration=True,
        )
    elif kind == "pid":
        context = control_plant.CreateDefaultContext()
        scale = np.diag(control_plant.CalcMassMatrix(context)).copy()
        controller = PidController(kp * scale, ki * scale, kd * scale)
    else:
        raise SimulationError(
            f"unknown controller type '{kind}'", hint="use " + " or ".join(CONTROLLER_TYPES)
        )
    builder.AddSystem(controller)
    controller.set_name(name)
    return controller


def controller_output(controller: Any) -> Any:
    """The generalized-force output port of a controller made by :func:`add_controller`."""
    if hasattr(controller, "get_output_port_generalized_force"):
        return controller.get_output_port_generalized_force()
    return controller.get_output_port_control()
