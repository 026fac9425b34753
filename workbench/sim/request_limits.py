"""Bounds on the numbers a Gazebo ROS request or a plugin may hand the running simulator.

A wrench of 1e308 N, a twist of 1e308 m/s or a NaN anywhere makes Drake's state
infinite or NaN within a step, and then every model of the world stops. The
server refuses such values before they reach the physics: every number must be
finite and within a bound far above anything a lab robot does (README, "The
Gazebo ROS API"). A request that passes may still be more than a light body can
take (a large torque on a small box spins it up without limit); the server
then stops the physics with a message naming the model (see
:class:`~workbench.sim.server.SimServer`).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

#: Largest position coordinate in a request (poses, reference points), m.
MAX_POSITION = 1e6

#: Largest linear velocity component set on a model, m/s.
MAX_LINEAR_SPEED = 1e4

#: Largest angular velocity component set on a model, rad/s.
MAX_ANGULAR_SPEED = 1e3

#: Largest force component (wrenches), N.
MAX_FORCE = 1e6

#: Largest torque component (wrenches), N m.
MAX_TORQUE = 1e6

#: Largest joint effort, N m or N.
MAX_EFFORT = 1e6

#: Largest joint position (``set_model_configuration``), rad or m.
MAX_JOINT_POSITION = 1e6

#: Largest quaternion component before normalisation (any non-zero length is normalised).
MAX_QUATERNION = 1e6


def out_of_bounds(values: Iterable[tuple[str, float]], limit: float, unit: str) -> str | None:
    """Why the first of ``(name, value)`` is refused (not finite, or beyond ``limit``), or None.

    Returns:
        ``'force.x is not finite'`` or ``'force.x = 1e+308 is beyond 1e+06 N'``.
    """
    for name, value in values:
        try:
            number = float(value)
        except (TypeError, ValueError, OverflowError):
            return f"{name} is not a number"
        if not math.isfinite(number):
            return f"{name} is not finite"
        if abs(number) > limit:
            return f"{name} = {number!r} is beyond {limit:g}{' ' + unit if unit else ''}"
    return None


def xyz(name: str, vector: object) -> list[tuple[str, float]]:
    """``[(name.x, v.x), (name.y, v.y), (name.z, v.z)]`` of a geometry_msgs vector or point."""
    return [(f"{name}.{axis}", getattr(vector, axis)) for axis in ("x", "y", "z")]
