"""A World's collision geometry as a :class:`~workbench.sim.sensors.raycast.ShapeTable`.

The shapes are read from Drake's SceneGraph (the model inspector) once per
diagram (the World rebuilds it when models come and go); their poses are
refreshed from the plant for each query. Meshes and convex shapes are taken as
their convex hulls, which is what Drake's point contact collides with.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.sim.sensors.raycast import (
    BOX,
    CAPSULE,
    CONVEX,
    CYLINDER,
    ELLIPSOID,
    HALFSPACE,
    SPHERE,
    ShapeTable,
)


@dataclass
class CollisionScene:
    """The shapes of one diagram, with what is needed to pose them.

    Attributes:
        table: The shapes (poses as of the last :meth:`update`).
        bodies: (n,) the body index each shape is fixed to (0: the world).
        R_BG: (n, 3, 3) and p_BG (n, 3): each shape in its body.
        names: Each shape's geometry name, for messages.
        scene_graph: The SceneGraph this was read from.
        moving: Rows of shapes on bodies not welded to the world (None: not yet sorted).
    """

    table: ShapeTable
    bodies: np.ndarray
    R_BG: np.ndarray
    p_BG: np.ndarray
    names: list[str]
    scene_graph: Any
    moving: np.ndarray | None = None

    def update(self, world: Any) -> None:
        """Pose every shape as the world is now (only the shapes of moving bodies change)."""
        if self.moving is None:
            self._anchor_welded(world)
        moving = self.moving
        assert moving is not None
        if moving.size == 0:
            return
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        bodies = self.bodies[moving]
        R_WB = np.empty((len(moving), 3, 3))
        p_WB = np.empty((len(moving), 3))
        from pydrake.multibody.tree import BodyIndex

        for body in np.unique(bodies):
            X = plant.EvalBodyPoseInWorld(context, plant.get_body(BodyIndex(int(body))))
            pick = bodies == body
            R_WB[pick] = X.rotation().matrix()
            p_WB[pick] = X.translation()
        self.table.R_WG[moving] = R_WB @ self.R_BG[moving]
        self.table.p_WG[moving] = np.einsum("nij,nj->ni", R_WB, self.p_BG[moving]) + p_WB

    def _anchor_welded(self, world: Any) -> None:
        """Fold bodies welded to the world into it: static models never move in a diagram
        (moving one rebuilds it), so their shapes are posed once."""
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        welded = {int(body.index()) for body in plant.GetBodiesWeldedTo(plant.world_body())}
        from pydrake.multibody.tree import BodyIndex

        R_WG, p_WG = self.R_BG.copy(), self.p_BG.copy()
        fixed = self.bodies == 0
        for body in np.unique(self.bodies):
            if body == 0 or int(body) not in welded:
                continue
            X = plant.EvalBodyPoseInWorld(context, plant.get_body(BodyIndex(int(body))))
            pick = self.bodies == body
            R = X.rotation().matrix()
            R_WG[pick] = R @ self.R_BG[pick]
            p_WG[pick] = self.p_BG[pick] @ R.T + X.translation()
            fixed |= pick
        self.table.R_WG, self.table.p_WG = R_WG, p_WG
        self.moving = np.flatnonzero(~fixed)

    def mask_without(self, body_index: int | None) -> np.ndarray | None:
        """Shapes not fixed to ``body_index`` (None: all)."""
        if body_index is None or body_index == 0:
            return None
        return self.bodies != body_index


_SCENES: weakref.WeakKeyDictionary[Any, CollisionScene] = weakref.WeakKeyDictionary()


def collision_scene(world: Any) -> CollisionScene:
    """The posed collision shapes of a built ``World`` (read again after a rebuild)."""
    if world.diagram is None:
        raise SimulationError("build the world before casting rays in it")
    scene = _SCENES.get(world)
    if scene is None or scene.scene_graph is not world.scene_graph:
        scene = read_scene(world.plant, world.scene_graph)
        _SCENES[world] = scene
    scene.update(world)
    return scene


def read_scene(plant: Any, scene_graph: Any) -> CollisionScene:
    """Every proximity geometry of a finalized plant, in its body's frame."""
    from pydrake.geometry import (
        Box,
        Capsule,
        Convex,
        Cylinder,
        Ellipsoid,
        HalfSpace,
        Mesh,
        Role,
        Sphere,
    )

    inspector = scene_graph.model_inspector()
    kinds: list[int] = []
    params: list[np.ndarray] = []
    centers: list[np.ndarray] = []
    radii: list[float] = []
    bodies: list[int] = []
    R_BG: list[np.ndarray] = []
    p_BG: list[np.ndarray] = []
    names: list[str] = []
    planes: dict[int, np.ndarray] = {}
    world_index = plant.world_body().index()
    for geometry in inspector.GetAllGeometryIds(Role.kProximity):
        shape = inspector.GetShape(geometry)
        center = np.zeros(3)
        param = np.zeros(3)
        if isinstance(shape, Box):
            kind, param = BOX, np.asarray(shape.size(), dtype=float) / 2.0
            radius = float(np.linalg.norm(param))
        elif isinstance(shape, Sphere):
            kind, radius = SPHERE, shape.radius()
            param[0] = radius
        elif isinstance(shape, Cylinder):
            kind = CYLINDER
            param[:2] = shape.radius(), shape.length() / 2.0
            radius = float(np.hypot(*param[:2]))
        elif isinstance(shape, Capsule):
            kind = CAPSULE
            param[:2] = shape.radius(), shape.length() / 2.0
            radius = float(param[0] + param[1])
        elif isinstance(shape, Ellipsoid):
            kind, param = ELLIPSOID, np.array([shape.a(), shape.b(), shape.c()])
            radius = float(param.max())
        elif isinstance(shape, HalfSpace):
            kind, radius = HALFSPACE, np.inf
        elif isinstance(shape, (Mesh, Convex)):
            kind = CONVEX
            hull_planes, center, radius = _hull(shape.GetConvexHull())
            planes[len(kinds)] = hull_planes
        else:  # a shape a ray sensor cannot see (e.g. a point cloud): skipped
            continue
        frame = inspector.GetFrameId(geometry)
        body = plant.GetBodyFromFrameId(frame)
        X_FG = inspector.GetPoseInFrame(geometry)
        R = X_FG.rotation().matrix()
        pieces = _box_pieces(param) if kind == BOX else [(param, np.zeros(3))]
        for piece, offset in pieces:
            kinds.append(kind)
            params.append(piece)
            centers.append(center)
            radii.append(float(np.linalg.norm(piece)) if kind == BOX else radius)
            bodies.append(0 if body is None or body.index() == world_index else int(body.index()))
            R_BG.append(R)
            p_BG.append(X_FG.translation() + R @ offset)
            names.append(inspector.GetName(geometry))
    n = len(kinds)
    table = ShapeTable(
        kind=np.asarray(kinds, dtype=np.int64),
        params=np.asarray(params, dtype=float).reshape(n, 3),
        R_WG=np.asarray(R_BG, dtype=float).reshape(n, 3, 3),
        p_WG=np.asarray(p_BG, dtype=float).reshape(n, 3),
        center_G=np.asarray(centers, dtype=float).reshape(n, 3),
        radius=np.asarray(radii, dtype=float),
        planes=planes,
    )
    return CollisionScene(
        table=table,
        bodies=np.asarray(bodies, dtype=np.int64),
        R_BG=np.asarray(R_BG, dtype=float).reshape(n, 3, 3),
        p_BG=np.asarray(p_BG, dtype=float).reshape(n, 3),
        names=names,
        scene_graph=scene_graph,
    )


def _box_pieces(half: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """A long box as boxes of at most twice its middle half extent, end to end along its length.

    The pieces fill the box exactly, so a ray from outside enters the first piece
    where it enters the box; their bounding spheres are tight, which is what the
    broad phase needs (a 12 m wall's own sphere would cover every beam).
    """
    axis = int(np.argmax(half))
    middle = float(np.sort(half)[1])
    count = int(min(64, np.ceil(half[axis] / max(middle, 0.05, half[axis] / 64))))
    if count <= 1:
        return [(half, np.zeros(3))]
    piece = half.copy()
    piece[axis] = half[axis] / count
    pieces = []
    for k in range(count):
        offset = np.zeros(3)
        offset[axis] = -half[axis] + (2 * k + 1) * piece[axis]
        pieces.append((piece.copy(), offset))
    return pieces


def _hull(mesh: Any) -> tuple[np.ndarray, np.ndarray, float]:
    """Half planes ``n . x <= b`` of a convex PolygonSurfaceMesh, its centre and bounding radius."""
    vertices = np.array([mesh.vertex(i) for i in range(mesh.num_vertices())], dtype=float)
    data = mesh.face_data()
    rows = []
    i = 0
    for face in range(mesh.num_faces()):
        count = int(data[i])
        first = vertices[int(data[i + 1])]
        normal = np.asarray(mesh.face_normal(face), dtype=float)
        rows.append([*normal, float(normal @ first)])
        i += count + 1
    center = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    radius = float(np.linalg.norm(vertices - center, axis=1).max())
    return np.asarray(rows, dtype=float), center, radius
