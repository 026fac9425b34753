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
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.model.sdf_names import drake_body, drake_joint, scoped, shown_name
from workbench.sim.controllers import (
    Command,
    add_controller,
    controller_output,
    make_command_system,
)
from workbench.sim.model_spec import SimModel
from workbench.sim.scene import (
    GROUND_NAME,
    PlacedModel,
    add_ground,
    add_obstacle,
    add_placed_model,
    filter_self_collisions,
)
from workbench.sim.trajectory import TrackingReport, as_joint_trajectory
from workbench.spatial import (
    Mesh,
    Shape,
    SpatialError,
    as_rigid_transform,
    drake_shape,
    make_shape,
)


@dataclass
class _RobotEntry:
    robot: Any
    controller_type: str | None
    gains: dict[str, Any] | None
    X_WB: Any = None
    command: Any = None
    controller: Any = None
    joint_names: list[str] | None = None


@dataclass
class _Obstacle:
    name: str
    shape: Any
    X_WB: Any
    rgba: Any


class World:
    """Ground, static obstacles, robots and controllers in one Drake diagram.

    Args:
        time_step: Discrete plant step, s (> 0).
        bus: A ``workbench.bus.Bus`` to publish ``/clock`` and ``/joint_states`` on, or None.
        ground: Add the ground (a 20 m x 20 m slab whose top is ``z = ground_z``).
        ground_z: Height of the ground surface in W, m.
        gravity: Gravity along -z of W, m/s^2.
        publish_period: Simulated time between bus messages, s.
        clock: Publish ``/clock`` and stamp with simulated time (Gazebo's way). False:
            no ``/clock``, messages stamped with wall time (MoveIt's fake execution,
            for tools on wall time); pair it with ``realtime_rate=1``.
        realtime_rate: Pace the simulation at this multiple of wall time (0: as fast
            as it computes).
    """

    def __init__(
        self,
        time_step: float = 0.001,
        bus: Any = None,
        *,
        ground: bool = True,
        ground_z: float = 0.0,
        gravity: float | Sequence[float] = 9.81,
        publish_period: float = 0.01,
        physics: Mapping[str, Any] | None = None,
        clock: bool = True,
        realtime_rate: float = 0.0,
    ) -> None:
        if not time_step > 0:
            raise SimulationError(f"time_step must be positive, got {time_step}")
        if not realtime_rate >= 0:
            raise SimulationError(f"realtime_rate must be 0 or positive, got {realtime_rate}")
        self.time_step = float(time_step)
        self.bus = bus
        self.publish_period = float(publish_period)
        self.publish_clock = bool(clock)
        self.realtime_rate = float(realtime_rate)
        self.gravity_vector = _gravity_vector(gravity)
        self.physics = dict(physics or {})
        self._ground_z = float(ground_z) if ground else None
        self._renderers: list[str] = []
        self._robots: dict[str, _RobotEntry] = {}
        self._obstacles: list[_Obstacle] = []
        self._models: dict[str, PlacedModel] = {}
        self.diagram: Any = None
        self.simulator: Any = None
        self.context: Any = None
        self.visualizer: Any = None
        self.meshcat: Any = None
        self.contact_visualizer: Any = None
        self.show_contacts = False
        self.visual_period = 1.0 / 32.0
        self.efforts_source: Any = None
        self.rebuilds = 0
        self._node: Any = None
        self._publishers: dict[str, Any] = {}
        self._next_publish = 0.0
        self._new_plant()
        if self._ground_z is not None:
            add_ground(self.plant, self._ground_z)

    def _new_plant(self) -> None:
        from pydrake.multibody.plant import AddMultibodyPlant, MultibodyPlantConfig
        from pydrake.systems.framework import DiagramBuilder

        self.builder = DiagramBuilder()
        config = MultibodyPlantConfig(time_step=self.time_step)
        for key, value in self.physics.items():
            if key in ("static_friction", "dynamic_friction", "point_stiffness"):
                continue
            setattr(config, key, value)
        self.plant, self.scene_graph = AddMultibodyPlant(config, self.builder)
        if "dynamic_friction" in self.physics or "point_stiffness" in self.physics:
            from pydrake.geometry import DefaultProximityProperties, SceneGraphConfig

            defaults = DefaultProximityProperties()
            defaults.static_friction = self.physics.get(
                "static_friction", self.physics.get("dynamic_friction", 1.0)
            )
            defaults.dynamic_friction = self.physics.get("dynamic_friction", 1.0)
            if "point_stiffness" in self.physics:
                defaults.point_stiffness = self.physics["point_stiffness"]
            self.scene_graph.set_config(SceneGraphConfig(default_proximity_properties=defaults))
        self.plant.mutable_gravity_field().set_gravity_vector(self.gravity_vector)
        for name in self._renderers:
            self.scene_graph.AddRenderer(name, _render_engine())

    # --- construction ------------------------------------------------------------

    @property
    def robots(self) -> dict[str, Any]:
        """Robots by name."""
        return {name: entry.robot for name, entry in self._robots.items()}

    @property
    def obstacles(self) -> list[str]:
        """Names of the static obstacles (ground excluded)."""
        return [obstacle.name for obstacle in self._obstacles]

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
        self._require_open("add_robot")
        robot = self._load_robot(source, name, X_WB, floating_base)
        if robot.name in self._robots or robot.name in self._models:
            raise SimulationError(
                f"a model named '{robot.name}' is already in the world", hint="pass name=..."
            )
        self._robots[robot.name] = _RobotEntry(
            robot, None if floating_base else controller, dict(gains or {}), X_WB
        )
        return robot

    def _load_robot(self, source: Any, name: str | None, X_WB: Any, floating_base: bool) -> Any:
        from workbench.model import load_robot

        robot = load_robot(
            source,
            builder=self.builder,
            plant=self.plant,
            floating_base=True,
            finalize=False,
            model_name=name,
        )
        root = self.plant.GetBodyByName(robot.root_link, robot.model_instance)
        if not floating_base:
            self.plant.WeldFrames(self.plant.world_frame(), root.body_frame(), _transform(X_WB))
        elif X_WB is not None:
            self.plant.SetDefaultFloatingBaseBodyPose(root, _transform(X_WB))
        robot.floating_base = floating_base
        return robot

    def add_model(
        self,
        model: SimModel,
        X_WM: Any = None,
        *,
        joint_positions: Mapping[str, float] | None = None,
    ) -> None:
        """Put a Gazebo-style model into the world, also while it runs.

        The model is free (it falls, collides and can be pushed) unless it is
        static; it has no controller. Once the world is built, adding a model
        rebuilds the diagram and every other model keeps its state.

        Args:
            model: The model (see :mod:`workbench.sim.model_spec`).
            X_WM: Where its model frame goes (see the module docstring).
            joint_positions: Initial positions of 1-dof joints by name, rad or m.

        Raises:
            SimulationError: The name is in use or not a name Drake can take, the world
                would hold more models or links than :mod:`workbench.sim.bounds` allows (the
                world is unchanged), the pose is not finite, or Drake cannot load the model.
        """
        from workbench.sim.bounds import check_model_name, check_room, model_links, world_load

        check_model_name(model.name, "model name")
        if model.name in self._models or model.name in self._robots or model.name == GROUND_NAME:
            raise SimulationError(f"model name '{model.name}' is already in use")
        check_room(world_load(self), model_links(model.text), model.static, model.name)
        X = _model_transform(model.name, X_WM)
        placed = PlacedModel(model, X, dict(joint_positions or {}), initial_X_WM=X)
        if self.diagram is None:
            self._models[model.name] = placed
            try:
                add_placed_model(self.plant, placed, self.scene_graph)
            except (SimulationError, RuntimeError) as error:
                del self._models[model.name]
                self._replay()
                raise _as_simulation_error(error, model) from None
            return
        self._models[model.name] = placed
        try:
            self.rebuild()
        except (SimulationError, RuntimeError) as error:
            del self._models[model.name]  # the rebuild left the world as it was
            raise _as_simulation_error(error, model) from None

    def remove_model(self, name: str) -> None:
        """Delete a model (or robot) from the world; the others keep their state."""
        if name in self._robots:
            del self._robots[name]
        elif name in self._models:
            del self._models[name]
        else:
            raise SimulationError(f"no model named '{name}' in the world")
        if self.diagram is not None:
            self.rebuild()
        else:
            self._replay()

    @property
    def models(self) -> dict[str, PlacedModel]:
        """The Gazebo-style models by name (robots added with add_robot are in ``robots``)."""
        return dict(self._models)

    def model_names(self) -> list[str]:
        """Every model in the world, in Gazebo's sense: ground, robots and models."""
        names = [GROUND_NAME] if self._ground_z is not None else []
        return names + list(self._robots) + list(self._models)

    def model_instance(self, name: str) -> Any:
        """The Drake model instance of a model or robot."""
        if name in self._models:
            return self._models[name].instance
        if name in self._robots:
            return self._robots[name].robot.model_instance
        raise SimulationError(
            f"no model named '{name}' in the world",
            hint="models: " + (", ".join(self.model_names()) or "none"),
        )

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

    @property
    def renderers(self) -> list[str]:
        """Names of the render engines the SceneGraph has (see :meth:`add_renderer`)."""
        return list(self._renderers)

    def add_renderer(self, name: str) -> None:
        """Give the SceneGraph a Drake ``RenderEngineVtk`` called ``name``, for cameras.

        It renders every visual geometry (Drake gives visuals the perception role)
        and is added again whenever the diagram is rebuilt. A world without cameras
        has none, so its physics step does not update a renderer. Adding a name
        twice does nothing; a built world gets it at once (no rebuild).
        """
        if name in self._renderers:
            return
        self._renderers.append(name)
        self.scene_graph.AddRenderer(name, _render_engine())
        if self.context is not None:
            scene_graph_context = self.scene_graph.GetMyMutableContextFromRoot(self.context)
            self.scene_graph.AddRenderer(scene_graph_context, name, _render_engine())

    def build(self, meshcat: Any = None) -> None:
        """Finalize the plant, wire controllers, create the simulator (idempotent).

        Args:
            meshcat: A pydrake ``Meshcat`` to draw the world in (e.g.
                ``workbench.viz.Viewer.instance().meshcat``), or None.
        """
        if self.diagram is not None:
            return
        if meshcat is not None:
            self.meshcat = meshcat
        try:
            self._assemble()
        except RuntimeError as error:  # Drake's refusal at Finalize, as one line
            first = next((line for line in str(error).splitlines() if line.strip()), "")
            raise SimulationError(f"Drake cannot build the world: {shown_name(first)}") from None
        self.simulator.Initialize()

    def _assemble(self) -> None:
        from pydrake.systems.analysis import Simulator
        from pydrake.systems.primitives import Adder, ConstantVectorSource, MatrixGain, Saturation

        plant = self.plant
        plant.Finalize()
        for placed in self._models.values():
            if not placed.model.self_collide:
                filter_self_collisions(plant, self.scene_graph, placed.instance)
        self.efforts_source = self.builder.AddSystem(
            ConstantVectorSource(np.zeros(plant.num_velocities()))
        )
        self.efforts_source.set_name("joint_efforts")
        forces = [self.efforts_source.get_output_port(0)]
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
        adder = self.builder.AddSystem(Adder(len(forces), plant.num_velocities()))
        for i, port in enumerate(forces):
            self.builder.Connect(port, adder.get_input_port(i))
        self.builder.Connect(
            adder.get_output_port(0), plant.get_applied_generalized_force_input_port()
        )
        if self.meshcat is not None:
            self._add_visualizers()
        self.diagram = self.builder.Build()
        self.simulator = Simulator(self.diagram)
        if self.realtime_rate > 0:
            self.simulator.set_target_realtime_rate(self.realtime_rate)
        self.context = self.simulator.get_mutable_context()
        self.set_body_wrenches([])
        for name, placed in self._models.items():
            if placed.motors:
                self.set_motor_targets(name, placed.motor_targets)

    def _add_visualizers(self) -> None:
        from pydrake.geometry import MeshcatVisualizer, MeshcatVisualizerParams, Role

        params = MeshcatVisualizerParams()
        params.role = Role.kIllustration
        params.publish_period = self.visual_period
        self.visualizer = MeshcatVisualizer.AddToBuilder(
            self.builder, self.scene_graph, self.meshcat, params
        )
        if self.show_contacts:
            from pydrake.multibody.meshcat import ContactVisualizer, ContactVisualizerParams

            contact_params = ContactVisualizerParams()
            contact_params.publish_period = self.visual_period
            self.contact_visualizer = ContactVisualizer.AddToBuilder(
                self.builder, self.plant, self.meshcat, contact_params
            )

    def _replay(self) -> None:
        """A fresh (unfinalized) plant with the ground, obstacles, robots and models re-added."""
        self._new_plant()
        if self._ground_z is not None:
            add_ground(self.plant, self._ground_z)
        for obstacle in self._obstacles:
            add_obstacle(self.plant, obstacle.name, obstacle.shape, obstacle.X_WB, obstacle.rgba)
        for name, entry in self._robots.items():
            floating = bool(entry.robot.floating_base)
            entry.robot = self._load_robot(entry.robot, name, entry.X_WB, floating)
            entry.command = entry.controller = None
        for placed in self._models.values():
            add_placed_model(self.plant, placed, self.scene_graph)

    def rebuild(self) -> None:
        """Build the diagram again from what the world holds, keeping time and every model's state.

        Called by :meth:`add_model` and :meth:`remove_model` on a built world.
        Positions and velocities are carried over by model name; joint
        commands of controlled robots too; applied efforts and wrenches are cleared.
        """
        if self.diagram is None:
            self._replay()
            return
        saved = self._save_state()
        names = (
            "builder",
            "plant",
            "scene_graph",
            "diagram",
            "simulator",
            "context",
            "visualizer",
            "contact_visualizer",
            "efforts_source",
        )
        previous = {name: getattr(self, name) for name in names}
        entries = {n: (e.robot, e.command, e.controller) for n, e in self._robots.items()}
        try:
            self.diagram = self.simulator = self.context = None
            self.visualizer = self.contact_visualizer = None
            self._replay()
            self._assemble()
        except BaseException:
            # Drake refused something: the world stays as it was, still running
            for name, value in previous.items():
                setattr(self, name, value)
            for name, (robot, command, controller) in entries.items():
                if name in self._robots:
                    entry = self._robots[name]
                    entry.robot, entry.command, entry.controller = robot, command, controller
            raise
        self._restore_state(saved)
        self.simulator.Initialize()
        self.rebuilds += 1

    def _save_state(self) -> dict[str, Any]:
        plant = self.plant
        plant_context = plant.GetMyContextFromRoot(self.context)
        states: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        for name in [*self._robots, *self._models]:
            instance = self.model_instance(name)
            if instance is None:  # being added now
                continue
            states[name] = (
                plant.GetPositions(plant_context, instance).copy(),
                plant.GetVelocities(plant_context, instance).copy(),
            )
        commands = {
            name: self._command_of(entry)
            for name, entry in self._robots.items()
            if entry.command is not None
        }
        return {"time": self.time, "states": states, "commands": commands}

    def _restore_state(self, saved: dict[str, Any]) -> None:
        self.context.SetTime(saved["time"])
        plant = self.plant
        plant_context = plant.GetMyMutableContextFromRoot(self.context)
        for name, (q, v) in saved["states"].items():
            if name not in self._robots and name not in self._models:
                continue
            instance = self.model_instance(name)
            if plant.num_positions(instance) == len(q) and plant.num_velocities(instance) == len(v):
                plant.SetPositions(plant_context, instance, q)
                plant.SetVelocities(plant_context, instance, v)
        for name, command in saved["commands"].items():
            entry = self._robots.get(name)
            if entry is not None and entry.command is not None:
                self._set_command(entry, command)

    # --- state -------------------------------------------------------------------

    def root_body(self, name: str) -> Any:
        """The body whose pose is the model's pose (the URDF root / SDF canonical link)."""
        instance = self.model_instance(name)
        if name in self._robots:
            return self.plant.GetBodyByName(self._robots[name].robot.root_link, instance)
        placed = self._models[name]
        if placed.model.root_link and self.plant.HasBodyNamed(placed.model.root_link, instance):
            return self.plant.GetBodyByName(placed.model.root_link, instance)
        return self.plant.get_body(self.plant.GetBodyIndices(instance)[0])

    def body(self, scoped_name: str) -> Any:
        """A body by Gazebo's scoped name ``model::link`` (or a link name unique in the world)."""
        self._require_built("body")
        plant = self.plant
        if "::" in scoped_name:
            # the longest model name that starts it: links of nested models are A::B::link
            owners = [m for m in self.model_names() if scoped_name.startswith(f"{m}::")]
            model = max(owners, key=len) if owners else scoped_name.partition("::")[0]
            link = scoped_name[len(model) + 2 :]
            instance = self.model_instance(model)
            found = drake_body(plant, link, instance)
            if found is None:
                raise SimulationError(f"model '{model}' has no link '{link}'")
            return plant.GetBodyByName(found, instance)
        from pydrake.multibody.tree import BodyIndex

        matches = [
            plant.get_body(BodyIndex(index))
            for index in range(1, plant.num_bodies())
            if shown_name(plant.get_body(BodyIndex(index)).name()) == scoped_name
        ]
        if len(matches) != 1:
            raise SimulationError(
                f"no link named '{scoped_name}' in the world"
                if not matches
                else f"link name '{scoped_name}' is in several models",
                hint="name it as model::link",
            )
        return matches[0]

    def get_model_pose(self, name: str) -> Any:
        """Pose of a model's frame in the world, ``X_WM`` (a RigidTransform)."""
        self._require_built("get_model_pose")
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        X_WR = self.plant.EvalBodyPoseInWorld(plant_context, self.root_body(name))
        placed = self._models.get(name)
        if placed is None or placed.X_MR is None:
            return X_WR
        return X_WR.multiply(placed.X_MR.inverse())

    def ground_penetration(self, name: str) -> float:
        """How deep model ``name``'s collision shapes reach into the ground now, m (0: none)."""
        self._require_built("ground_penetration")
        if self._ground_z is None:
            return 0.0
        sg_context = self.scene_graph.GetMyContextFromRoot(self.context)
        query = self.scene_graph.get_query_output_port().Eval(sg_context)
        inspector = query.inspector()
        bodies = {int(i) for i in self.plant.GetBodyIndices(self.model_instance(name))}
        deepest = 0.0
        for pair in query.ComputePointPairPenetration():
            names = {inspector.GetName(pair.id_A), inspector.GetName(pair.id_B)}
            if GROUND_NAME not in names:
                continue
            for geometry in (pair.id_A, pair.id_B):
                body = self.plant.GetBodyFromFrameId(inspector.GetFrameId(geometry))
                if body is not None and int(body.index()) in bodies:
                    deepest = max(deepest, float(pair.depth))
        return deepest

    def lift_out_of_ground(self, name: str, clearance: float = 0.0005) -> float:
        """Raise a free model that was placed partly below the ground until it just clears it.

        Gazebo pushes such a model out at once (ODE corrects penetration at up to 100 m/s);
        a stiff point contact would lift it slowly and hold its wheels. Returns the lift, m.
        """
        depth = self.ground_penetration(name)
        if depth <= 0.0 or not self.root_body(name).is_floating_base_body():
            return 0.0
        X_WM = self.get_model_pose(name)
        lifted = X_WM.translation() + np.array([0.0, 0.0, depth + clearance])
        from pydrake.math import RigidTransform

        v, w = self.get_model_twist(name)
        self.set_model_state(name, RigidTransform(X_WM.rotation(), lifted), v.tolist(), w.tolist())
        return depth + clearance

    def get_model_twist(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """``(v_W, w_W)``: velocity of the model's root link origin and its angular velocity in W."""
        self._require_built("get_model_twist")
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        V = self.plant.EvalBodySpatialVelocityInWorld(plant_context, self.root_body(name))
        return np.array(V.translational()), np.array(V.rotational())

    def set_model_state(
        self,
        name: str,
        X_WM: Any,
        linear: Sequence[float] | None = None,
        angular: Sequence[float] | None = None,
    ) -> None:
        """Move a model to ``X_WM`` with root velocities ``linear``/``angular`` (W, m/s, rad/s).

        A free model is teleported in place; a static one is welded anew (the
        diagram is rebuilt, other models keep their state).
        """
        self._require_built("set_model_state")
        self.model_instance(name)  # checks the name
        X = _model_transform(name, X_WM)
        for label, vector in (("linear", linear), ("angular", angular)):
            if vector is not None and not np.all(np.isfinite(np.asarray(vector, dtype=float))):
                raise SimulationError(f"model '{name}': the {label} velocity is not finite")
        body = self.root_body(name)
        placed = self._models.get(name)
        if not body.is_floating_base_body():
            if placed is None:
                raise SimulationError(
                    f"robot '{name}' is welded to the world and cannot be moved",
                    hint="add it with floating_base=True",
                )
            placed.X_WM = X
            self.rebuild()
            return
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        X_MR = placed.X_MR if placed is not None and placed.X_MR is not None else None
        self.plant.SetFloatingBaseBodyPoseInWorldFrame(
            plant_context, body, X if X_MR is None else X.multiply(X_MR)
        )
        from pydrake.multibody.math import SpatialVelocity

        # pydrake's stubs give numpy arrays a float64 shape; any float 3-vector is right here
        V = SpatialVelocity(
            np.asarray(angular if angular is not None else np.zeros(3), dtype=float),  # type: ignore[arg-type]
            np.asarray(linear if linear is not None else np.zeros(3), dtype=float),  # type: ignore[arg-type]
        )
        self.plant.SetFreeBodySpatialVelocity(plant_context, body, V)

    def link_states(self) -> list[tuple[str, Any, Any]]:
        """``(model::link, X_WL, V_WL)`` of every link of every model (Gazebo's link_states)."""
        self._require_built("link_states")
        plant = self.plant
        plant_context = plant.GetMyContextFromRoot(self.context)
        states = []
        for name in [*self._robots, *self._models]:
            for index in plant.GetBodyIndices(self.model_instance(name)):
                body = plant.get_body(index)
                states.append(
                    (
                        scoped(name, body.name()),
                        plant.EvalBodyPoseInWorld(plant_context, body),
                        plant.EvalBodySpatialVelocityInWorld(plant_context, body),
                    )
                )
        return states

    def set_body_wrenches(
        self, wrenches: Sequence[tuple[Any, Sequence[float], Sequence[float]]]
    ) -> None:
        """Apply ``(body, force_W, torque_W)`` at each body's origin until changed (N, N m).

        Replaces the wrenches applied before; ``[]`` removes them.
        """
        from pydrake.multibody.math import SpatialForce
        from pydrake.multibody.plant import ExternallyAppliedSpatialForce

        self._require_built("set_body_wrenches")
        forces = []
        for body, force, torque in wrenches:
            applied = ExternallyAppliedSpatialForce()
            applied.body_index = body.index()
            # pydrake's stubs give numpy arrays a float64 shape; 3-vectors are right here
            applied.p_BoBq_B = np.zeros(3)  # type: ignore[assignment]
            applied.F_Bq_W = SpatialForce(
                np.asarray(torque, dtype=float),  # type: ignore[arg-type]
                np.asarray(force, dtype=float),  # type: ignore[arg-type]
            )
            forces.append(applied)
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        self.plant.get_applied_spatial_force_input_port().FixValue(plant_context, forces)

    def set_joint_efforts(self, efforts: Mapping[tuple[str, str], float]) -> None:
        """Apply ``{(model, joint): effort}`` (N m or N) until changed; ``{}`` removes them."""
        self._require_built("set_joint_efforts")
        tau = np.zeros(self.plant.num_velocities())
        for (model, joint_name), effort in efforts.items():
            joint = self.joint(model, joint_name)
            if joint.num_velocities() != 1:
                raise SimulationError(f"joint '{joint_name}' of '{model}' is not a 1-dof joint")
            tau[joint.velocity_start()] += float(effort)
        source_context = self.efforts_source.GetMyMutableContextFromRoot(self.context)
        self.efforts_source.get_mutable_source_value(source_context).set_value(tau)

    def add_velocity_motors(self, model: str, limits: Mapping[str, float]) -> None:
        """Give joints of a model velocity motors ``{joint: effort limit}`` (N m or N), held at 0.

        Gazebo's ``Joint::SetParam("vel"/"fmax")`` (see :mod:`workbench.sim.motors`).
        The diagram is rebuilt (every model keeps its state).

        Raises:
            SimulationError: Not a model of this world, or a joint is missing or not 1-dof
                (the world is unchanged).
        """
        placed = self._models.get(model)
        if placed is None:
            raise SimulationError(f"no model named '{model}' in the world")
        for joint_name in limits:
            if self.joint(model, joint_name).num_velocities() != 1:
                raise SimulationError(f"joint '{joint_name}' of '{model}' is not a 1-dof joint")
        before = dict(placed.motors)
        placed.motors.update({joint: float(limit) for joint, limit in limits.items()})
        try:
            self.rebuild()
        except (SimulationError, RuntimeError):
            placed.motors = before
            raise

    def set_motor_targets(self, model: str, velocities: Mapping[str, float]) -> None:
        """Target velocities ``{joint: v}`` of a model's motors (rad/s or m/s) until changed."""
        from workbench.sim.motors import fix_motor_targets

        placed = self._models.get(model)
        if placed is None:
            raise SimulationError(f"no model named '{model}' in the world")
        placed.motor_targets.update({joint: float(v) for joint, v in velocities.items()})
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        fix_motor_targets(self.plant, plant_context, placed.instance, placed.motor_targets)

    def motor_efforts(self, model: str) -> dict[str, float]:
        """``{joint: effort}`` a model's motors applied in the last step, N m or N."""
        from workbench.sim.motors import motor_efforts

        plant_context = self.plant.GetMyContextFromRoot(self.context)
        return motor_efforts(self.plant, plant_context, self.model_instance(model))

    def set_joint_positions(self, model: str, positions: Mapping[str, float]) -> None:
        """Move 1-dof joints of a model to ``{joint: position}`` now, at rest (rad or m)."""
        self._require_built("set_joint_positions")
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        q = self.plant.GetPositions(plant_context).copy()
        v = self.plant.GetVelocities(plant_context).copy()
        for joint_name, value in positions.items():
            joint = self.joint(model, joint_name)
            if joint.num_positions() != 1 or not np.isfinite(value):
                raise SimulationError(
                    f"joint '{joint_name}' of '{model}': not a 1-dof joint or not a finite value"
                )
            q[joint.position_start()] = float(value)
            v[joint.velocity_start()] = 0.0
        self.plant.SetPositions(plant_context, q)
        self.plant.SetVelocities(plant_context, v)

    def joint(self, model: str, joint_name: str) -> Any:
        """A joint of a model by name."""
        instance = self.model_instance(model)
        found = drake_joint(self.plant, joint_name, instance)
        if found is None:
            from workbench.sim.scene import joint_names

            raise SimulationError(
                f"model '{model}' has no joint '{joint_name}'",
                hint="joints: " + (", ".join(joint_names(self.plant, instance)) or "none"),
            )
        return self.plant.GetJointByName(found, instance)

    def reset(self, *, time: bool = True) -> None:
        """Every model back to where it was spawned, at rest (``time``: the clock to 0 too)."""
        self._require_built("reset")
        plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        for placed in self._models.values():
            placed.X_WM = placed.initial_X_WM
        static_moved = any(
            p.model.static and p.X_WM is not p.initial_X_WM for p in self._models.values()
        )
        if static_moved:
            self.rebuild()
            plant_context = self.plant.GetMyMutableContextFromRoot(self.context)
        self.plant.SetDefaultState(plant_context, plant_context.get_mutable_state())
        for entry in self._robots.values():
            if entry.command is not None:
                q0 = self.plant.GetPositions(plant_context, entry.robot.model_instance)
                self._set_command(entry, Command(q0.copy()))
        if time:
            self.context.SetTime(0.0)
            self._next_publish = 0.0
        self.simulator.Initialize()

    def state_is_finite(self) -> bool:
        """False once the simulation blew up (a NaN or infinite position or velocity)."""
        plant_context = self.plant.GetMyContextFromRoot(self.context)
        return bool(np.all(np.isfinite(self.plant.GetPositionsAndVelocities(plant_context))))

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
        seconds = self.time if self.publish_clock else time.time()
        nanos = int(round(seconds * 1e9))
        stamp = Time(nanos // 1_000_000_000, nanos % 1_000_000_000)
        if self.publish_clock:
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

    def _add_obstacle(self, name: str, shape: Any, X_WB: Any, rgba: Any) -> None:
        self._require_open(f"add '{name}'")
        taken = {o.name for o in self._obstacles} | {GROUND_NAME}
        if not name or name in taken:
            raise SimulationError(f"obstacle name '{name}' is empty or already used")
        obstacle = _Obstacle(name, shape, _transform(X_WB), rgba)
        add_obstacle(self.plant, obstacle.name, obstacle.shape, obstacle.X_WB, obstacle.rgba)
        self._obstacles.append(obstacle)

    def _geometry_label(self, inspector: Any, geometry_id: Any) -> str:
        body = self.plant.GetBodyFromFrameId(inspector.GetFrameId(geometry_id))
        if body is None or body.index() == self.plant.world_body().index():
            return inspector.GetName(geometry_id)
        return shown_name(body.name())

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


def _render_engine() -> Any:
    from pydrake.geometry import MakeRenderEngineVtk, RenderEngineVtkParams

    return MakeRenderEngineVtk(RenderEngineVtkParams())


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


def _as_simulation_error(error: Exception, model: SimModel) -> SimulationError:
    if isinstance(error, SimulationError):
        return error
    first = next((line for line in str(error).splitlines() if line.strip()), type(error).__name__)
    return SimulationError(
        f"model '{model.name}' ({model.source}): Drake cannot simulate it: {first}"
    )


def _model_transform(name: str, X: Any) -> Any:
    """``_transform`` whose errors name the model and say the pose is not finite."""
    try:
        transform = as_rigid_transform(X)
    except SpatialError as error:
        raise SimulationError(
            f"model '{name}': the pose is not finite or malformed: {error.message}"
        ) from None
    if not np.all(np.isfinite(transform.GetAsMatrix4())):
        raise SimulationError(f"model '{name}': the pose is not finite")
    return transform


def _gravity_vector(gravity: float | Sequence[float]) -> np.ndarray:
    """``9.81`` (m/s^2 along -z) or a 3-vector in W, checked finite."""
    if isinstance(gravity, (int, float)):
        vector = np.array([0.0, 0.0, -float(gravity)])
    else:
        vector = np.asarray(gravity, dtype=float).reshape(-1)
    if vector.shape != (3,) or not np.all(np.isfinite(vector)):
        raise SimulationError(f"gravity must be a number or a finite 3-vector, got {gravity!r}")
    return vector
