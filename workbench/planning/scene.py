"""A planning scene: static obstacles (box, sphere, cylinder, mesh) posed in the world frame.

A scene comes from Python (:meth:`PlanningScene.add_box` and friends) or from a
YAML file such as ``planning/scenes/table.yaml``::

    objects:
      - name: table
        type: box
        size: [0.8, 0.6, 0.04]          # x, y, z extents, metres
        pose: {xyz: [0.5, 0.0, 0.2], rpy: [0, 0, 0]}
      - name: ball
        type: sphere
        radius: 0.05
        pose: {xyz: [0.3, 0.2, 0.5]}
      - name: post
        type: cylinder                  # axis along the object's z
        radius: 0.03
        length: 0.4
        pose: {xyz: [0.4, -0.3, 0.2]}
      - name: part
        type: mesh
        filename: part.obj              # relative to the YAML file
        scale: 1.0

A bare list of objects is accepted too. Poses are in the world frame (REP 103:
metres, radians, fixed-axis roll-pitch-yaw). Nothing here imports pydrake.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from workbench.errors import ModelError
from workbench.paths import is_file
from workbench.planning.errors import SceneError
from workbench.spatial import Box, Cylinder, Mesh, Shape, Sphere, matrix_from_rpy, pose_matrix
from workbench.spatial.shapes import SHAPE_FIELDS

#: The object types a scene may hold and the size fields each needs.
SIZE_FIELDS: dict[str, tuple[str, ...]] = SHAPE_FIELDS
#: Most objects in one scene: each is checked in every planning step, and setting up the
#: planner's distance table takes about 0.05 s per object on a 2-core machine.
MAX_SCENE_OBJECTS = 500
#: Largest scene file, bytes.
MAX_SCENE_BYTES = 16 * 1024 * 1024
#: Mesh formats a scene takes: what Drake builds a convex hull from.
SCENE_MESH_FORMATS = (".obj", ".gltf", ".vtk")


def rpy_to_matrix(rpy: np.ndarray) -> np.ndarray:
    """Rotation matrix of fixed-axis roll, pitch, yaw (URDF convention), radians."""
    return matrix_from_rpy(rpy)


@dataclass
class SceneObject:
    """One static obstacle.

    Attributes:
        name: Unique name (shown in collision messages and the viewer).
        type: ``box``, ``sphere``, ``cylinder`` or ``mesh``.
        size: Box extents (x, y, z) in metres; unused otherwise.
        radius: Sphere or cylinder radius, metres.
        length: Cylinder length along its z axis, metres.
        filename: Mesh file (OBJ, STL, ...) for ``mesh``.
        scale: Uniform mesh scale.
        xyz: Position of the object frame in the world frame, metres.
        rpy: Orientation of the object frame in the world frame, radians.
    """

    name: str
    type: str
    size: np.ndarray = field(default_factory=lambda: np.zeros(3))
    radius: float = 0.0
    length: float = 0.0
    filename: Path | None = None
    scale: float = 1.0
    xyz: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rpy: np.ndarray = field(default_factory=lambda: np.zeros(3))

    @property
    def X_WO(self) -> np.ndarray:  # noqa: N802 (monogram notation)
        """The object's pose in the world frame as a 4x4 homogeneous matrix."""
        return pose_matrix(self.xyz, rpy=self.rpy)

    @property
    def shape(self) -> Shape:
        """The object's geometry in the :mod:`workbench.spatial` vocabulary."""
        if self.type == "box":
            return Box(tuple(float(v) for v in self.size))  # type: ignore[arg-type]
        if self.type == "sphere":
            return Sphere(float(self.radius))
        if self.type == "cylinder":
            return Cylinder(float(self.radius), float(self.length))
        return Mesh(str(self.filename), float(self.scale))

    def half_extents(self) -> np.ndarray:
        """Half extents of the object's bounding box in its own frame, metres."""
        return self.shape.half_extents()

    def mesh_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper corner of a mesh's vertices in the object frame (scaled), metres."""
        return Mesh(str(self.filename), float(self.scale)).bounds()


class _LineLoader(yaml.SafeLoader):
    """A YAML loader that records the 1-based line of every mapping under ``__line__``."""


def _construct_mapping(loader: _LineLoader, node: yaml.MappingNode) -> dict[str, Any]:
    mapping = loader.construct_mapping(node, deep=True)
    mapping["__line__"] = node.start_mark.line + 1
    return mapping


_LineLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


class PlanningScene:
    """The obstacles around the robot, all fixed in the world frame."""

    def __init__(self, objects: list[SceneObject] | None = None, *, source: Path | None = None):
        self.objects: list[SceneObject] = []
        self.source = source
        for obj in objects or []:
            self.add(obj)

    def __len__(self) -> int:
        return len(self.objects)

    def __iter__(self):
        return iter(self.objects)

    def names(self) -> list[str]:
        """The object names in insertion order."""
        return [obj.name for obj in self.objects]

    def add(self, obj: SceneObject) -> SceneObject:
        """Add an object after validating its type, sizes and name.

        Raises:
            SceneError: A bad object, a name already used, or more than
                :data:`MAX_SCENE_OBJECTS` objects.
        """
        if len(self.objects) >= MAX_SCENE_OBJECTS:
            raise SceneError(
                f"a scene holds at most {MAX_SCENE_OBJECTS} objects",
                hint="merge obstacles into larger boxes or meshes; see 'Limits on input' in the README",
            )
        _validate(obj)
        if obj.name in self.names():
            raise SceneError(
                f"the scene already has an object named '{obj.name}'", hint="rename it"
            )
        self.objects.append(obj)
        return obj

    def add_box(self, name: str, size, xyz=(0, 0, 0), rpy=(0, 0, 0)) -> SceneObject:
        """Add a box with extents ``size`` (x, y, z) in metres, centred at its frame."""
        return self.add(SceneObject(name, "box", size=_vec(size), xyz=_vec(xyz), rpy=_vec(rpy)))

    def add_sphere(self, name: str, radius: float, xyz=(0, 0, 0)) -> SceneObject:
        """Add a sphere of ``radius`` metres centred at ``xyz``."""
        return self.add(SceneObject(name, "sphere", radius=float(radius), xyz=_vec(xyz)))

    def add_cylinder(
        self, name: str, radius: float, length: float, xyz=(0, 0, 0), rpy=(0, 0, 0)
    ) -> SceneObject:
        """Add a cylinder (axis along its z, centred at its frame), metres."""
        return self.add(
            SceneObject(
                name,
                "cylinder",
                radius=float(radius),
                length=float(length),
                xyz=_vec(xyz),
                rpy=_vec(rpy),
            )
        )

    def add_mesh(
        self,
        name: str,
        filename: str | os.PathLike[str],
        scale: float = 1.0,
        xyz=(0, 0, 0),
        rpy=(0, 0, 0),
    ) -> SceneObject:
        """Add a mesh obstacle read from ``filename`` (OBJ, STL ...), scaled uniformly."""
        return self.add(
            SceneObject(
                name,
                "mesh",
                filename=Path(filename),
                scale=float(scale),
                xyz=_vec(xyz),
                rpy=_vec(rpy),
            )
        )

    def to_dict(self) -> dict[str, Any]:
        """The scene in the YAML layout (for writing back)."""
        out = []
        for obj in self.objects:
            item: dict[str, Any] = {"name": obj.name, "type": obj.type}
            if obj.type == "box":
                item["size"] = [float(v) for v in obj.size]
            if obj.type in ("sphere", "cylinder"):
                item["radius"] = obj.radius
            if obj.type == "cylinder":
                item["length"] = obj.length
            if obj.type == "mesh":
                item["filename"] = str(obj.filename)
                item["scale"] = obj.scale
            item["pose"] = {"xyz": [float(v) for v in obj.xyz], "rpy": [float(v) for v in obj.rpy]}
            out.append(item)
        return {"objects": out}


def _vec(value, n: int = 3) -> np.ndarray:
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if not isinstance(value, list | tuple):
        raise ValueError(f"expected a list of {n} numbers, got {_shown(value)}")
    if len(value) != n:
        raise ValueError(f"expected {n} numbers, got {len(value)}")
    if not all(isinstance(v, int | float | np.number) and not isinstance(v, bool) for v in value):
        raise ValueError(f"expected {n} numbers, got {_shown(value)}")
    return np.array(value, dtype=float)


def _number(value: Any, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float | np.number):
        raise ValueError(f"{what} must be a number, got {_shown(value)}")
    return float(value)


def _shown(value: Any) -> str:
    text = (
        repr(value)
        if isinstance(value, str | int | float | bool) or value is None
        else type(value).__name__
    )
    return text if len(text) <= 40 else text[:37] + "..."


def _validate(obj: SceneObject) -> None:
    from workbench.model.limits import name_problem, shown_name

    if not obj.name or not isinstance(obj.name, str):
        raise SceneError("a scene object needs a non-empty 'name'")
    problem = name_problem(obj.name)
    if problem is not None:
        raise SceneError(
            f"object name '{shown_name(obj.name)}' {problem}",
            hint="give it a short name of printable characters",
        )
    if obj.type not in SIZE_FIELDS:
        raise SceneError(
            f"object '{obj.name}' has unknown type '{obj.type}'",
            hint=f"use one of {', '.join(SIZE_FIELDS)}",
        )
    if obj.type == "box" and not (np.all(np.isfinite(obj.size)) and np.all(obj.size > 0)):
        raise SceneError(f"box '{obj.name}' needs three positive sizes, got {list(obj.size)}")
    if obj.type in ("sphere", "cylinder") and not (math.isfinite(obj.radius) and obj.radius > 0):
        raise SceneError(f"{obj.type} '{obj.name}' needs a positive radius, got {obj.radius}")
    if obj.type == "cylinder" and not (math.isfinite(obj.length) and obj.length > 0):
        raise SceneError(f"cylinder '{obj.name}' needs a positive length, got {obj.length}")
    if obj.type == "mesh":
        if obj.filename is None or not is_file(obj.filename):
            raise SceneError(f"mesh '{obj.name}': file '{obj.filename}' not found")
        if not (math.isfinite(obj.scale) and obj.scale > 0):
            raise SceneError(f"mesh '{obj.name}' needs a positive scale, got {obj.scale}")
        check_scene_mesh(obj.name, Path(obj.filename))
    if not (np.all(np.isfinite(obj.xyz)) and np.all(np.isfinite(obj.rpy))):
        raise SceneError(f"object '{obj.name}' has a non-finite pose")


def load_scene(path: str | os.PathLike[str]) -> PlanningScene:
    """Read a scene YAML file (see the module docstring for the layout).

    Raises:
        SceneError: naming the file and line of the first bad object.
    """
    path = Path(path)
    if not is_file(path):
        raise SceneError(f"scene file '{path}' not found", hint="give a path to a .yaml scene")
    text = _read_text(path)
    try:
        data = yaml.load(text, Loader=_LineLoader)  # noqa: S506 (SafeLoader subclass)
    except RecursionError:
        raise SceneError(
            "the YAML is nested too deeply", path=path, hint="a scene is a list of objects"
        ) from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else None
        problem = " ".join(str(getattr(exc, "problem", None) or exc).split())
        raise SceneError(f"not valid YAML: {problem}", path=path, line=line) from None
    if data is None:
        return PlanningScene(source=path)
    if isinstance(data, dict):
        if "objects" not in data:
            raise SceneError(
                "expected a list of objects or a mapping with 'objects'",
                path=path,
                line=data["__line__"],
            )
        data = data["objects"] or []
    if not isinstance(data, list):
        raise SceneError("expected a list of objects", path=path, line=1)
    if len(data) > MAX_SCENE_OBJECTS:
        raise SceneError(
            f"the scene lists {len(data):,} objects; at most {MAX_SCENE_OBJECTS}",
            path=path,
            hint="merge obstacles into larger boxes or meshes; see 'Limits on input' in the README",
        )
    scene = PlanningScene(source=path)
    for item in data:
        line = item.get("__line__") if isinstance(item, dict) else None
        try:
            scene.add(_object_from_dict(item, path.parent))
        except SceneError as exc:
            raise SceneError(exc.message, path=path, line=line, hint=exc.hint) from None
        except (TypeError, ValueError) as exc:
            name = item.get("name", "?") if isinstance(item, dict) else "?"
            raise SceneError(f"object '{name}': {exc}", path=path, line=line) from None
    return scene


def _read_text(path: Path) -> str:
    """The scene file's text: a regular file of at most :data:`MAX_SCENE_BYTES`, UTF-8."""
    from workbench.model.limits import check_input_file

    try:
        check_input_file(path, "scene file", MAX_SCENE_BYTES)
        data = path.read_bytes()
    except ModelError as error:  # the size check's: said as a scene error
        raise SceneError(error.message, path=path, hint=error.hint) from None
    except OSError as error:
        raise SceneError(f"cannot read the scene: {error.strerror}", path=path) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise SceneError(
            "the file is not UTF-8 text", path=path, hint="a scene is a YAML file"
        ) from None


def _object_from_dict(item: Any, base_dir: Path) -> SceneObject:
    if not isinstance(item, dict):
        raise SceneError(f"each object must be a mapping with name and type, got {_shown(item)}")
    item = {k: v for k, v in item.items() if k != "__line__"}
    name = item.pop("name", None)
    if not isinstance(name, str) or not name:
        raise SceneError("an object has no 'name'")
    kind = item.pop("type", None)
    if kind not in SIZE_FIELDS:
        raise SceneError(
            f"object '{name}' has unknown type '{kind}'",
            hint=f"use one of {', '.join(SIZE_FIELDS)}",
        )
    missing = [f for f in SIZE_FIELDS[kind] if f not in item]
    if missing:
        raise SceneError(f"{kind} '{name}' needs the field(s) {', '.join(missing)}")
    pose = item.pop("pose", {}) or {}
    if not isinstance(pose, dict):
        raise SceneError(f"object '{name}': 'pose' must be a mapping with xyz and rpy")
    pose = {k: v for k, v in pose.items() if k != "__line__"}
    unknown_pose = set(pose) - {"xyz", "rpy"}
    if unknown_pose:
        raise SceneError(
            f"object '{name}': unknown pose field(s) {sorted(unknown_pose)}", hint="use xyz and rpy"
        )
    obj = SceneObject(
        name, kind, xyz=_vec(pose.get("xyz", (0, 0, 0))), rpy=_vec(pose.get("rpy", (0, 0, 0)))
    )
    allowed = set(SIZE_FIELDS[kind]) | ({"scale"} if kind == "mesh" else set())
    unknown = set(item) - allowed
    if unknown:
        raise SceneError(
            f"{kind} '{name}' has unknown field(s) {sorted(unknown)}",
            hint=f"a {kind} takes {', '.join(sorted(allowed))} and pose",
        )
    if kind == "box":
        obj.size = _vec(item["size"])
    if kind in ("sphere", "cylinder"):
        obj.radius = _number(item["radius"], "radius")
    if kind == "cylinder":
        obj.length = _number(item["length"], "length")
    if kind == "mesh":
        if not isinstance(item["filename"], str) or not item["filename"]:
            raise SceneError(f"mesh '{name}': filename must be a file name")
        filename = Path(item["filename"])
        obj.filename = filename if filename.is_absolute() else base_dir / filename
        obj.scale = _number(item.get("scale", 1.0), "scale")
    return obj


def check_scene_mesh(name: str, path: Path) -> None:
    """Check that Drake can build a convex hull of the mesh ``path``: format, size, 3D points.

    Raises:
        SceneError: Another format, not a regular file or too big, unreadable, or fewer
            than four points that span a volume.
    """
    from workbench.model.limits import MAX_MESH_BYTES, check_input_file

    suffix = path.suffix.lower()
    if suffix not in SCENE_MESH_FORMATS:
        raise SceneError(
            f"mesh '{name}': {path} is not a mesh Drake can use here ('{suffix or path.name}')",
            hint="use " + ", ".join(SCENE_MESH_FORMATS),
        )
    try:
        check_input_file(path, "mesh", MAX_MESH_BYTES)
    except ModelError as error:  # said as a scene error
        raise SceneError(f"mesh '{name}': {error.message}", hint=error.hint) from None
    if suffix == ".vtk":
        return  # Drake reads VTK itself; trimesh cannot
    try:
        import trimesh

        mesh: Any = trimesh.load(str(path), force="mesh")
        points = np.asarray(mesh.vertices, dtype=float).reshape(-1, 3)
    except Exception as error:  # trimesh raises many kinds; all mean "cannot read it"
        raise SceneError(f"mesh '{name}': cannot read {path}: {error}") from None
    spread = points - points.mean(axis=0) if len(points) else points
    if len(points) < 4 or np.linalg.matrix_rank(spread, tol=1e-9) < 3:
        raise SceneError(
            f"mesh '{name}': {path} has no volume ({len(points)} points"
            + (")" if len(points) < 4 else ", all in one plane)"),
            hint="is it really a mesh? give an OBJ or glTF with a closed surface",
        )
