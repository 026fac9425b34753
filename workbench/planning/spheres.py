"""A sphere model of the robot, checked against the scene for many configurations at once.

Planning spends nearly all its time asking "is this configuration free?".
:class:`SphereChecker` answers it with a sphere model of the robot:

* every collision shape of every robot body is covered by spheres centred deep
  inside it that bulge out of its surface by about a centimetre (boxes,
  cylinders and meshes — which Drake checks as their convex hulls — through
  :func:`~workbench.planning.sphere_cover.cover_shape`), so the model
  over-approximates the robot;
* the spheres are grouped per body into small clusters with bounding spheres
  (:mod:`workbench.planning.sphere_layout`), so a check descends to single
  spheres only near an obstacle or another link;
* forward kinematics of the planning group's joints is a Rodrigues step per
  joint (batched in numpy for the reference, one loop in the compiled kernel);
* spheres are tested against the scene's primitives (sphere, box, cylinder;
  meshes by their bounding box) and against each other for the body pairs
  the exact checker does not filter (SRDF disabled pairs, adjacent and welded
  bodies, and pairs whose relative pose the group's joints cannot change);
  body pairs that sit close together in many poses also get a table of their
  exact distance over the (at most two) joints between them, which clears
  them where the spheres cannot.

Because the spheres cover the geometry, a configuration the sphere model
accepts is free for the exact geometry too; the planner still re-checks the
final trajectory with Drake's exact checker before returning it.

The planner's checks (:meth:`SphereChecker.configs_free`, :meth:`~SphereChecker.is_free`,
:meth:`~SphereChecker.motion_status`) run in the compiled kernel of
:mod:`workbench.planning.sphere_kernel`, which stops at the first collision;
:meth:`SphereChecker.configs_free_reference` is the numpy version it is tested against.
"""

from __future__ import annotations

import math
import time

import numpy as np

from workbench.planning import sphere_kernel
from workbench.planning.collision import CollisionWorld, JointMap
from workbench.planning.obstacles import ObstacleSet
from workbench.planning.sphere_cover import cover_shape, load_sphere_model  # noqa: F401
from workbench.planning.sphere_kernel import EPS as _EPS
from workbench.planning.sphere_layout import build_layout
from workbench.spatial import matrix_from_rigid_transform

_transform = matrix_from_rigid_transform


class SphereChecker:
    """Vectorised collision checks of a planning group's configurations with a sphere model.

    Args:
        world: The exact collision world (its plant, filters and obstacles are reused).
        joints: The planning group and the values of the joints outside it.
        padding: Extra radius added to every sphere, metres.
        seed: Seed of the mesh clustering.
        sphere_model: Spheres per link (see :func:`load_sphere_model`) to use instead of
            covering those links' geometry.
    """

    def __init__(
        self,
        world: CollisionWorld,
        joints: JointMap,
        *,
        padding: float = 0.0,
        seed: int = 0,
        sphere_model: dict[str, tuple[np.ndarray, np.ndarray]] | None = None,
    ):
        self.world = world
        self.joints = joints
        plant = world.plant
        context = plant.CreateDefaultContext()
        plant.SetPositions(context, joints.base)
        group_joints = {
            plant.GetJointByName(n, world.instance).index(): i for i, n in enumerate(joints.names)
        }

        # Bodies in topological order with their parent and the joint between.
        order, parent_of, joint_of = [plant.world_body().index()], {}, {}
        children: dict = {}
        for j in plant.GetJointIndices():
            joint = plant.get_joint(j)
            children.setdefault(joint.parent_body().index(), []).append(joint)
        queue = [plant.world_body().index()]
        while queue:
            b = queue.pop(0)
            for joint in children.get(b, []):
                c = joint.child_body().index()
                parent_of[c], joint_of[c] = b, joint
                order.append(c)
                queue.append(c)
        # Only joints of the group get a slot of their own: a body attached by a fixed
        # (or held) joint rides in its parent's slot with a constant offset.
        # X_PC(q) = X_PF R(q) X_MC = M0 + sin(q) M1 + (1 - cos(q)) M2 (Rodrigues), so each
        # step is one product of the coefficients with a (3, 16) stack.
        self._steps = []  # (child slot, parent slot, group index, (3, 16) stack)
        slot = {plant.world_body().index(): 0}
        offset = {plant.world_body().index(): np.eye(4)}  # X_slot_body
        depends: dict = {plant.world_body().index(): frozenset()}
        self._prismatic = np.zeros(len(joints.names), dtype=bool)
        for b in order[1:]:
            joint, p = joint_of[b], parent_of[b]
            gi = group_joints.get(joint.index())
            if gi is None:
                X_PC = _transform(
                    plant.CalcRelativeTransform(
                        context, plant.get_body(p).body_frame(), plant.get_body(b).body_frame()
                    )
                )
                slot[b], offset[b], depends[b] = slot[p], offset[p] @ X_PC, depends[p]
                continue
            X_PF = offset[p] @ _transform(joint.frame_on_parent().GetFixedPoseInBodyFrame())
            X_MC = np.linalg.inv(_transform(joint.frame_on_child().GetFixedPoseInBodyFrame()))
            kind = type(joint).__name__
            if kind == "RevoluteJoint":
                x, y, z = np.asarray(joint.revolute_axis(), float) / np.linalg.norm(
                    joint.revolute_axis()
                )
                K = np.zeros((4, 4))
                K[:3, :3] = [[0, -z, y], [z, 0, -x], [-y, x, 0]]
                stack = [X_PF @ X_MC, X_PF @ K @ X_MC, X_PF @ K @ K @ X_MC]
            elif kind == "PrismaticJoint":
                axis = np.asarray(joint.translation_axis(), float)
                T = np.zeros((4, 4))
                T[:3, 3] = axis / np.linalg.norm(axis)
                stack = [X_PF @ X_MC, X_PF @ T @ X_MC, np.zeros((4, 4))]
                self._prismatic[gi] = True
            else:
                raise TypeError(f"joint '{joint.name()}' of type {kind} cannot be planned")
            slot[b] = len(self._steps) + 1
            offset[b] = np.eye(4)
            depends[b] = depends[p] | {gi}
            self._steps.append((slot[b], slot[p], gi, np.array(stack).reshape(3, 16)))
        self._num_slots = len(self._steps) + 1
        self._offset_by_name = {plant.get_body(b).name(): offset[b] for b in slot}
        self._slot_by_name = {plant.get_body(b).name(): k for b, k in slot.items()}

        # Spheres per robot body.
        inspector = world.scene_graph.model_inspector()
        centres, radii, owner = [], [], []
        robot_bodies = [plant.get_body(b) for b in plant.GetBodyIndices(world.instance)]
        for body in robot_bodies:
            if sphere_model and body.name() in sphere_model:
                c, r = sphere_model[body.name()]
                X_SB = offset[body.index()]
                centres.append(np.asarray(c, float) @ X_SB[:3, :3].T + X_SB[:3, 3])
                radii.append(np.asarray(r, float) + padding)
                owner += [body.index()] * len(r)
                continue
            for gid in plant.GetCollisionGeometriesForBody(body):
                c, r = cover_shape(inspector.GetShape(gid))
                X_BG = offset[body.index()] @ _transform(inspector.GetPoseInFrame(gid))
                centres.append(c @ X_BG[:3, :3].T + X_BG[:3, 3])
                radii.append(r + padding)
                owner += [body.index()] * len(r)
        local = np.vstack(centres) if centres else np.zeros((0, 3))
        radius = np.concatenate(radii) if radii else np.zeros(0)
        owner_body = np.array([int(b) for b in owner], dtype=int)
        owner_slot = np.array([slot[b] for b in owner], dtype=int)
        depends_of = {int(b): depends[b] for b in slot}

        # Spheres reordered into bodies and clusters (see sphere_layout).
        layout = build_layout(local, radius, owner_body, owner_slot)
        self.layout = layout
        self.local = local[layout.order]
        self._local_h = np.hstack([self.local, np.ones((len(self.local), 1))])[:, :, None]
        self.radii = radius[layout.order]
        self.owner_slot = owner_slot[layout.order]
        self._part_spheres = [
            np.arange(layout.cluster_spheres[c0, 0], layout.cluster_spheres[c1 - 1, 1])
            for c0, c1 in layout.part_clusters
        ]
        # Bodies that move with the group check the environment.
        self._env_parts = np.array(
            [k for k, b in enumerate(layout.part_body) if depends_of[int(b)]], dtype=int
        )
        self.env_spheres = (
            np.concatenate([self._part_spheres[k] for k in self._env_parts])
            if len(self._env_parts)
            else np.zeros(0, int)
        )

        # Self pairs: robot body pairs not filtered whose relative pose the group changes
        # (bodies with the same group joints above them never move relative to each other).
        filtered = world.checker.GetFilteredCollisionMatrix()
        pairs = []
        for i, a in enumerate(layout.part_body):
            for j in range(i + 1, len(layout.part_body)):
                b = layout.part_body[j]
                if filtered[int(a), int(b)] == 0 and depends_of[int(a)] != depends_of[int(b)]:
                    pairs.append((i, j))
        self._pairs = np.array(pairs, dtype=int).reshape(-1, 2)
        self.obstacles = ObstacleSet(world)
        self.checks = 0
        self._slot_depends = {slot[b]: depends[b] for b in slot}
        self._slot_bodies: dict[int, list[str]] = {}
        for b, k in slot.items():
            if b != plant.world_body().index():
                self._slot_bodies.setdefault(k, []).append(plant.get_body(b).name())
        self._grid_list: list[tuple] = []
        self._pair_grid_index = np.full(len(self._pairs), -1, dtype=int)
        self._build_pair_grids(seed)
        self._build_field(seed)
        self._kernel = sphere_kernel.pack(self.kernel_data(), self._num_slots)
        # Compile the kernel (or load it from numba's cache) here, once per process, so
        # that no plan's timing includes it.
        began = time.perf_counter()
        q = np.clip(np.zeros(len(joints.names)), *self._limits())
        self.configs_free(q[None, :])
        self.is_free(q)
        self.motion_status(q, q, 1.0)
        self.checks = 0
        #: Seconds the first kernel calls took (compilation or cache load in the first checker).
        self.kernel_load_seconds = time.perf_counter() - began
        _KERNEL_LOAD.append(self.kernel_load_seconds)

    def _limits(self) -> tuple[np.ndarray, np.ndarray]:
        """The group's joint limits, ±π where a joint has none."""
        lower, upper = self.world.position_limits()
        lo = np.where(np.isfinite(lower), lower, -np.pi)[self.joints.indices]
        hi = np.where(np.isfinite(upper), upper, np.pi)[self.joints.indices]
        return lo, hi

    def kernel_data(self) -> tuple:
        """The model packed for :mod:`workbench.planning.sphere_kernel` (its ``FIELDS``)."""
        obs = self.obstacles
        layout = self.layout
        i64 = np.int64
        J = len(self._steps)
        step_stack = np.zeros((J, 3, 4, 4))
        for k, (_, _, _, stack) in enumerate(self._steps):
            step_stack[k] = stack.reshape(3, 4, 4)
        has_field = getattr(obs, "field", None) is not None
        G = len(self._grid_list)
        grid_joints = np.full((G, 2), -1, dtype=i64)
        grid_origin = np.zeros((G, 2))
        grid_shape = np.ones((G, 2), dtype=i64)
        grid_spec = np.zeros((G, 2))
        grid_offset = np.zeros(G, dtype=i64)
        tables, offset = [], 0
        for g, (between, origin, step, table, margin) in enumerate(self._grid_list):
            d = len(between)
            grid_joints[g, :d] = between
            grid_origin[g, :d] = origin
            grid_shape[g, :d] = table.shape
            grid_spec[g] = step, margin
            grid_offset[g] = offset
            tables.append(np.ravel(table))
            offset += table.size
        pa, pb = self._pairs[:, 0], self._pairs[:, 1]
        reach = layout.part_radius[pa] + layout.part_radius[pb] + _EPS

        def f64(a, *shape):
            return np.ascontiguousarray(np.asarray(a, float).reshape(*shape))

        def ints(a, *shape):
            return np.ascontiguousarray(np.asarray(a, i64).reshape(*shape))

        return (
            ints([c for c, _, _, _ in self._steps], -1),
            ints([p for _, p, _, _ in self._steps], -1),
            ints([gi for _, _, gi, _ in self._steps], -1),
            step_stack,
            np.ascontiguousarray(self._prismatic, dtype=np.int64),
            f64(self.local, -1, 3),
            f64(self.radii, -1),
            ints(layout.cluster_slot, -1),
            f64(layout.cluster_centre, -1, 3),
            f64(layout.cluster_radius, -1),
            ints(layout.cluster_spheres, -1, 2),
            ints(layout.part_slot, -1),
            f64(layout.part_centre, -1, 3),
            f64(layout.part_radius, -1),
            ints(layout.part_clusters, -1, 2),
            ints(self._env_parts if obs.any else [], -1),
            np.array([has_field], dtype=np.int64),
            np.ascontiguousarray(obs.field if has_field else np.zeros((1, 1, 1)), np.float32),
            f64(obs.field_lo if has_field else np.zeros(3), 3),
            f64([obs.field_h, obs.field_slack] if has_field else [1.0, 0.0], 2),
            f64(obs.sphere_c, -1, 3),
            f64(obs.sphere_r, -1),
            f64(obs.box_R, -1, 3, 3),
            f64(obs._box_off, -1, 3),
            f64(obs.box_h, -1, 3),
            f64(obs.cyl_R, -1, 3, 3),
            f64(obs._cyl_off, -1, 3),
            f64(np.stack([obs.cyl_r, obs.cyl_h], axis=1) if len(obs.cyl_r) else [], -1, 2),
            grid_joints,
            grid_origin,
            grid_shape,
            grid_spec,
            grid_offset,
            f64(np.concatenate(tables) if tables else np.zeros(1), -1),
            ints(self._pairs, -1, 2),
            f64(reach * reach, -1),
            ints(self._pair_grid_index, -1),
        )

    def _build_field(self, seed: int, spacing: float = 0.02) -> None:
        """The obstacles' distance table over the region the robot's spheres can reach."""
        if not self.obstacles.any or not len(self.env_spheres):
            return
        rng = np.random.default_rng(seed)
        lower, upper = self.world.position_limits()
        lo = np.where(np.isfinite(lower), lower, -np.pi)[self.joints.indices]
        hi = np.where(np.isfinite(upper), upper, np.pi)[self.joints.indices]
        centres = self.sphere_centres(rng.uniform(lo, hi, size=(256, len(lo))))[:, self.env_spheres]
        reach = float(self.radii[self.env_spheres].max()) + 0.1
        box_lo = centres.reshape(-1, 3).min(axis=0) - reach
        box_hi = centres.reshape(-1, 3).max(axis=0) + reach
        self.obstacles.build_field(box_lo, box_hi, spacing)

    def _build_pair_grids(self, seed: int, samples: int = 200, grid_step: float = 0.05) -> None:
        """Exact distance tables for body pairs whose spheres often overlap.

        Some bodies sit so close to each other (the Panda's wrist and hand) that their
        covering spheres overlap in many poses although the geometry does not. When
        such a pair's relative pose depends on at most two of the group's joints, the
        exact signed distance is tabulated over those joints every ``grid_step`` rad;
        a configuration whose nearest table entry exceeds what the joints' half-step
        can change it by is free for that pair, and the spheres decide otherwise.
        Tables depend on the robot only and are kept on disk (:meth:`_cached_pair_grid`).
        """
        if not len(self._pairs):
            return
        rng = np.random.default_rng(seed)
        lo, hi = self._limits()
        Q = rng.uniform(lo, hi, size=(samples, len(lo)))
        centres = self.sphere_centres(Q)
        layout = self.layout
        by_slots: dict[tuple[int, int], list[int]] = {}
        for k, (pa, pb) in enumerate(self._pairs):
            by_slots.setdefault((int(layout.part_slot[pa]), int(layout.part_slot[pb])), []).append(
                k
            )
        for (sa, sb), ks in by_slots.items():
            between = sorted(self._slot_depends[sa] ^ self._slot_depends[sb])
            if not 1 <= len(between) <= 2:
                continue
            overlap = np.zeros(samples, dtype=bool)
            for k in ks:
                overlap |= self._parts_touch(centres, *self._pairs[k])
            if overlap.mean() < 0.2:
                continue
            self._pair_grid_index[ks] = len(self._grid_list)
            self._grid_list.append(self._cached_pair_grid(sa, sb, between, lo, hi, grid_step))

    def _cached_pair_grid(self, sa: int, sb: int, between: list[int], lo, hi, step: float):
        """:meth:`_pair_grid`, kept on disk (:mod:`workbench.planning.array_cache`) under a
        digest of what it depends on: the robot description, the collision filter, the group and
        the fixed joints' values, both bodies' names and sphere covers, and the grid."""
        from workbench.planning.array_cache import cached_arrays, digest

        # The description's text is the file's (xacro expanded), already in memory.
        robot_text = self.world.robot.description.text.encode()
        own = [np.nonzero(self.owner_slot == k)[0] for k in (sa, sb)]
        key = digest(
            robot_text,
            np.asarray(self.world.checker.GetFilteredCollisionMatrix()),
            tuple(self.joints.names),
            np.asarray(self.joints.base, float),
            sorted(self._slot_bodies[sa]),
            sorted(self._slot_bodies[sb]),
            *(np.round(self.local[i], 9) for i in own),
            *(np.round(self.radii[i], 9) for i in own),
            tuple(between),
            np.asarray(lo, float),
            np.asarray(hi, float),
            step,
        )

        def compute() -> dict[str, np.ndarray]:
            joints, origin, _, table, reach = self._pair_grid(sa, sb, between, lo, hi, step)
            return {"joints": joints, "origin": origin, "table": table, "reach": np.array(reach)}

        grid = cached_arrays("pair-distance-tables", key, compute)
        return grid["joints"], grid["origin"], step, grid["table"], float(grid["reach"])

    def _pair_grid(self, sa: int, sb: int, between: list[int], lo, hi, step: float):
        names_a, names_b = set(self._slot_bodies[sa]), set(self._slot_bodies[sb])
        plant = self.world.plant
        axes = [np.arange(lo[j], hi[j] + step, step) for j in between]
        shape = tuple(len(a) for a in axes)
        table = np.full(shape, np.inf)
        base = self.joints.group(self.joints.base).copy()
        influence = 0.1
        for index in np.ndindex(shape):
            q = base.copy()
            for axis, j, i in zip(axes, between, index, strict=True):
                q[j] = axis[i]
            clearance = self.world.checker.CalcRobotClearance(self.joints.full(q), influence)
            for a, b, dist in zip(
                clearance.robot_indices(),
                clearance.other_indices(),
                clearance.distances(),
                strict=True,
            ):
                na, nb = plant.get_body(a).name(), plant.get_body(b).name()
                if (na in names_a and nb in names_b) or (na in names_b and nb in names_a):
                    table[index] = min(table[index], dist)
        # How far the pair's closest points can move while each joint moves half a step.
        reach = 0.0
        for j in between:
            points = self._slot_points(sa) if j in self._slot_depends[sa] else self._slot_points(sb)
            reach += self._lever(j, points) * step / 2
        return np.array(between), np.array([a[0] for a in axes]), step, table, reach

    def _slot_points(self, slot: int) -> np.ndarray:
        return np.nonzero(self.owner_slot == slot)[0]

    def _lever(self, joint: int, spheres: np.ndarray) -> float:
        """Largest distance of a sphere's surface from ``joint``'s axis, over many poses, m."""
        rng = np.random.default_rng(1)
        lower, upper = self.world.position_limits()
        lo = np.where(np.isfinite(lower), lower, -np.pi)[self.joints.indices]
        hi = np.where(np.isfinite(upper), upper, np.pi)[self.joints.indices]
        Q = rng.uniform(lo, hi, size=(32, len(lo)))
        X = self.body_transforms(Q)
        child = next(c for c, _, gi, _ in self._steps if gi == joint)
        centres = self.sphere_centres(Q)[:, spheres]
        origin = X[:, child, :3, 3][:, None, :]
        # a conservative lever: distance to the joint's origin (not just its axis)
        return float(np.max(np.linalg.norm(centres - origin, axis=-1) + self.radii[spheres]))

    @property
    def num_spheres(self) -> int:
        """Number of spheres in the robot model."""
        return len(self.radii)

    def body_transforms(self, Q: np.ndarray) -> np.ndarray:
        """World poses (N, slots, 4, 4) of the moving frames for group configurations ``Q`` (N, n).

        Slot 0 is the world; each group joint's child body has a slot (see :meth:`body_pose`).
        """
        n = len(Q)
        coef = np.empty((n, Q.shape[1], 3))
        coef[..., 0] = 1.0
        coef[..., 1] = np.where(self._prismatic, Q, np.sin(Q))
        coef[..., 2] = np.where(self._prismatic, 0.0, 1.0 - np.cos(Q))
        X = np.empty((n, self._num_slots, 4, 4))
        X[:, 0] = np.eye(4)
        for child, parent, gi, stack in self._steps:
            X_PC = (coef[:, gi] @ stack).reshape(n, 4, 4)
            X[:, child] = X_PC if parent == 0 else X[:, parent] @ X_PC
        return X

    def body_pose(self, X: np.ndarray, body_name: str) -> np.ndarray:
        """A body's world poses (N, 4, 4) from :meth:`body_transforms`'s result."""
        return X[:, self._slot_by_name[body_name]] @ self._offset_by_name[body_name]

    def sphere_centres(self, Q: np.ndarray) -> np.ndarray:
        """World centres (N, S, 3) of the robot's spheres."""
        X = self.body_transforms(np.atleast_2d(Q))
        Xs = X[:, self.owner_slot, :3, :]
        return (Xs @ self._local_h)[..., 0]

    def configs_free(self, Q: np.ndarray) -> np.ndarray:
        """Which group configurations (rows of ``Q``) the sphere model finds free (compiled)."""
        Q = np.ascontiguousarray(np.atleast_2d(np.asarray(Q, float)))
        self.checks += len(Q)
        return sphere_kernel.configs_free(Q, *self._kernel)

    def is_free(self, q: np.ndarray) -> bool:
        """One group configuration (compiled)."""
        self.checks += 1
        return sphere_kernel.config_free(np.asarray(q, float), *self._kernel)

    def motion_status(self, qa: np.ndarray, qb: np.ndarray, step: float) -> tuple[int, int]:
        """Check the motion qa→qb every ``step`` (max-norm), ends first, stopping at a collision.

        Returns:
            ``(status, samples checked)``: 1 free, 0 both ends free but a sample between
            collides, -1 an end collides (see :meth:`edge_samples` and :meth:`configs_free`
            for the per-sample answer).
        """
        status, checked = sphere_kernel.motion_status(
            np.asarray(qa, float), np.asarray(qb, float), float(step), *self._kernel
        )
        self.checks += checked
        return status, checked

    def configs_free_reference(self, Q: np.ndarray) -> np.ndarray:
        """The numpy version of :meth:`configs_free`, the reference for the compiled kernel.

        Every moving sphere against every obstacle primitive; every sphere pair of every
        self-collision body pair, unless the pair's distance table clears it. The kernel
        accepts no configuration this rejects (it grows radii by
        :data:`~workbench.planning.sphere_kernel.EPS` against rounding).
        """
        Q = np.atleast_2d(np.asarray(Q, float))
        n = len(Q)
        centres = self.sphere_centres(Q)
        bad = np.zeros(n, dtype=bool)
        env = self.env_spheres
        if len(env) and self.obstacles.any:
            hits = self.obstacles.hit(centres[:, env].reshape(-1, 3), np.tile(self.radii[env], n))
            bad |= hits.reshape(n, len(env)).any(axis=1)
        for k, (pa, pb) in enumerate(self._pairs):
            touch = self._parts_touch(centres, pa, pb)
            g = self._pair_grid_index[k]
            if g >= 0:
                between, origin, step, table, margin = self._grid_list[g]
                index = np.rint((Q[:, between] - origin) / step).astype(np.intp)
                np.clip(index, 0, np.array(table.shape) - 1, out=index)
                touch &= ~(table[tuple(index.T)] > margin)
            bad |= touch
        return ~bad

    def _parts_touch(self, centres: np.ndarray, pa: int, pb: int) -> np.ndarray:
        """Whether any sphere of body part ``pa`` touches one of ``pb``, per configuration.

        ``centres``: (N, S, 3) from :meth:`sphere_centres`; returns (N,) bool.
        """
        a, b = self._part_spheres[pa], self._part_spheres[pb]
        d2 = ((centres[:, a, None] - centres[:, None, b]) ** 2).sum(-1)
        return (d2 < (self.radii[a, None] + self.radii[None, b]) ** 2).any(axis=(1, 2))

    def edge_samples(self, qa: np.ndarray, qb: np.ndarray, step: float) -> np.ndarray:
        """Configurations on the segment qa→qb every ``step`` (max-norm), coarse to fine."""
        qa, qb = np.asarray(qa, float), np.asarray(qb, float)
        count = max(1, math.ceil(np.max(np.abs(qb - qa)) / step))
        t = np.linspace(0.0, 1.0, count + 1)[_bisection_order(count + 1)]
        return qa + (qb - qa) * t[:, None]


_BISECTION_CACHE: dict[int, np.ndarray] = {}
_KERNEL_LOAD: list[float] = []


def kernel_load_seconds() -> float:
    """Seconds the compiled kernel took to compile or load in this process (0 before use)."""
    return max(_KERNEL_LOAD, default=0.0)


def _bisection_order(n: int) -> np.ndarray:
    """Indices 0..n-1 ordered ends first, then midpoints of ever finer halvings."""
    cached = _BISECTION_CACHE.get(n)
    if cached is not None:
        return cached
    order, seen = [], set()
    for i in (0, n - 1):
        if i not in seen:
            order.append(i)
            seen.add(i)
    level = 2
    while len(order) < n:
        for k in range(1, level, 2):
            i = round(k * (n - 1) / level)
            if i not in seen:
                order.append(i)
                seen.add(i)
        level *= 2
        if level > 4 * n:
            order += [i for i in range(n) if i not in seen]
            break
    result = np.array(order[:n], dtype=int)
    _BISECTION_CACHE[n] = result
    return result
