"""A robot loaded into a Drake MultibodyPlant, with its description alongside."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from workbench import spatial
from workbench.errors import ModelError
from workbench.model.info import JointInfo, LinkInfo

if TYPE_CHECKING:
    from pydrake.math import RigidTransform

    from workbench.model.description import RobotDescription
    from workbench.model.urdf_xml import UrdfDocument


class UnknownJointError(ModelError):
    """A joint name that the robot does not have."""


class Robot:
    """One robot model in a Drake plant.

    Built by :func:`workbench.model.load_robot`; not constructed directly.

    Attributes:
        name: The robot (model instance) name.
        path: The description file.
        builder: The ``DiagramBuilder`` holding the plant and scene graph.
        plant: The ``MultibodyPlant`` (continuous when time_step is 0).
        scene_graph: The ``SceneGraph`` the plant registers geometry with.
        model_instance: The ``ModelInstanceIndex`` of this robot in the plant.
        links: Every link, in file order.
        joints: Every joint, in file order.
        root_link: The link at the root of the tree (welded to the world unless floating).
        floating_base: Whether the root is free to move in the world.
        materials: Named colours from the description, ``name -> (r, g, b, a)``.
        document: The parsed URDF (None for SDF).
        description: The :class:`~workbench.model.RobotDescription` it was loaded from;
            pass it (or this robot) to ``load_robot`` to load the same robot into another
            plant without reading the file again.
        load_warnings: Drake's warnings while parsing, one line each.
    """

    def __init__(
        self,
        *,
        name: str,
        path: Path,
        builder: Any,
        plant: Any,
        scene_graph: Any,
        model_instance: Any,
        links: list[LinkInfo],
        joints: list[JointInfo],
        root_link: str,
        floating_base: bool,
        materials: dict[str, tuple[float, float, float, float]],
        document: UrdfDocument | None = None,
        description: RobotDescription | None = None,
    ) -> None:
        self.name = name
        self.path = path
        self.builder = builder
        self.plant = plant
        self.scene_graph = scene_graph
        self.model_instance = model_instance
        self.links = links
        self.joints = joints
        self.root_link = root_link
        self.floating_base = floating_base
        self.materials = materials
        self.document = document
        self.description = description
        self.load_warnings: list[str] = []
        self._context = None
        self._movable: list[JointInfo] | None = None
        self._plant_joint_cache: list[Any] | None = None

    def __repr__(self) -> str:
        return (
            f"Robot(name={self.name!r}, path='{self.path}', links={len(self.links)}, "
            f"joints={len(self.joints)}, dofs={len(self.joints_movable_in_file())})"
        )

    # --- plant life cycle ----------------------------------------------------

    def finalize(self) -> None:
        """Finalize the plant (idempotent). Needed before positions and kinematics."""
        if not self.plant.is_finalized():
            self.plant.Finalize()

    def _require_finalized(self) -> None:
        if not self.plant.is_finalized():
            raise ModelError(
                f"robot '{self.name}': the plant is not finalized yet",
                hint="call robot.finalize() after adding other models",
            )

    def create_context(self):
        """A fresh default context of the plant (all positions at their defaults)."""
        self._require_finalized()
        return self.plant.CreateDefaultContext()

    # --- joints --------------------------------------------------------------

    def joints_movable_in_file(self) -> list[JointInfo]:
        return [joint for joint in self.joints if joint.is_movable]

    def joint(self, name: str) -> JointInfo:
        """The joint called ``name``; raises :class:`UnknownJointError` otherwise."""
        for joint in self.joints:
            if joint.name == name:
                return joint
        raise self._unknown_joint(name, [joint.name for joint in self.joints])

    def _unknown_joint(self, name: str, names: Sequence[str]) -> UnknownJointError:
        import difflib

        close = difflib.get_close_matches(name, names, n=3)
        hint = f"did you mean {', '.join(close)}?" if close else "joints: " + ", ".join(names)
        return UnknownJointError(
            f"robot '{self.name}' has no movable joint '{name}'", path=self.path, hint=hint
        )

    def _plant_joints(self) -> list[Any]:
        self._require_finalized()
        if self._plant_joint_cache is None:
            plant = self.plant
            joints = [plant.get_joint(i) for i in plant.GetJointIndices(self.model_instance)]
            movable = [joint for joint in joints if joint.num_positions() == 1]
            self._plant_joint_cache = sorted(movable, key=lambda joint: joint.position_start())
        return self._plant_joint_cache

    @property
    def movable_joints(self) -> list[JointInfo]:
        """One-dof joints in plant position (q index) order."""
        if self._movable is None:
            by_name = {joint.name: joint for joint in self.joints}
            result = []
            for plant_joint in self._plant_joints():
                info = by_name.get(plant_joint.name())
                if info is None:
                    info = joint_info_from_plant(plant_joint)
                result.append(info)
            self._movable = result
        return self._movable

    @property
    def joint_names(self) -> list[str]:
        """Names of :attr:`movable_joints`, in q order."""
        return [joint.name for joint in self.movable_joints]

    @property
    def num_positions(self) -> int:
        return len(self.movable_joints)

    @property
    def lower_limits(self) -> np.ndarray:
        """Lower position limits over the movable joints (rad or m; -inf when unlimited)."""
        return np.array([joint.position_lower_limits()[0] for joint in self._plant_joints()])

    @property
    def upper_limits(self) -> np.ndarray:
        """Upper position limits over the movable joints (rad or m; inf when unlimited)."""
        return np.array([joint.position_upper_limits()[0] for joint in self._plant_joints()])

    @property
    def velocity_limits(self) -> np.ndarray:
        """Velocity limits over the movable joints (rad/s or m/s; inf when not given)."""
        values = []
        for joint in self._plant_joints():
            limit = float(joint.velocity_upper_limits()[0])
            info = next((j for j in self.joints if j.name == joint.name()), None)
            if info is not None and info.velocity is not None and info.velocity > 0:
                limit = info.velocity
            values.append(limit)
        return np.array(values)

    def default_positions(self) -> np.ndarray:
        """Zeros clipped into the joint limits, over the movable joints."""
        return np.clip(np.zeros(self.num_positions), self.lower_limits, self.upper_limits)

    def positions_from(
        self, mapping: Mapping[str, float], base: Sequence[float] | None = None
    ) -> np.ndarray:
        """A q vector with the named joints set.

        Args:
            mapping: Joint name -> position (rad or m).
            base: Values for the joints not named (default: :meth:`default_positions`).

        Raises:
            UnknownJointError: A name is not a movable joint of this robot.
        """
        names = self.joint_names
        q = self.default_positions() if base is None else np.array(base, dtype=float)
        if q.shape != (len(names),):
            raise ModelError(
                f"robot '{self.name}': base has {q.size} values, expected {len(names)}",
                hint="one value per movable joint, in robot.joint_names order",
            )
        for name, value in mapping.items():
            if name not in names:
                raise self._unknown_joint(name, names)
            q[names.index(name)] = float(value)
        self._check_finite(q)
        return q

    def _check_finite(self, q: np.ndarray) -> None:
        """Drake aborts the process on a NaN or infinite position: refuse it here."""
        bad = np.flatnonzero(~np.isfinite(q))
        if bad.size:
            names = self.joint_names
            name = names[bad[0]] if q.size == len(names) else f"#{bad[0]}"
            raise ModelError(
                f"robot '{self.name}': joint '{name}' would be set to {q[bad[0]]}, "
                "which is not a finite number",
                hint="give every joint position as a finite number (rad or m)",
            )

    def set_positions(self, context, q: Sequence[float] | np.ndarray) -> None:
        """Write the movable-joint positions ``q`` into a plant context."""
        values = np.asarray(q, dtype=float).ravel()
        self._check_finite(values)
        plant_joints = self._plant_joints()
        plant = self.plant
        if values.size == plant.num_positions() and values.size != len(plant_joints):
            plant.SetPositions(context, values)
            return
        if values.size != len(plant_joints):
            raise ModelError(
                f"robot '{self.name}': q has {values.size} values, expected {len(plant_joints)}",
                hint="one value per movable joint, in robot.joint_names order",
            )
        full = plant.GetPositions(context).copy()
        for joint, value in zip(plant_joints, values, strict=True):
            full[joint.position_start()] = value
        plant.SetPositions(context, full)

    # --- kinematics ----------------------------------------------------------

    def link_bodies(self) -> list[Any]:
        """The plant bodies of this robot, in plant order."""
        plant = self.plant
        return [plant.get_body(index) for index in plant.GetBodyIndices(self.model_instance)]

    @property
    def frame_names(self) -> list[str]:
        """Every frame of this robot in the plant: link frames and joint frames."""
        plant = self.plant
        return [
            plant.get_frame(index).name() for index in plant.GetFrameIndices(self.model_instance)
        ]

    def forward_kinematics(self, q: Sequence[float] | None = None) -> dict[str, RigidTransform]:
        """Pose of every link in the world, ``X_WL``, at positions ``q``.

        Args:
            q: Movable-joint positions (rad or m), default :meth:`default_positions`.

        Returns:
            Link name -> ``RigidTransform`` of the link frame in the world frame (metres).
        """
        self._require_finalized()
        if self._context is None:
            self._context = self.plant.CreateDefaultContext()
        context = self._context
        self.set_positions(context, self.default_positions() if q is None else q)
        poses = {
            body.name(): self.plant.EvalBodyPoseInWorld(context, body)
            for body in self.link_bodies()
        }
        if self.root_link == "world":  # the URDF's world link is Drake's world body
            from pydrake.math import RigidTransform

            poses["world"] = RigidTransform()
        return poses


_DRAKE_TYPES = {
    "revolute": "revolute",
    "prismatic": "prismatic",
    "weld": "fixed",
    "quaternion_floating": "floating",
    "rpy_floating": "floating",
    "planar": "planar",
}


def joint_info_from_plant(joint) -> JointInfo:
    """Describe a Drake joint as a :class:`JointInfo` (used for SDF models)."""
    kind = _DRAKE_TYPES.get(joint.type_name(), joint.type_name())
    axis = np.array([1.0, 0.0, 0.0])
    lower = upper = velocity = effort = None
    if joint.num_positions() == 1:
        if kind == "revolute":
            axis = np.array(joint.revolute_axis())
        elif hasattr(joint, "translation_axis"):
            axis = np.array(joint.translation_axis())
        elif hasattr(joint, "screw_axis"):  # a screw joint turns and slides along one axis
            axis = np.array(joint.screw_axis())
        lower = float(joint.position_lower_limits()[0])
        upper = float(joint.position_upper_limits()[0])
        velocity = float(joint.velocity_upper_limits()[0])
        if kind == "revolute" and np.isinf(lower) and np.isinf(upper):
            kind, lower, upper = "continuous", None, None
    xyz, rpy = spatial.xyz_rpy_from_rigid_transform(
        joint.frame_on_parent().GetFixedPoseInBodyFrame()
    )
    return JointInfo(
        joint.name(),
        kind,
        joint.parent_body().name(),
        joint.child_body().name(),
        axis,
        xyz,
        rpy,
        lower,
        upper,
        velocity,
        effort,
    )
