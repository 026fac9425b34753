"""State and motion validity for the planner: the sphere model first, exact geometry to confirm.

A configuration the sphere model accepts is free (the spheres cover the
geometry). One it rejects may still be free — the spheres are larger than
the links. By default the planner treats what the spheres reject as invalid
(it gives up the thin margin around obstacles, as sphere-based planners
do); only the start and goal, which may lie inside that margin, are
confirmed with Drake's exact checker. With ``confirm=True`` every rejected
sample is confirmed exactly (the exact free space, at a higher cost).
Motions are sampled every ``step`` (max-norm over joints, rad or m) and go
through the compiled sphere kernel in one call (ends first, then midpoints,
stopping at the first collision). When both ends are clear of the spheres
the motion must be clear of them too; a motion to a state the spheres reject
is refused unless that state is the start or goal (OMPL asks for motions to
states it has not checked); when an end that is the start or goal lies inside
the margin (next to an obstacle) the rejected samples leading out of it are
confirmed exactly. Without a sphere model every sample goes to the exact
checker.
"""

from __future__ import annotations

import numpy as np

from workbench.planning.collision import CollisionWorld, JointMap
from workbench.planning.spheres import SphereChecker


class Validity:
    """Validity callbacks for OMPL over a planning group's joint values.

    Args:
        world: The exact collision world.
        joints: The group's joints within the full position vector.
        step: Largest joint change between checked samples of a motion (rad or m).
        spheres: The sphere model, or None to check every sample exactly.
        confirm: Confirm every sphere rejection exactly (exact semantics, slower) instead
            of giving up the spheres' margin.
    """

    def __init__(
        self,
        world: CollisionWorld,
        joints: JointMap,
        step: float,
        spheres: SphereChecker | None,
        *,
        confirm: bool = False,
    ) -> None:
        self.world = world
        self.joints = joints
        self.step = float(step)
        self.spheres = spheres
        self.confirm = confirm
        self.exact_checks = 0
        self.sphere_checks = 0
        self.motions = 0

    def _exact(self, q_group: np.ndarray) -> bool:
        self.exact_checks += 1
        return self.world.is_free(self.joints.full(q_group))

    def trust(self, *configurations: np.ndarray) -> None:
        """Configurations (start, goal) whose sphere rejections are confirmed exactly."""
        self._trusted = {np.asarray(q, float).tobytes() for q in configurations}

    def state_valid(self, q: np.ndarray) -> bool:
        """True when the group configuration ``q`` is free (of the spheres' margin, except at
        the trusted start and goal, which are checked exactly)."""
        if self.spheres is None:
            return self._exact(q)
        self.sphere_checks += 1
        if self.spheres.is_free(q):
            return True
        if self.confirm or self._trusted_state(q):
            return self._exact(q)
        return False

    def _trusted_state(self, q: np.ndarray) -> bool:
        return np.asarray(q, float).tobytes() in getattr(self, "_trusted", ())

    def motion_valid(self, qa: np.ndarray, qb: np.ndarray) -> bool:
        """True when every sample of the straight motion qa→qb is collision-free (qa assumed free)."""
        self.motions += 1
        if self.spheres is not None:
            # Compiled: ends first, then midpoints, stopping at the first collision.
            status, checked = self.spheres.motion_status(qa, qb, self.step)
            self.sphere_checks += checked
            if status == 1:
                return True  # every sample clear of the spheres, hence free
            if not self.confirm:
                if status == 0:
                    # Both ends are clear of the spheres' margin: so must the motion be.
                    return False
                if checked == 2 and not self._trusted_state(qb):
                    # qb is rejected and is neither the start nor the goal: state_valid would
                    # refuse it too (OMPL asks for motions to states it has not checked yet).
                    return False
            samples = self.spheres.edge_samples(qa, qb, self.step)  # [qa, qb, midpoints...]
            self.sphere_checks += len(samples)
            free = self.spheres.configs_free(samples)
            if self.confirm:
                return all(self._exact(q) for q in samples[1:][~free[1:]])
            if free[0] and free[1]:
                # Both ends are clear of the spheres' margin: so must the motion be.
                return bool(free.all())
            # An end inside the margin (a trusted start or goal next to an obstacle): the
            # samples leading out of the margin from that end are confirmed exactly; a
            # rejection anywhere else refutes the motion.
            along = np.argsort(np.linalg.norm(samples - samples[0], axis=1), kind="stable")
            free_along = free[along]
            clear = np.nonzero(free_along)[0]
            if len(clear) == 0:
                suspects = samples[along[1:]]
            else:
                first, last = clear[0], clear[-1]
                if not free_along[first : last + 1].all():
                    return False
                ends = np.concatenate([along[1:first], along[last + 1 :]])
                suspects = samples[ends]
        return all(self._exact(q) for q in suspects)
