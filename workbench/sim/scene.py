"""Putting things into a World's Drake plant: the ground, static obstacles and Gazebo-style models.

These are the steps :class:`workbench.sim.World` replays each time it (re)builds
its diagram, so they take the plant and what to add, and keep no state.
"""

from __future__ import annotations

import logging
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.model.sdf_names import drake_joint, shown_name
from workbench.sim.model_spec import SimModel
from workbench.spatial import rigid_transform

GROUND_NAME = "ground_plane"
GROUND_FRICTION = 1.0
GROUND_SIZE = 100.0
CORNER_RADIUS = 0.001
_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)

_LOG = logging.getLogger("workbench.sim")


@dataclass
class PlacedModel:
    """A Gazebo-style model in the world: what it is and where it was put.

    Attributes:
        model: The parsed-ready model.
        X_WM: Where the model frame was placed (spawn pose), a RigidTransform.
        joint_positions: Initial joint positions by joint name (``-J``), rad or m.
        instance: The model instance in the current plant.
        initial_X_WM: The pose the model was spawned at (``reset_world`` returns there).
        X_MR: Pose of the model's root link in its model frame (set when parsed).
        motors: Joint velocity motors ``{joint: effort limit}`` a plugin asked for
            (see :mod:`workbench.sim.motors`), N m or N.
        motor_targets: Their target velocities ``{joint: velocity}``, rad/s or m/s.
    """

    model: SimModel
    X_WM: Any
    joint_positions: dict[str, float] = field(default_factory=dict)
    instance: Any = None
    initial_X_WM: Any = None
    X_MR: Any = None
    motors: dict[str, float] = field(default_factory=dict)
    motor_targets: dict[str, float] = field(default_factory=dict)


def add_ground(plant: Any, z: float) -> None:
    """The ground: a half space whose surface is the plane ``z``, drawn 100 m x 100 m as Gazebo's."""
    # A half space, not a box: its contact with cylinders and spheres is analytic
    # (a box made the two-wheeled robot 30 % slower). Drake warns that half spaces
    # take no part in deformable contact, which the simulator does not use.
    from pydrake.geometry import Box, HalfSpace
    from pydrake.multibody.plant import CoulombFriction

    world = plant.world_body()
    drake_log = logging.getLogger("drake")
    if not any(isinstance(f, _HalfSpaceNotice) for f in drake_log.filters):
        drake_log.addFilter(_HalfSpaceNotice())
    plant.RegisterCollisionGeometry(
        world,
        rigid_transform([0.0, 0.0, z]),
        HalfSpace(),
        GROUND_NAME,
        CoulombFriction(GROUND_FRICTION, GROUND_FRICTION),
    )
    plant.RegisterVisualGeometry(
        world,
        rigid_transform([0.0, 0.0, z - 0.005]),
        Box(GROUND_SIZE, GROUND_SIZE, 0.01),
        GROUND_NAME,
        np.array([0.8, 0.8, 0.8, 1.0]),
    )


class _HalfSpaceNotice(logging.Filter):
    """Drops Drake's notice that half spaces take no part in deformable contact."""

    def filter(self, record: logging.LogRecord) -> bool:
        return "half spaces are not currently supported for deformable" not in record.getMessage()


def add_obstacle(plant: Any, name: str, shape: Any, X_WB: Any, rgba: Any) -> None:
    """A static shape welded to the world, with collision and visual geometry."""
    from pydrake.multibody.plant import CoulombFriction
    from pydrake.multibody.tree import SpatialInertia, default_model_instance

    # On a body welded to the world rather than on the world body: a few hundred shapes
    # anchored beside the ground's half space crash Drake 1.51 (its broad phase copies a
    # tree holding the half space's infinite box when a context is made). Welded, they are
    # just as static and filtered against each other and the ground.
    body = plant.AddRigidBody(name, default_model_instance(), SpatialInertia.Zero())
    plant.WeldFrames(plant.world_frame(), body.body_frame(), X_WB)
    identity = rigid_transform([0.0, 0.0, 0.0])
    plant.RegisterCollisionGeometry(body, identity, shape, name, CoulombFriction(0.8, 0.6))
    color = np.array(rgba if rgba is not None else [0.55, 0.45, 0.35, 1.0], dtype=float)
    plant.RegisterVisualGeometry(body, identity, shape, name, color)


def add_placed_model(plant: Any, placed: PlacedModel, scene_graph: Any = None) -> Any:
    """Parse ``placed.model`` into ``plant`` and put it at ``placed.X_WM``.

    Root bodies (those no joint of the model moves) are free bodies placed at
    ``X_WM * X_MB``, or welded there when the model is static (a root of a nested
    model follows that model's ``<static>``, ``model.static_links``). ``-J`` joint
    positions become the joints' default positions. With ``scene_graph``, the
    boxes of a free one-link model (a box, a cup: things that lie on surfaces) get
    corner points (:func:`add_corner_points`); robots stand on their wheels and
    casters, and 8 more geometries per box would slow them down.

    Returns:
        The model instance.

    Raises:
        SimulationError: Drake refused the model, or a ``-J`` joint does not exist.
    """
    from pydrake.multibody.parsing import Parser

    model = placed.model
    parser = Parser(plant)
    for package, folder in model.package_map.items():
        if not parser.package_map().Contains(package):
            parser.package_map().Add(package, Path(folder))
    drake_log = logging.getLogger("drake")
    level = drake_log.level
    drake_log.setLevel(logging.ERROR)  # what Drake would warn about was fixed and reported already
    try:
        instances = parser.AddModelsFromString(model.text, model.format)
    except RuntimeError as error:
        first = shown_name(next((line for line in str(error).splitlines() if line.strip()), ""))
        # Drake numbers the lines of the text it was given, not of the user's file
        first = re.sub(r"<(literal|data)-string>(\.\w+)?:\d+: (error: )?", "", first)
        raise SimulationError(
            f"model '{model.name}' ({model.source or model.format}): Drake cannot load it: {first}"
        ) from None
    finally:
        drake_log.setLevel(level)
    if not instances:
        raise SimulationError(f"model '{model.name}' ({model.source}) defines no model")
    instance = instances[0]
    _refuse_loops(plant, instance, model)
    X_pose = rigid_transform(model.pose[:3], rpy=model.pose[3:])
    X_WM = placed.X_WM.multiply(X_pose)
    roots = root_bodies(plant, instance)
    canonical = next((b for b in roots if b.name() == model.root_link), roots[0] if roots else None)
    for body in roots:
        X_MB = plant.GetDefaultFloatingBaseBodyPose(body)
        if canonical is not None and body.index() == canonical.index():
            placed.X_MR = X_MB
        X_WB = X_WM.multiply(X_MB)
        if model.static_links.get(body.name(), model.static):
            plant.WeldFrames(plant.world_frame(), body.body_frame(), X_WB)
        else:
            plant.SetDefaultFloatingBaseBodyPose(body, X_WB)
    for joint_name, value in placed.joint_positions.items():
        found = drake_joint(plant, joint_name, instance)
        if found is None:
            raise SimulationError(
                f"model '{model.name}' has no joint '{joint_name}'",
                hint="joints: " + ", ".join(joint_names(plant, instance)),
            )
        joint = plant.GetJointByName(found, instance)
        if joint.num_positions() != 1:
            raise SimulationError(f"joint '{joint_name}' of '{model.name}' is not a 1-dof joint")
        joint.set_default_positions(np.array([float(value)]))
    if model.collision_pieces:
        add_collision_pieces(plant, instance, model)
    if placed.motors:
        from workbench.sim.motors import add_velocity_motors

        add_velocity_motors(plant, instance, placed.motors)
    if not model.gravity:
        plant.set_gravity_enabled(instance, False)
    if not model.static and scene_graph is not None and len(plant.GetBodyIndices(instance)) == 1:
        add_corner_points(plant, scene_graph, instance)
    placed.instance = instance
    return instance


def _refuse_loops(plant: Any, instance: Any, model: SimModel) -> None:
    """Refuse, naming the joint, a model whose joints close a loop (Drake builds trees only;
    it would fail later, at Finalize, without naming the model)."""
    group: dict[int, int] = {}

    def root(i: int) -> int:
        while group.setdefault(i, i) != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    for index in plant.GetJointIndices(instance):
        joint = plant.get_joint(index)
        a, b = root(int(joint.parent_body().index())), root(int(joint.child_body().index()))
        if a == b:
            raise SimulationError(
                f"model '{model.name}' ({model.source or model.format}): joint "
                f"'{shown_name(joint.name())}' closes a loop of links, which Drake cannot "
                "simulate (Gazebo can)",
                hint="remove one joint of the loop",
            )
        group[a] = b


def add_collision_pieces(plant: Any, instance: Any, model: SimModel) -> None:
    """Register the convex pieces of the model's concave collision meshes on their links."""
    from pydrake.geometry import Convex
    from pydrake.multibody.plant import CoulombFriction

    for item in model.collision_pieces:
        body = plant.GetBodyByName(item.link, instance)
        X_BC = rigid_transform(item.pose[:3], rpy=item.pose[3:])
        friction = CoulombFriction(item.friction, item.friction)
        for k, points in enumerate(item.pieces):
            label = f"{item.name}_piece_{k}"
            shape = Convex(np.asarray(points, dtype=float).T, label)
            plant.RegisterCollisionGeometry(body, X_BC, shape, label, friction)


def add_corner_points(plant: Any, scene_graph: Any, instance: Any) -> None:
    """Give every box of ``instance`` small spheres in its 8 corners.

    Drake's point contact makes one contact point per pair of geometries, so a
    box standing on the ground (or on another box) touches it at one point and
    rocks, hops and stops short when pushed; Gazebo's ODE makes a point per
    touching corner. A sphere of radius ``CORNER_RADIUS`` inside each corner,
    flush with the faces and with the box's friction, gives the same corner
    contacts (the standard way to make boxes sit flat under point contact).
    """
    from pydrake.geometry import Box, ProximityProperties, Sphere
    from pydrake.math import RigidTransform

    inspector = scene_graph.model_inspector()
    boxes = []
    # Everything is read before anything is registered: registering moves the plant's
    # geometry lists, and the ids pybind handed out point into them.
    for index in plant.GetBodyIndices(instance):
        body = plant.get_body(index)
        for geometry in plant.GetCollisionGeometriesForBody(body):
            shape = inspector.GetShape(geometry)
            if isinstance(shape, Box):
                half = np.array([shape.width(), shape.depth(), shape.height()]) / 2.0
                boxes.append(
                    (
                        body,
                        half,
                        RigidTransform(inspector.GetPoseInFrame(geometry)),
                        ProximityProperties(inspector.GetProximityProperties(geometry)),
                        inspector.GetName(geometry),
                    )
                )
    for body, half, X_BG, properties, name in boxes:
        radius = min(CORNER_RADIUS, 0.25 * float(half.min()))
        for k, signs in enumerate(_CORNERS):
            plant.RegisterCollisionGeometry(
                body,
                X_BG.multiply(rigid_transform(signs * (half - radius))),
                Sphere(radius),
                f"{name}_corner_{k}",
                properties,
            )


def filter_self_collisions(plant: Any, scene_graph: Any, instance: Any) -> None:
    """Stop a model's links colliding with each other (Gazebo's default, ``selfCollide`` off)."""
    from pydrake.geometry import CollisionFilterDeclaration

    bodies = [plant.get_body(index) for index in plant.GetBodyIndices(instance)]
    if len(bodies) < 2:
        return
    geometries = plant.CollectRegisteredGeometries(bodies)
    scene_graph.collision_filter_manager().Apply(
        CollisionFilterDeclaration().ExcludeWithin(geometries)
    )


def root_bodies(plant: Any, instance: Any) -> list[Any]:
    """The bodies of ``instance`` that no joint moves (the model's free or welded roots)."""
    moved = {plant.get_joint(j).child_body().index() for j in plant.GetJointIndices(instance)}
    return [plant.get_body(index) for index in plant.GetBodyIndices(instance) if index not in moved]


def joint_names(plant: Any, instance: Any) -> list[str]:
    """Names of the joints of ``instance`` that have positions (free-body joints excluded)."""
    names = []
    for index in plant.GetJointIndices(instance):
        joint = plant.get_joint(index)
        if joint.num_positions() and joint.type_name() not in (
            "quaternion_floating",
            "rpy_floating",
        ):
            names.append(shown_name(joint.name()))
    return names
