"""What a plugin holds: a handle on its model or on the world (Gazebo's ``physics::Model``/``World``).

Handles look the model up by name on every call, so they stay valid when the
server rebuilds its diagram (a spawn or delete elsewhere). Units: m, rad, s,
N, N m; vectors in the world frame W.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from workbench.errors import SimulationError
from workbench.model.sdf_names import drake_joint, shown_name

if TYPE_CHECKING:
    from workbench.sim.server import SimServer


class ModelHandle:
    """One model of a running simulation."""

    def __init__(self, server: SimServer, name: str, owner: Any = None) -> None:
        self._server = server
        self.name = name
        self._owner = owner

    @property
    def _world(self) -> Any:
        return self._server.world

    @property
    def server(self) -> SimServer:
        """The server the model runs in (sensor plugins read its world)."""
        return self._server

    def _context(self) -> Any:
        return self._world.plant.GetMyMutableContextFromRoot(self._world.context)

    @property
    def joint_names(self) -> list[str]:
        """The model's joints that have positions."""
        from workbench.sim.scene import joint_names

        return joint_names(self._world.plant, self._world.model_instance(self.name))

    @property
    def link_names(self) -> list[str]:
        """The model's links."""
        plant = self._world.plant
        return [
            shown_name(plant.get_body(i).name())
            for i in plant.GetBodyIndices(self._world.model_instance(self.name))
        ]

    def pose(self) -> Any:
        """``X_WM``, the model frame in the world (a RigidTransform)."""
        return self._world.get_model_pose(self.name)

    def linear_velocity(self) -> np.ndarray:
        """Velocity of the model's root link origin in W, m/s."""
        return self._world.get_model_twist(self.name)[0]

    def angular_velocity(self) -> np.ndarray:
        """Angular velocity of the model's root link in W, rad/s."""
        return self._world.get_model_twist(self.name)[1]

    def set_pose(self, X_WM: Any) -> None:
        """Teleport the model (velocities kept)."""
        v, w = self._world.get_model_twist(self.name)
        self._world.set_model_state(self.name, X_WM, v, w)

    def set_linear_velocity(self, v_W: Sequence[float]) -> None:
        """Set the root link's linear velocity now (Gazebo's ``Model::SetLinearVel``)."""
        _, w = self._world.get_model_twist(self.name)
        self._world.set_model_state(self.name, self.pose(), v_W, w)

    def set_angular_velocity(self, w_W: Sequence[float]) -> None:
        """Set the root link's angular velocity now (Gazebo's ``Model::SetAngularVel``)."""
        v, _ = self._world.get_model_twist(self.name)
        self._world.set_model_state(self.name, self.pose(), v, w_W)

    def joint_position(self, joint: str) -> float:
        """A 1-dof joint's position, rad or m."""
        item = self._world.joint(self.name, joint)
        return float(self._world.plant.GetPositions(self._context())[item.position_start()])

    def joint_velocity(self, joint: str) -> float:
        """A 1-dof joint's velocity, rad/s or m/s."""
        item = self._world.joint(self.name, joint)
        return float(self._world.plant.GetVelocities(self._context())[item.velocity_start()])

    def set_joint_position(self, joint: str, position: float) -> None:
        """Move a 1-dof joint to ``position`` now."""
        item = self._world.joint(self.name, joint)
        q = self._world.plant.GetPositions(self._context()).copy()
        q[item.position_start()] = float(position)
        self._world.plant.SetPositions(self._context(), q)

    def set_joint_velocity(self, joint: str, velocity: float) -> None:
        """Set a 1-dof joint's velocity now (Gazebo's ``Joint::SetVelocity``)."""
        item = self._world.joint(self.name, joint)
        v = self._world.plant.GetVelocities(self._context()).copy()
        v[item.velocity_start()] = float(velocity)
        self._world.plant.SetVelocities(self._context(), v)

    def set_joint_effort(self, joint: str, effort: float) -> None:
        """Apply a torque (N m) or force (N) on a 1-dof joint until this plugin's next update."""
        if not np.isfinite(effort):
            raise SimulationError(f"joint '{joint}' of '{self.name}': effort is not finite")
        self._world.joint(self.name, joint)  # checks the name
        self._server.set_plugin_effort(self._owner, (self.name, joint), float(effort))

    def set_joint_efforts(self, efforts: Mapping[str, float]) -> None:
        """Apply ``{joint: effort}`` (N m or N) on 1-dof joints until this plugin's next
        update, all at once (one call per control step instead of one per joint)."""
        checked = {}
        for joint, effort in efforts.items():
            if not np.isfinite(effort):
                raise SimulationError(f"joint '{joint}' of '{self.name}': effort is not finite")
            self._world.joint(self.name, joint)  # checks the name
            checked[(self.name, joint)] = float(effort)
        self._server.set_plugin_efforts(self._owner, checked)

    def set_joint_states(
        self, positions: Mapping[str, float], velocities: Mapping[str, float] | None = None
    ) -> None:
        """Move 1-dof joints to ``positions`` now and give them ``velocities`` (default: kept),
        in one write of the state (Gazebo's ``Joint::SetPosition`` for several joints)."""
        plant = self._world.plant
        context = self._context()
        q = plant.GetPositions(context).copy()
        v = plant.GetVelocities(context).copy()
        for joint, value in positions.items():
            q[self._world.joint(self.name, joint).position_start()] = float(value)
        for joint, value in (velocities or {}).items():
            v[self._world.joint(self.name, joint).velocity_start()] = float(value)
        plant.SetPositions(context, q)
        plant.SetVelocities(context, v)

    def link_twist(self, link: str) -> tuple[np.ndarray, np.ndarray]:
        """``(v_W, w_W)``: velocity of a link's origin and its angular velocity, in W."""
        body = self._world.body(f"{self.name}::{link}")
        V = self._world.plant.EvalBodySpatialVelocityInWorld(self._context(), body)
        return np.array(V.translational()), np.array(V.rotational())

    def apply_wrench(
        self, link: str, force: Sequence[float], torque: Sequence[float] = (0.0, 0.0, 0.0)
    ) -> None:
        """Push a link at its origin with ``force`` and ``torque`` in W until this plugin's next update."""
        self._world.body(f"{self.name}::{link}")  # checks the name
        self._server.set_plugin_wrench(self._owner, f"{self.name}::{link}", force, torque)

    @property
    def sim_time(self) -> float:
        """Simulated time, s."""
        return float(self._world.time)

    @property
    def time_step(self) -> float:
        """The physics step, s."""
        return float(self._world.time_step)

    def has_joint(self, joint: str) -> bool:
        """True when the model has a joint called ``joint``."""
        instance = self._world.model_instance(self.name)
        return drake_joint(self._world.plant, joint, instance) is not None

    def joint_links(self, joint: str) -> tuple[str, str]:
        """``(parent, child)``: the links a joint connects."""
        item = self._world.joint(self.name, joint)
        return shown_name(item.parent_body().name()), shown_name(item.child_body().name())

    def link_pose(self, link: str) -> Any:
        """``X_WL``, a link's frame in the world (a RigidTransform)."""
        body = self._world.body(f"{self.name}::{link}")
        return self._world.plant.EvalBodyPoseInWorld(self._context(), body)

    def joints(self) -> list[tuple[str, str]]:
        """``(name, type)`` of every joint in the model's order (Gazebo's ``Model::GetJoints``);
        types are Drake's: ``revolute``, ``prismatic``, ``weld`` (fixed), ``ball_rpy``, ..."""
        plant = self._world.plant
        return [
            (shown_name(plant.get_joint(i).name()), plant.get_joint(i).type_name())
            for i in plant.GetJointIndices(self._world.model_instance(self.name))
            if plant.get_joint(i).type_name() not in ("quaternion_floating", "rpy_floating")
        ]

    def joint_anchor(self, joint: str) -> np.ndarray:
        """Where a joint is in W, m (Gazebo's ``Joint::Anchor``): its frame on the child link."""
        item = self._world.joint(self.name, joint)
        X_WJ = item.frame_on_child().CalcPoseInWorld(self._context())
        return np.array(X_WJ.translation())

    def link_bounding_box(self, link: str) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)``: the box in W around a link's collision shapes now, m
        (Gazebo's ``Link::BoundingBox``; see :func:`workbench.sim.geometry_bounds.body_bounds`)."""
        from workbench.sim.geometry_bounds import body_bounds

        body = self._world.body(f"{self.name}::{link}")
        return body_bounds(self._world, body)

    def sensors(self) -> list[tuple[str, str]]:
        """``(link, <sensor> XML)`` of the model's sensors, in file order."""
        placed = self._world.models.get(self.name)
        return list(placed.model.sensors) if placed is not None else []

    def add_velocity_motors(self, limits: Mapping[str, float]) -> None:
        """Drive joints with velocity motors ``{joint: effort limit}`` (Gazebo's
        ``Joint::SetParam("fmax")`` with ``"vel"``; see :mod:`workbench.sim.motors`).

        They hold velocity 0 until :meth:`set_motor_velocities`. The world's diagram
        is rebuilt (every model keeps its state).
        """
        self._world.add_velocity_motors(self.name, limits)
        self._server.rebuilt()

    def set_motor_velocities(self, velocities: Mapping[str, float]) -> None:
        """Targets ``{joint: velocity}`` of the motors, rad/s or m/s, until changed."""
        self._world.set_motor_targets(self.name, velocities)

    def motor_efforts(self) -> dict[str, float]:
        """``{joint: effort}`` the motors applied in the last step, N m or N."""
        return self._world.motor_efforts(self.name)

    def set_twist(self, v_W: Sequence[float], w_W: Sequence[float]) -> None:
        """Set the root link's linear and angular velocity now (W, m/s and rad/s)."""
        self._world.set_model_state(self.name, self.pose(), v_W, w_W)


class WorldHandle:
    """The running world, for world plugins."""

    def __init__(self, server: SimServer, owner: Any = None) -> None:
        self._server = server
        self._owner = owner

    @property
    def sim_time(self) -> float:
        """Simulated time, s."""
        return self._server.world.time

    def model_names(self) -> list[str]:
        """Every model in the world."""
        return self._server.world.model_names()

    def model(self, name: str) -> ModelHandle:
        """A handle on model ``name``."""
        self._server.world.model_instance(name)  # checks the name
        return ModelHandle(self._server, name, self._owner)

    @property
    def paused(self) -> bool:
        return self._server.paused
