"""A small Drake simulation: ground, static obstacles, robots and their joint controllers.

Usage::

    world = World(time_step=0.001)
    world.add_robot("robot_arm", X_WB=[0, 0, 0.05])
    world.add_box("table", size=(0.4, 0.6, 0.02), X_WB=[0.3, 0, 0.1])
    world.build()
    world.set_positions("robot_arm", q)
    report = world.track_trajectory("robot_arm", JointTrajectory(names, t, q, qd))

Frames: the world frame W has z up; the ground's top surface is the plane
``z = ground_z``. ``X_WB`` arguments are anything
:func:`workbench.spatial.as_rigid_transform` takes: a pydrake ``RigidTransform``,
an ``[x, y, z]`` translation, a 4x4 matrix, or ``{"xyz": [...], "rpy": [...]}`` (m, rad).

Each fixed-base robot gets a joint-level controller (see
:mod:`workbench.sim.controllers`) acting through the plant's applied
generalized force, clipped to the URDF's effort limits. When a ``bus`` is
given, the World publishes ``/clock`` (rosgraph_msgs/Clock) and
``/joint_states`` (sensor_msgs/JointState, all robots' 1-dof joints) every
``publish_period`` of simulated time while it advances.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.sim.controllers import (
    Command,
    add_controller,
    controller_output,
    make_command_system,
)
from workbench.sim.trajectory import TrackingReport, as_joint_trajectory
from workbench.spatial import (
    Mesh,
    Shape,
    SpatialError,
    as_rigid_transform,
    drake_shape,
    make_shape,
    rigid_transform,
)

GROUND_NAME = "ground"


@dataclass
class _RobotEntry:
    robot: Any
    controller_type: str | None
    gains: dict[str, Any] | None
    command: Any = None
    controller: Any = None
    joint_names: list[str] | None = None


class World:
    """Ground, static obstacles, robots and controllers in one Drake diagram.

    Args:
        time_step: Discrete plant step, s (> 0).
        bus: A ``workbench.bus.Bus`` to publish ``/clock`` and ``/joint_states`` on, or None.
        ground: Add the ground (a 20 m x 20 m slab whose top is ``z = ground_z``).
        ground_z: Height of the ground surface in W, m.
        gravity: Gravity along -z of W, m/s^2.
        publish_period: Simulated time between bus messages, s.
    """

    def __init__(
        self,
        time_step: float = 0.001,
        bus: Any = None,
        *,
        ground: bool = True,
        ground_z: float = 0.0,
        gravity: float = 9.81,
        publish_period: float = 0.01,
    ) -> None:
        from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
        from pydrake.systems.framework import DiagramBuilder

        if not time_step > 0:
            raise SimulationError(f"time_step must be positive, got {time_step}")
        self.time_step = float(time_step)
        self.bus = bus
        self.publish_period = float(publish_period)
        self.builder = DiagramBuilder()
        self.plant, self.scene_graph = AddMultibodyPlantSceneGraph(self.builder, self.time_step)
        self.plant.mutable_gravity_field().set_gravity_vector([0.0, 0.0, -float(gravity)])
        self._robots: dict[str, _RobotEntry] = {}
        self._obstacles: list[str] = []
        self.diagram: Any = None
        self.simulator: Any = None
        self.context: Any = None
        self.visualizer: Any = None
        self._node: Any = None
        self._publishers: dict[str, Any] = {}
        self._next_publish = 0.0
        if ground:
            self._add_ground(ground_z)

    # --- construction ------------------------------------------------------------

    @property
    def robots(self) -> dict[str, Any]:
        """Robots by name."""
        return {name: entry.robot for name, entry in self._robots.items()}

    @property
    def obstacles(self) -> list[str]:
        """Names of the static obstacles (ground excluded)."""
        return list(self._obstacles)

    def add_robot(
        self,
        source: str | os.PathLike[str],
        name: str | None = None,
        X_WB: Any = None,
        floating_base: bool = False,
        *,
        controller: str | None = "inverse_dynamics",
        gains: Mapping[str, Any] | None = None,
    ) -> Any:
        """Add a robot; its root link is welded at ``X_WB`` unless ``floating_base``.

        Args:
            source: A ``urdf/`` name, a description path, a ``RobotDescription`` or a
                loaded ``Robot`` (the last two are not read or parsed again).
            name: Model instance name (default: the description's robot name).
            X_WB: Pose of the root link in the world (default: identity).
            floating_base: Leave the root free (then no controller is attached).
            controller: ``inverse_dynamics``, ``pid`` or None (joints are passive).
            gains: ``{"kp": ..., "ki": ..., "kd": ...}`` scalars or per-joint lists.

        Returns:
            The :class:`workbench.model.Robot`.
        """
        from workbench.model import load_robot

        self._require_open("add_robot")
        robot = load_robot(
            source,
            builder=self.builder,
            plant=self.plant,
            floating_base=True,
            finalize=False,
            model_name=name,
        )
        if robot.name in self._robots:
            raise SimulationError(
                f"a robot named '{robot.name}' is already in the world", hint="pass name=..."
            )
        if not floating_base:
            root = self.plant.GetBodyByName(robot.root_link, robot.model_instance)
            self.plant.WeldFrames(self.plant.world_frame(), root.body_frame(), _transform(X_WB))
        elif X_WB is not None:
            root = self.plant.GetBodyByName(robot.root_link, robot.model_instance)
            self.plant.SetDefaultFreeBodyPose(root, _transform(X_WB))
        robot.floating_base = floating_base
        self._robots[robot.name] = _RobotEntry(
            robot, None if floating_base else controller, dict(gains or {})
        )
        return robot

    def add_box(self, name: str, size: Sequence[float], X_WB: Any = None, rgba=None) -> None:
        """Add a static box with edge lengths ``size`` (x, y, z in m) centred at ``X_WB``."""
        self.add_shape(name, _shape(name, "box", size=size), X_WB, rgba)

    def add_sphere(self, name: str, radius: float, X_WB: Any = None, rgba=None) -> None:
        """Add a static sphere of ``radius`` (m) centred at ``X_WB``."""
        self.add_shape(name, _shape(name, "sphere", radius=radius), X_WB, rgba)

    def add_cylinder(
        self, name: str, radius: float, length: float, X_WB: Any = None, rgba=None
    ) -> None:
        """Add a static cylinder (axis along its z) of ``radius`` and ``length`` (m) at ``X_WB``."""
        self.add_shape(name, _shape(name, "cylinder", radius=radius, length=length), X_WB, rgba)

    def add_mesh(
        self, name: str, path: str | os.PathLike[str], X_WB: Any = None, scale=1.0
    ) -> None:
        """Add a static mesh (OBJ/STL/GLTF; contact uses its convex hull) at ``X_WB``."""
        if not os.path.isfile(path):
            raise SimulationError(f"mesh file for '{name}' not found", path=path)
        self.add_shape(name, _shape(name, "mesh", filename=path, scale=scale), X_WB, None)

    def add_shape(self, name: str, shape: Shape, X_WB: Any = None, rgba=None) -> None:
        """Add a static obstacle of any :mod:`workbench.spatial` shape at ``X_WB``.

        Args:
            name: Unique obstacle name.
            shape: A ``spatial.Box``, ``Cylinder``, ``Sphere`` or ``Mesh`` (sizes in m).
            X_WB: Pose of the shape's frame in the world (see the module docstring).
            rgba: Colour (r, g, b, a) in [0, 1], or None for the default brown.
        """
        if isinstance(shape, Mesh) and not os.path.isfile(shape.filename):
            raise SimulationError(f"mesh file for '{name}' not found", path=shape.filename)
        self._add_obstacle(name, drake_shape(shape), X_WB, rgba)

    def build(self, meshcat: Any = None) -> None:
        """Finalize the plant, wire controllers, create the simulator (idempotent).

        Args:
            meshcat: A pydrake ``Meshcat`` to draw the world in (e.g.
                ``workbench.viz.Viewer.instance().meshcat``), or None.
        """
        if self.diagram is not None:
            return
        from pydrake.systems.analysis import Simulator
        from pydrake.systems.primitives import Adder, MatrixGain, Saturation

        plant = self.plant
        plant.Finalize()
        forces = []
        for entry in self._robots.values():
            robot = entry.robot
            joints = [
                plant.get_joint(i)
                for i in plant.GetJointIndices(robot.model_instance)
                if plant.get_joint(i).num_positions() == 1
            ]
            joints.sort(key=lambda j: j.position_start())
            entry.joint_names = [j.name() for j in joints]
            if entry.controller_type is None or not joints:
                continue
            n = len(joints)
            if plant.num_positions(robot.model_instance) != n:
                raise SimulationError(
                    f"robot '{robot.name}' has joints with more than one position; only 1-dof "
                    "joints can be controlled"
                )
            control_plant = _control_plant(robot)
            controller = add_controller(
                self.builder,
                control_plant,
                entry.controller_type,
                entry.gains,
                f"{robot.name}_controller",
            )
            q0 = plant.GetPositions(plant.CreateDefaultContext(), robot.model_instance)
            command = self.builder.AddSystem(make_command_system(n, q0))
            command.set_name(f"{robot.name}_command")
            self.builder.Connect(
                plant.get_state_output_port(robot.model_instance),
                controller.get_input_port_estimated_state(),
            )
            self.builder.Connect(
                command.GetOutputPort("desired_state"), controller.get_input_port_desired_state()
            )
            if entry.controller_type == "inverse_dynamics":
                self.builder.Connect(
                    command.GetOutputPort("desired_acceleration"),
                    controller.get_input_port_desired_acceleration(),
                )
            effort = np.array([_effort_limit(robot, j.name()) for j in joints])
            # pydrake's stubs give numpy arrays a float64 shape; any float array is right here
            saturation = self.builder.AddSystem(Saturation(-effort, effort))  # type: ignore[arg-type]
            self.builder.Connect(controller_output(controller), saturation.get_input_port(0))
            selector = np.zeros((plant.num_velocities(), n))
            for col, joint in enumerate(joints):
                selector[joint.velocity_start(), col] = 1.0
            gain = self.builder.AddSystem(MatrixGain(selector))
            self.builder.Connect(saturation.get_output_port(0), gain.get_input_port(0))
            forces.append(gain.get_output_port(0))
            entry.command = command
            entry.controller = controller
        if forces:
            adder = self.builder.AddSystem(Adder(len(forces), plant.num_velocities()))
            for i, port in enumerate(forces):
                self.builder.Connect(port, adder.get_input_port(i))
            self.builder.Connect(
                adder.get_output_port(0), plant.get_applied_generalized_force_input_port()
            )
        if meshcat is not None:
            from pydrake.geometry import MeshcatVisualizer

            self.visualizer = MeshcatVisualizer.AddToBuilder(
                self.builder, self.scene_graph, meshcat
            )
        self.diagram = self.builder.Build()
        self.simulator = Simulator(self.diagram)
        self.context = self.simulator.get_mutable_context()
        self.simulator.Initialize()

    # --- state -------------------------------------------------------------------

    @property
    def time(self) -> float:
        """Current simulation time, s."""
        self._require_built("time")
        return float(self.context.get_time())

    def joint_names(self, robot_name: str) -> list[str]:
        """The 1-dof joints of a robot in its q order."""
        self._require_built("joint_names")
        return list(self._entry(robot_name).joint_names or [])

    def get_positions(self, robot_name: str) -> np.ndarray:
        """Positions of a robot's joints (its q vector), rad or m."""
        self._require_built("get_positions")
        entry = self._entry(robot_name)
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        return self.plant.GetPositions(plant_context, entry.robot.model_instance).copy()

    def get_velocities(self, robot_name: str) -> np.ndarray:
        """Velocities of a robot's joints, rad/s or m/s."""
        self._require_built("get_velocities")
        entry = self._entry(robot_name)
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        return self.plant.GetVelocities(plant_context, entry.robot.model_instance).copy()

    def set_positions(self, robot_name: str, q: Sequence[float]) -> None:
        """Teleport a robot to ``q`` at rest and make its controller hold ``q``."""
        self._require_built("set_positions")
        entry = self._entry(robot_name)
        instance = entry.robot.model_instance
        positions = np.asarray(q, dtype=float).reshape(-1)
        expected = self.plant.num_positions(instance)
        if positions.shape != (expected,):
            raise SimulationError(
                f"robot '{robot_name}' takes {expected} positions, got {positions.size}",
                hint="joints: " + ", ".join(entry.joint_names or []),
            )
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        self.plant.SetPositions(plant_context, instance, positions)
        self.plant.SetVelocities(
            plant_context, instance, np.zeros(self.plant.num_velocities(instance))
        )
        if entry.command is not None and len(positions) == len(entry.joint_names or []):
            self._set_command(entry, Command(positions.copy()))
        if entry.controller is not None:
            ctrl_context = entry.controller.GetMyMutableContextFromRoot(self.context)
            if ctrl_context.num_continuous_states():
                ctrl_context.SetContinuousState(np.zeros(ctrl_context.num_continuous_states()))

    def advance_to(self, t: float) -> None:
        """Simulate until time ``t`` (s), publishing on the bus if one was given."""
        self._require_built("advance_to")
        if t < self.time:
            raise SimulationError(f"cannot advance to {t:g} s: the world is at {self.time:g} s")
        try:
            if self.bus is None:
                self.simulator.AdvanceTo(t)
                return
            while self.time < t - 1e-12:
                step_end = min(t, max(self._next_publish, self.time))
                if step_end > self.time:
                    self.simulator.AdvanceTo(step_end)
                if self.time >= self._next_publish - 1e-12:
                    self.publish()
                    self._next_publish = self.time + self.publish_period
        except RuntimeError as exc:
            raise SimulationError(f"the simulation failed at t={self.time:.4f} s: {exc}") from None

    def track_trajectory(
        self,
        robot_name: str,
        trajectory: Any,
        *,
        joint_names: list[str] | None = None,
        settle_time: float = 0.5,
        sample_period: float = 0.01,
        tolerance: float = 0.01,
    ) -> TrackingReport:
        """Execute a joint trajectory with the robot's controller and measure the tracking error.

        The trajectory starts at the current simulation time; joints it does not
        name are held where they are. After its end the controller holds the last
        point for ``settle_time`` seconds.

        Args:
            robot_name: The robot to move.
            trajectory: :class:`JointTrajectory`, or a mapping/object with
                ``joint_names``, ``t`` (N,), ``q`` (N, n), ``qd`` (N, n).
            joint_names: Column names when ``trajectory`` has none.
            settle_time: Simulated time after the end, s.
            sample_period: Period of the error samples in the report, s.
            tolerance: Final error (rad or m) under which the run succeeded.

        Returns:
            The :class:`TrackingReport`.

        Raises:
            SimulationError: Unknown robot or joint, a robot without controller,
                a malformed trajectory, or a failing simulation.
        """
        self.build()
        entry = self._entry(robot_name)
        traj = as_joint_trajectory(trajectory, joint_names)
        if entry.command is None:
            raise SimulationError(
                f"robot '{robot_name}' has no controller",
                hint="add it with floating_base=False and a controller type",
            )
        names = entry.joint_names or []
        missing = [n for n in traj.joint_names if n not in names]
        if missing:
            raise SimulationError(
                f"robot '{robot_name}' has no joint '{missing[0]}'",
                hint="joints: " + ", ".join(names),
            )
        columns = np.array([names.index(n) for n in traj.joint_names], dtype=int)
        start = self.time
        q_now = self.get_positions(robot_name)
        command = Command.follow(self._command_of(entry).q_hold, start, columns, traj)
        command.q_hold[np.setdiff1d(np.arange(len(names)), columns)] = q_now[
            np.setdiff1d(np.arange(len(names)), columns)
        ]
        self._set_command(entry, command)
        end = traj.duration + max(settle_time, 0.0)
        steps = max(int(np.ceil(end / sample_period)), 1)
        times = np.minimum(np.arange(steps + 1) * sample_period, end)
        desired = np.empty((len(times), len(columns)))
        actual = np.empty_like(desired)
        contacts: set[tuple[str, str]] = set()
        for k, s in enumerate(times):
            if s > 0:
                self.advance_to(start + s)
            desired[k] = command.evaluate(start + s)[0][columns]
            actual[k] = self.get_positions(robot_name)[columns]
            contacts |= self.contact_pairs()
        error = np.abs(actual - desired)
        moving = times <= traj.duration + 1e-12
        return TrackingReport(
            robot=robot_name,
            joint_names=list(traj.joint_names),
            t=times,
            q_desired=desired,
            q_actual=actual,
            duration=traj.duration,
            settle_time=float(max(settle_time, 0.0)),
            max_error=error[moving].max(axis=0),
            rms_error=np.sqrt(np.mean(error[moving] ** 2, axis=0)),
            final_error=error[-1],
            tolerance=tolerance,
            contacts=sorted(contacts),
        )

    def contact_pairs(self) -> set[tuple[str, str]]:
        """Body (or obstacle) name pairs in contact now, each pair sorted."""
        self._require_built("contact_pairs")
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        results = self.plant.get_contact_results_output_port().Eval(plant_context)
        inspector = self.scene_graph.model_inspector()
        pairs = set()
        for i in range(results.num_point_pair_contacts()):
            info = results.point_pair_contact_info(i).point_pair()
            pairs.add(
                _pair(
                    self._geometry_label(inspector, info.id_A),
                    self._geometry_label(inspector, info.id_B),
                )
            )
        for i in range(results.num_hydroelastic_contacts()):
            surface = results.hydroelastic_contact_info(i).contact_surface()
            pairs.add(
                _pair(
                    self._geometry_label(inspector, surface.id_M()),
                    self._geometry_label(inspector, surface.id_N()),
                )
            )
        return pairs

    def publish(self) -> None:
        """Publish ``/clock`` and ``/joint_states`` now (no-op without a bus)."""
        if self.bus is None:
            return
        self._require_built("publish")
        from workbench.msgs import Time
        from workbench.msgs.rosgraph_msgs import Clock
        from workbench.msgs.sensor_msgs import JointState

        if self._node is None:
            from workbench.bus import Node

            self._node = Node("workbench_sim", bus=self.bus)
            self._publishers["clock"] = self._node.create_publisher("/clock", Clock, queue_size=10)
            self._publishers["joint_states"] = self._node.create_publisher(
                "/joint_states", JointState, queue_size=10
            )
        nanos = int(round(self.time * 1e9))
        stamp = Time(nanos // 1_000_000_000, nanos % 1_000_000_000)
        self._publishers["clock"].publish(Clock(clock=stamp))
        msg = JointState()
        msg.header.stamp = stamp
        names, positions, velocities = [], [], []
        for robot_name, entry in self._robots.items():
            if not entry.joint_names:
                continue
            names += entry.joint_names
            positions += self.get_positions(robot_name).tolist()
            velocities += self.get_velocities(robot_name).tolist()
        msg.name = names
        msg.position = positions
        msg.velocity = velocities
        self._publishers["joint_states"].publish(msg)

    # --- helpers -------------------------------------------------------------------

    def _add_ground(self, z: float) -> None:
        # A thick box rather than a HalfSpace: same contact, and Drake's
        # deformable-contact warning about half spaces stays quiet.
        from pydrake.geometry import Box
        from pydrake.multibody.plant import CoulombFriction

        world = self.plant.world_body()
        X_WG = rigid_transform([0.0, 0.0, z - 0.5])
        self.plant.RegisterCollisionGeometry(
            world, X_WG, Box(20.0, 20.0, 1.0), GROUND_NAME, CoulombFriction(0.8, 0.6)
        )
        self.plant.RegisterVisualGeometry(
            world,
            rigid_transform([0.0, 0.0, z - 0.005]),
            Box(4.0, 4.0, 0.01),
            GROUND_NAME,
            np.array([0.85, 0.85, 0.85, 1.0]),
        )

    def _add_obstacle(self, name: str, shape: Any, X_WB: Any, rgba: Any) -> None:
        from pydrake.multibody.plant import CoulombFriction

        self._require_open(f"add '{name}'")
        if not name or name in self._obstacles or name == GROUND_NAME:
            raise SimulationError(f"obstacle name '{name}' is empty or already used")
        X = _transform(X_WB)
        world = self.plant.world_body()
        self.plant.RegisterCollisionGeometry(world, X, shape, name, CoulombFriction(0.8, 0.6))
        color = np.array(rgba if rgba is not None else [0.55, 0.45, 0.35, 1.0], dtype=float)
        self.plant.RegisterVisualGeometry(world, X, shape, name, color)
        self._obstacles.append(name)

    def _geometry_label(self, inspector: Any, geometry_id: Any) -> str:
        body = self.plant.GetBodyFromFrameId(inspector.GetFrameId(geometry_id))
        if body is None or body.index() == self.plant.world_body().index():
            return inspector.GetName(geometry_id)
        return body.name()

    def _entry(self, robot_name: str) -> _RobotEntry:
        if robot_name not in self._robots:
            known = ", ".join(self._robots) or "none"
            raise SimulationError(f"no robot named '{robot_name}' in the world (robots: {known})")
        return self._robots[robot_name]

    def _command_of(self, entry: _RobotEntry) -> Command:
        ctx = entry.command.GetMyContextFromRoot(self.context)
        return ctx.get_abstract_parameter(0).get_value()

    def _set_command(self, entry: _RobotEntry, command: Command) -> None:
        ctx = entry.command.GetMyMutableContextFromRoot(self.context)
        ctx.get_mutable_abstract_parameter(0).set_value(command)

    def _require_open(self, what: str) -> None:
        if self.diagram is not None:
            raise SimulationError(f"cannot {what}: the world is already built")

    def _require_built(self, what: str) -> None:
        if self.diagram is None:
            raise SimulationError(f"call build() before {what}")


def _control_plant(robot: Any) -> Any:
    """The robot alone, welded, in a continuous plant with one actuator per 1-dof joint.

    Drake's InverseDynamicsController needs a fully actuated model; URDFs without
    ``<transmission>`` have no actuators, so they are added here (the simulated
    plant takes the controller's output as applied generalized force instead).
    """
    from workbench.model import load_robot

    copy = load_robot(robot, time_step=0.0, finalize=False)
    plant = copy.plant
    actuated = {
        plant.get_joint_actuator(i).joint().index() for i in plant.GetJointActuatorIndices()
    }
    for index in plant.GetJointIndices(copy.model_instance):
        joint = plant.get_joint(index)
        if joint.num_velocities() == 1 and joint.index() not in actuated:
            plant.AddJointActuator(f"{joint.name()}_actuator", joint)
    copy.finalize()
    return plant


def _effort_limit(robot: Any, joint_name: str) -> float:
    for j in robot.joints:
        if j.name == joint_name and j.effort is not None and j.effort > 0:
            return float(j.effort)
    return float("inf")


def _pair(a: str, b: str) -> tuple[str, str]:
    return (a, b) if a <= b else (b, a)


def _shape(name: str, kind: str, **fields: Any) -> Shape:
    try:
        return make_shape(kind, **fields)
    except SpatialError as error:
        raise SimulationError(f"{kind} '{name}': {error.message}", hint=error.hint) from None


def _transform(X: Any) -> Any:
    """A RigidTransform from None, a RigidTransform, [x, y, z], a 4x4 matrix or {"xyz", "rpy"}."""
    try:
        return as_rigid_transform(X)
    except SpatialError as error:
        raise SimulationError(error.message, hint=error.hint) from None
