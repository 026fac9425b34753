"""Inverse kinematics of a planning group's tip with Drake's InverseKinematics.

The tip link's origin is constrained to a box of ±``tolerance`` around the
target point in the world frame (and, optionally, its orientation to within
``angle_tolerance``). Joints outside the group are held at their current
values, the group's joints stay within their limits, and each solution is
rejected unless the exact collision checker finds it free. Random restarts
(seeded) try new initial guesses until one succeeds.
"""

from __future__ import annotations

import numpy as np

from workbench import spatial
from workbench.planning.collision import CollisionWorld, JointMap
from workbench.planning.errors import IKError


def solve_ik(
    world: CollisionWorld,
    joints: JointMap,
    tip_link: str,
    xyz: np.ndarray,
    *,
    rpy: np.ndarray | None = None,
    seed: int = 0,
    restarts: int = 30,
    tolerance: float = 0.0002,
    angle_tolerance: float = 0.01,
    q_seed: np.ndarray | None = None,
) -> np.ndarray:
    """Group joint values that put ``tip_link``'s origin at ``xyz`` (world frame, metres).

    Args:
        world: The robot and scene (collision-rejects solutions).
        joints: The group's joints; joints outside it stay at ``joints.base``.
        tip_link: The link whose origin must reach the point.
        xyz: Target position in the world frame, metres.
        rpy: Optional target orientation (fixed-axis roll, pitch, yaw, radians).
        seed: Seed of the random restarts.
        restarts: Number of initial guesses (the first is ``q_seed`` when given).
        tolerance: Half-width of the position box, metres (0.2 mm keeps the error under 0.35 mm).
        angle_tolerance: Orientation tolerance, radians.
        q_seed: First initial guess (group values), e.g. the start state.

    Raises:
        IKError: No collision-free solution within the limits was found.
    """
    from pydrake.math import RigidTransform, RotationMatrix
    from pydrake.multibody.inverse_kinematics import InverseKinematics
    from pydrake.solvers import Solve

    plant = world.plant
    if not plant.HasBodyNamed(tip_link, world.instance):
        raise IKError(f"the robot has no link '{tip_link}' to place")
    tip = plant.GetBodyByName(tip_link, world.instance).body_frame()
    xyz = np.asarray(xyz, float).reshape(3)
    lower, upper = world.position_limits()
    lower_g = np.where(np.isfinite(lower[joints.indices]), lower[joints.indices], -np.pi)
    upper_g = np.where(np.isfinite(upper[joints.indices]), upper[joints.indices], np.pi)
    rng = np.random.default_rng(seed)
    guesses = [] if q_seed is None else [np.asarray(q_seed, float)]
    while len(guesses) < restarts:
        guesses.append(rng.uniform(lower_g, upper_g))
    context = plant.CreateDefaultContext()
    found_any = False
    for guess in guesses:
        ik = InverseKinematics(plant, with_joint_limits=True)
        q = ik.q()
        ik.AddPositionConstraint(
            tip, np.zeros(3), plant.world_frame(), xyz - tolerance, xyz + tolerance
        )
        if rpy is not None:
            R = spatial.rotation_matrix(rpy)
            ik.AddOrientationConstraint(
                plant.world_frame(), R, tip, RotationMatrix(), angle_tolerance
            )
        prog = ik.get_mutable_prog()
        outside = np.setdiff1d(np.arange(len(joints.base)), joints.indices)
        for i in outside:
            prog.AddBoundingBoxConstraint(joints.base[i], joints.base[i], q[i])
        initial = joints.full(guess)
        result = Solve(prog, initial)
        if not result.is_success():
            continue
        q_full = result.GetSolution(q)
        plant.SetPositions(context, q_full)
        reached = plant.CalcRelativeTransform(context, plant.world_frame(), tip)
        if (
            not isinstance(reached, RigidTransform)
            or np.linalg.norm(reached.translation() - xyz) > 1e-3
        ):
            continue
        found_any = True
        q_group = np.clip(joints.group(q_full), lower_g, upper_g)
        if world.is_free(joints.full(q_group)):
            return q_group
    where = f"({xyz[0]:.3f}, {xyz[1]:.3f}, {xyz[2]:.3f})"
    if found_any:
        raise IKError(
            f"every IK solution placing '{tip_link}' at {where} collides",
            hint="choose a point away from obstacles",
        )
    raise IKError(
        f"no joint values within the limits put '{tip_link}' at {where} m "
        f"(tried {len(guesses)} starts)",
        hint="the point is probably out of reach; choose one closer to the robot",
    )
