"""Joint velocity motors: Gazebo's ``Joint::SetParam("vel", v)`` with ``"fmax"``, in Drake.

In Gazebo (ODE) a joint motor is a constraint solved together with the
contacts: the joint holds the target velocity exactly unless that needs more
than ``fmax`` (N m, or N for a prismatic joint). Drake's equivalent is a joint
actuator with PD control and an effort limit, which its convex (SAP-family)
solvers -- the server's "lagged" approximation among them -- treat implicitly
together with the contacts: here a proportional gain of zero and a damping gain
far above what any joint needs (the solver caps it at a near-rigid constraint),
so the joint tracks its target velocity within the effort limit, as in Gazebo.

The motors belong to a placed model (:attr:`workbench.sim.scene.PlacedModel.motors`)
and are added to the plant each time the world builds its diagram; their targets
are the plant's desired-state input for the model, fixed in the context.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.model.sdf_names import drake_joint, shown_name

#: Damping gain of a motor, N m s/rad (or N s/m): effectively rigid (see above).
MOTOR_DAMPING = 1e4


def add_velocity_motors(plant: Any, instance: Any, motors: Mapping[str, float]) -> None:
    """Give joints of ``instance`` velocity motors ``{joint: effort limit}`` (unfinalized plant).

    A joint that already has an actuator (a URDF ``<transmission>``) keeps it, with
    its own effort limit, and is put under velocity control.

    Raises:
        SimulationError: A joint is missing or does not have exactly one degree of freedom.
    """
    from pydrake.multibody.tree import PdControllerGains

    actuated = {
        shown_name(plant.get_joint_actuator(i).joint().name()): plant.get_joint_actuator(i)
        for i in plant.GetJointActuatorIndices(instance)
    }
    name = plant.GetModelInstanceName(instance)
    for joint_name, limit in motors.items():
        found = drake_joint(plant, joint_name, instance)
        if found is None:
            raise SimulationError(f"model '{name}' has no joint '{joint_name}' for a motor")
        joint = plant.GetJointByName(found, instance)
        if joint.num_velocities() != 1:
            raise SimulationError(f"joint '{joint_name}' of '{name}' is not a 1-dof joint")
        actuator = actuated.get(joint_name)
        if actuator is None:
            actuator = plant.AddJointActuator(
                f"{joint_name}_velocity_motor", joint, max(float(limit), 0.0)
            )
        actuator.set_controller_gains(PdControllerGains(p=0.0, d=MOTOR_DAMPING))


def fix_motor_targets(
    plant: Any, plant_context: Any, instance: Any, targets: Mapping[str, float]
) -> None:
    """Hold the motors of ``instance`` at ``{joint: velocity}`` (rad/s or m/s; others at 0)."""
    indices = plant.GetJointActuatorIndices(instance)
    if not indices:
        return
    velocities = [
        float(targets.get(shown_name(plant.get_joint_actuator(i).joint().name()), 0.0))
        for i in indices
    ]
    desired = np.concatenate([np.zeros(len(indices)), velocities])
    plant.get_desired_state_input_port(instance).FixValue(plant_context, desired)


def motor_efforts(plant: Any, plant_context: Any, instance: Any) -> dict[str, float]:
    """``{joint: effort}`` the motors of ``instance`` applied in the last step, N m or N."""
    indices = plant.GetJointActuatorIndices(instance)
    if not indices:
        return {}
    values = plant.get_net_actuation_output_port(instance).Eval(plant_context)
    return {
        shown_name(plant.get_joint_actuator(i).joint().name()): float(values[k])
        for k, i in enumerate(indices)
    }
