"""Exact collision checking of a robot in a planning scene with Drake's SceneGraphCollisionChecker.

:class:`CollisionWorld` loads the robot into a Drake ``RobotDiagram`` with
``workbench.model.load_robot`` (root link welded to the world: the SRDF's
fixed virtual joint), adds the scene's
obstacles as world geometry, and builds a ``SceneGraphCollisionChecker`` that
honours the SRDF's disabled collision pairs on top of Drake's own filters
(adjacent bodies, bodies welded together). Mesh geometry is checked as its
convex hull, as Drake does for point-pair queries.

Configurations passed here are *full* plant position vectors (every movable
joint of the robot, in plant order); :class:`JointMap` converts between a
planning group's joint values and full vectors.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workbench import spatial
from workbench.errors import ModelError
from workbench.planning.errors import SceneError
from workbench.planning.scene import PlanningScene, SceneObject


@dataclass
class JointMap:
    """Where a planning group's joints sit in the full position vector.

    Attributes:
        names: The group's joint names, in planning order.
        indices: Their indices in the full plant position vector.
        base: The full position vector used for joints outside the group.
    """

    names: list[str]
    indices: np.ndarray
    base: np.ndarray

    def full(self, q_group: np.ndarray) -> np.ndarray:
        """Full position vector(s) from group values; works on (n,) or (N, n) arrays."""
        q_group = np.asarray(q_group, float)
        if q_group.ndim == 1:
            q = self.base.copy()
            q[self.indices] = q_group
            return q
        q = np.repeat(self.base[None, :], len(q_group), axis=0)
        q[:, self.indices] = q_group
        return q

    def group(self, q_full: np.ndarray) -> np.ndarray:
        """Group values from full position vector(s)."""
        return np.asarray(q_full, float)[..., self.indices]


def drake_shape(obj: SceneObject):
    """The pydrake shape of a scene object (a mesh as its convex hull, as collision sees it)."""
    return spatial.drake_shape(obj.shape, convex_mesh=True)


def add_scene_to_plant(plant, scene: PlanningScene) -> None:
    """Register every scene object as collision geometry on the world body."""
    from pydrake.geometry import ProximityProperties

    for obj in scene:
        try:
            plant.RegisterCollisionGeometry(
                plant.world_body(),
                spatial.as_rigid_transform(obj.X_WO),
                drake_shape(obj),
                f"scene::{obj.name}",
                ProximityProperties(),
            )
        except (RuntimeError, ValueError) as error:
            reason = " ".join(str(error).split())
            raise SceneError(
                f"object '{obj.name}': Drake cannot use it: {reason}", path=scene.source
            ) from None


class CollisionWorld:
    """A robot welded to the world, a planning scene, and an exact collision checker.

    Args:
        robot_source: A ``urdf/`` name, a URDF, SDF or xacro path, a ``RobotDescription``
            or a loaded ``Robot`` (see ``load_robot``; the last two are not parsed again).
        scene: Obstacles fixed in the world frame.
        disabled_pairs: Link-name pairs never checked (the SRDF's ``disable_collisions``).
        edge_step: Joint-space step (rad or m, Euclidean) of exact edge checks.
    """

    def __init__(
        self,
        robot_source: str | os.PathLike[str],
        scene: PlanningScene | None = None,
        *,
        disabled_pairs: Iterable[tuple[str, str]] = (),
        edge_step: float = 0.01,
    ) -> None:
        from pydrake.common import Parallelism
        from pydrake.planning import RobotDiagramBuilder, SceneGraphCollisionChecker

        from workbench.model import load_robot

        self.scene = scene if scene is not None else PlanningScene()
        builder = RobotDiagramBuilder(time_step=0.0)
        plant = builder.plant()
        #: The robot as workbench.model describes it (links, joints, limits).
        self.robot = load_robot(
            robot_source, plant=plant, builder=builder.builder(), finalize=False
        )
        self.robot_path = Path(self.robot.path)
        self.instance = self.robot.model_instance
        self.root_link = self.robot.root_link
        add_scene_to_plant(plant, self.scene)
        plant.Finalize()
        self.diagram = builder.Build()
        self.plant = self.diagram.plant()
        self.scene_graph = self.diagram.scene_graph()
        drake_log = logging.getLogger("drake")
        level = drake_log.level
        drake_log.setLevel(logging.WARNING)  # not the checker's "Allocating contexts" notice
        try:
            self.checker = SceneGraphCollisionChecker(
                model=self.diagram,
                robot_model_instances=[self.instance],
                edge_step_size=float(edge_step),
                env_collision_padding=0.0,
                self_collision_padding=0.0,
                # One thread: planning is single-threaded and the machine may be shared.
                implicit_context_parallelism=Parallelism(1),
            )
        finally:
            drake_log.setLevel(level)
        self.disabled_pairs: set[frozenset[str]] = set()
        for link1, link2 in disabled_pairs:
            if plant.HasBodyNamed(link1, self.instance) and plant.HasBodyNamed(
                link2, self.instance
            ):
                self.checker.SetCollisionFilteredBetween(
                    plant.GetBodyByName(link1, self.instance),
                    plant.GetBodyByName(link2, self.instance),
                    True,
                )
                self.disabled_pairs.add(frozenset((link1, link2)))
        self._root_context = self.diagram.CreateDefaultContext()

    # --- joints --------------------------------------------------------------------------

    @property
    def num_positions(self) -> int:
        """Length of the full position vector."""
        return self.plant.num_positions()

    def joint_names(self) -> list[str]:
        """Names of the 1-dof joints in full-vector order."""
        names: list[str] = [""] * self.plant.num_positions()
        for index in self.plant.GetJointIndices(self.instance):
            joint = self.plant.get_joint(index)
            if joint.num_positions() == 1:
                names[joint.position_start()] = joint.name()
        return names

    def joint_map(self, names: list[str], base: np.ndarray | None = None) -> JointMap:
        """A :class:`JointMap` for the joints ``names`` (unknown names raise ModelError)."""
        all_names = self.joint_names()
        indices = []
        for name in names:
            if name not in all_names:
                raise ModelError(f"the robot has no movable joint '{name}'", path=self.robot_path)
            indices.append(all_names.index(name))
        if base is None:
            base = self.default_positions()
        return JointMap(list(names), np.array(indices, dtype=int), np.asarray(base, float).copy())

    def position_limits(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper position limits of the full vector (inf when unlimited)."""
        return self.plant.GetPositionLowerLimits(), self.plant.GetPositionUpperLimits()

    def velocity_limits(self) -> np.ndarray:
        """Velocity limits of the full vector (rad/s or m/s; inf when absent)."""
        return self.plant.GetVelocityUpperLimits()

    def default_positions(self) -> np.ndarray:
        """Zeros clipped into the position limits."""
        lower, upper = self.position_limits()
        return np.clip(np.zeros(self.num_positions), lower, upper)

    # --- collision queries ---------------------------------------------------------------

    def is_free(self, q: np.ndarray) -> bool:
        """True when the full configuration ``q`` collides with nothing (filters honoured)."""
        return bool(self.checker.CheckConfigCollisionFree(np.asarray(q, float)))

    def configs_free(self, Q: np.ndarray) -> np.ndarray:
        """Exact check of many full configurations (rows of ``Q``); returns a bool array."""
        result = self.checker.CheckConfigsCollisionFree(
            list(np.asarray(Q, float)), parallelize=False
        )
        return np.asarray(result, dtype=bool)

    def edge_free(self, qa: np.ndarray, qb: np.ndarray) -> bool:
        """Exact check of the straight joint-space segment at the checker's edge step."""
        return bool(
            self.checker.CheckEdgeCollisionFree(np.asarray(qa, float), np.asarray(qb, float))
        )

    def colliding_pairs(self, q: np.ndarray, margin: float = 0.0) -> list[tuple[str, str, float]]:
        """Body pairs closer than ``margin`` at ``q``, deepest first: (robot body, other, distance m).

        Other bodies of the scene are named ``scene::NAME``.
        """
        clearance = self.checker.CalcRobotClearance(np.asarray(q, float), max(margin, 0.0) + 1e-3)
        out: dict[frozenset[int], tuple[str, str, float]] = {}
        distances = clearance.distances()
        for robot_index, other_index, distance in zip(
            clearance.robot_indices(), clearance.other_indices(), distances, strict=True
        ):
            if distance >= margin:
                continue
            key = frozenset((int(robot_index), int(other_index)))
            names = (self._body_label(robot_index), self._body_label(other_index))
            if key not in out or distance < out[key][2]:
                out[key] = (*names, float(distance))
        return sorted(out.values(), key=lambda item: item[2])

    def _body_label(self, body_index) -> str:
        body = self.plant.get_body(body_index)
        if body.index() != self.plant.world_body().index():
            return body.name()
        return "world"

    def describe_collision(self, q: np.ndarray) -> str:
        """``'A' and 'B'`` for the deepest colliding pair at ``q``, with obstacle names."""
        pairs = self.colliding_pairs(q)
        if not pairs:
            return "no bodies"
        a, b, depth = pairs[0]
        if b == "world":
            b = self._obstacle_near(q, a)
        return f"'{a}' and '{b}' (penetration {abs(depth) * 1000:.1f} mm)"

    def _obstacle_near(self, q: np.ndarray, body_name: str) -> str:
        """The scene object the named robot body penetrates (by a point-pair query)."""
        plant_context = self.plant.GetMyMutableContextFromRoot(self._root_context)
        self.plant.SetPositions(plant_context, np.asarray(q, float))
        query = self.plant.get_geometry_query_input_port().Eval(plant_context)
        inspector = query.inspector()
        for pair in query.ComputePointPairPenetration():
            names = [inspector.GetName(pair.id_A), inspector.GetName(pair.id_B)]
            bodies = [
                self.plant.GetBodyFromFrameId(inspector.GetFrameId(gid)).name()
                for gid in (pair.id_A, pair.id_B)
            ]
            if body_name in bodies:
                other = names[1 - bodies.index(body_name)]
                if "scene::" in other:
                    return other.split("scene::", 1)[1]
        return "the world"
