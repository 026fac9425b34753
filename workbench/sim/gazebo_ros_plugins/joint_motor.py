"""Gazebo's joint velocity motor: ``Joint::SetParam("vel", v)`` limited by ``"fmax"``.

In Gazebo (ODE) the motor is a constraint: the joint reaches the target velocity
within one step unless that would need more than ``fmax`` (N m or N). Drake's
joints have no such motor, so :class:`VelocityMotor` applies, before every
physics step, the effort that would bring the joint to its target in that step
were it alone, ``tau = I (v_target - v) / dt``, clipped to ``[-fmax, fmax]``,
where ``I`` is the inertia the joint moves with the rest of the model free
(:meth:`ModelHandle.joint_inertia`). A wheel off the ground reaches its target in
one step like Gazebo's; a wheel on the ground also moves the robot through
friction, so it gets there over a few steps (about 15 ms for the lab robot).
"""

from __future__ import annotations

import math
from typing import Any


class VelocityMotor:
    """A velocity-controlled joint with an effort limit.

    Args:
        model: The plugin's :class:`~workbench.sim.handles.ModelHandle`.
        joint: The joint's name.
        max_effort: ``fmax``, N m (or N); ``inf`` for none.
    """

    def __init__(self, model: Any, joint: str, max_effort: float) -> None:
        self.model = model
        self.joint = joint
        self.max_effort = float(max_effort)
        self.target = 0.0
        self.effort = 0.0
        self.inertia = model.joint_inertia(joint)

    def apply(self) -> float:
        """Push the joint towards :attr:`target` for the coming step; the effort applied."""
        error = self.target - self.model.joint_velocity(self.joint)
        effort = self.inertia * error / self.model.time_step
        limit = self.max_effort
        if math.isfinite(limit):
            effort = min(max(effort, -limit), limit)
        self.effort = effort
        self.model.set_joint_effort(self.joint, effort)
        return effort
