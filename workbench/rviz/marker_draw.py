"""Drawing one ``visualization_msgs/Marker`` in Meshcat, as RViz draws it.

The marker goes under ``path``; the caller sets ``path``'s transform (the
marker's pose in the fixed frame). Shapes are unit shapes scaled by
``marker.scale`` (CUBE, SPHERE and CYLINDER as RViz: scale is the full size);
ARROW by pose (shaft 77 % of ``scale.x``, shaft diameter ``scale.y``, head
diameter ``scale.z``) or by two points (shaft diameter ``scale.x``, head
diameter ``scale.y``, head length ``scale.z``); LINE_STRIP/LINE_LIST as line
segments (one set per distinct colour; Meshcat draws lines one pixel wide);
POINTS as a point cloud of ``scale.x``; CUBE_LIST and SPHERE_LIST as one
coloured triangle mesh; TRIANGLE_LIST with per-vertex or per-triangle colours;
MESH_RESOURCE from ``package://``, ``file://`` or a path (STL/DAE/PLY converted
to OBJ). Meshcat has no text: TEXT_VIEW_FACING is drawn as a small sphere at
the text's position and says so in its status.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from workbench.rviz import marker_check as mc

#: Arrows by pose: RViz's proportions (shaft length 77 % of the arrow).
SHAFT_FRACTION = 0.77
#: Points beyond this are drawn decimated (every k-th), with a warning.
MAX_POINTS = 200_000


def rgba(color: Any) -> Any:
    from pydrake.geometry import Rgba

    return Rgba(float(color.r), float(color.g), float(color.b), float(color.a))


def points_array(points: Any) -> np.ndarray:
    """The (3, N) array of ``geometry_msgs/Point``s."""
    if not points:
        return np.zeros((3, 0))
    return np.array([[p.x, p.y, p.z] for p in points], dtype=float).T


def colors_array(colors: Any) -> np.ndarray:
    """The (4, N) array of ``std_msgs/ColorRGBA``s."""
    return np.array([[c.r, c.g, c.b, c.a] for c in colors], dtype=float).T


def draw_marker(
    meshcat: Any, path: str, marker: Any, resolve_mesh: Callable[[str], Path] | None = None
) -> str | None:
    """Draw ``marker`` under ``path`` (replacing what was there); returns a status note or None."""
    meshcat.Delete(f"{path}/geometry")
    geometry = f"{path}/geometry"
    kind = marker.type
    s = marker.scale
    if kind in (mc.CUBE, mc.SPHERE, mc.CYLINDER):
        from pydrake.geometry import Box, Cylinder, Sphere

        shape = {
            mc.CUBE: Box(1.0, 1.0, 1.0),
            mc.SPHERE: Sphere(0.5),
            mc.CYLINDER: Cylinder(0.5, 1.0),
        }
        meshcat.SetObject(geometry, shape[kind], rgba(marker.color))
        meshcat.SetProperty(geometry, "scale", [abs(float(s.x)), abs(float(s.y)), abs(float(s.z))])
        return None
    if kind == mc.ARROW:
        return _arrow(meshcat, geometry, marker)
    if kind in (mc.LINE_STRIP, mc.LINE_LIST):
        return _lines(meshcat, geometry, marker)
    if kind == mc.POINTS:
        return _points(meshcat, geometry, marker)
    if kind in (mc.CUBE_LIST, mc.SPHERE_LIST):
        return _solid_list(meshcat, geometry, marker)
    if kind == mc.TRIANGLE_LIST:
        return _triangles(meshcat, geometry, marker)
    if kind == mc.MESH_RESOURCE:
        return _mesh(meshcat, geometry, marker, resolve_mesh)
    if kind == mc.TEXT_VIEW_FACING:
        from pydrake.geometry import Sphere

        meshcat.SetObject(geometry, Sphere(max(float(s.z), 1e-3) * 0.3), rgba(marker.color))
        return f"text '{marker.text}' shown as a dot: the browser view draws no text"
    return f"Unknown marker type: {kind}."


def _arrow(meshcat: Any, path: str, marker: Any) -> str | None:
    from pydrake.geometry import Cylinder, MeshcatCone

    s = marker.scale
    if len(marker.points) == 2:
        p0, p1 = points_array(marker.points).T
        direction = p1 - p0
        length = float(np.linalg.norm(direction))
        if length < 1e-9:
            return "arrow points coincide: nothing to draw"
        head_length = float(s.z) if s.z > 0 else 0.23 * length
        head_length = min(head_length, length)
        shaft_d, head_d = float(s.x), float(s.y)
        R = _rotation_x_to(direction / length)
        start = p0
    else:
        length = float(s.x)
        head_length = (1.0 - SHAFT_FRACTION) * length
        shaft_d, head_d = float(s.y), float(s.z)
        R = np.eye(3)
        start = np.zeros(3)
    shaft = max(length - head_length, 0.0)
    colour = rgba(marker.color)
    x = R[:, 0]
    # a cylinder's axis is its z: turn z onto the arrow's x
    R_z_to_x = R @ np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])
    if shaft > 0:
        meshcat.SetObject(f"{path}/shaft", Cylinder(max(shaft_d, 1e-4) / 2, shaft), colour)
        meshcat.SetTransform(f"{path}/shaft", _transform(R_z_to_x, start + x * shaft / 2))
    radius = max(head_d, 1e-4) / 2
    # MeshcatCone's apex is at its origin and it opens along its +z: turn +z onto -x
    R_z_to_minus_x = R @ np.array([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    meshcat.SetObject(f"{path}/head", MeshcatCone(head_length, radius, radius), colour)
    meshcat.SetTransform(f"{path}/head", _transform(R_z_to_minus_x, start + x * length))
    return None


def _lines(meshcat: Any, path: str, marker: Any) -> str | None:
    pts = points_array(marker.points)
    if marker.type == mc.LINE_STRIP:
        starts, ends = pts[:, :-1], pts[:, 1:]
        seg_colors = colors_array(marker.colors)[:, :-1] if marker.colors else None
    else:
        starts, ends = pts[:, 0::2], pts[:, 1::2]
        seg_colors = colors_array(marker.colors)[:, 0::2] if marker.colors else None
    width = max(float(marker.scale.x) * 100.0, 1.0)  # Meshcat widths are pixels
    if seg_colors is None:
        meshcat.SetLineSegments(f"{path}/lines", starts, ends, width, rgba(marker.color))
        return None
    from pydrake.geometry import Rgba

    keys = [tuple(np.round(seg_colors[:, i], 3)) for i in range(seg_colors.shape[1])]
    for index, colour in enumerate(sorted(set(keys))):
        chosen = [i for i, k in enumerate(keys) if k == colour]
        meshcat.SetLineSegments(
            f"{path}/lines_{index}",
            np.ascontiguousarray(starts[:, chosen]),
            np.ascontiguousarray(ends[:, chosen]),
            width,
            Rgba(*colour),
        )
    return None


def _points(meshcat: Any, path: str, marker: Any) -> str | None:
    from pydrake.perception import BaseField, Fields, PointCloud

    pts = points_array(marker.points)
    note = None
    step = 1
    if pts.shape[1] > MAX_POINTS:
        step = int(np.ceil(pts.shape[1] / MAX_POINTS))
        note = f"{pts.shape[1]} points drawn decimated (every {step}th)"
    pts = pts[:, ::step]
    if marker.colors:
        cloud = PointCloud(pts.shape[1], Fields(BaseField.kXYZs | BaseField.kRGBs))  # type: ignore[arg-type]
        colours = colors_array(marker.colors)[:3, ::step]
        cloud.mutable_rgbs()[:] = np.clip(colours * 255.0, 0, 255).astype(np.uint8)
    else:
        cloud = PointCloud(pts.shape[1], Fields(BaseField.kXYZs))  # type: ignore[arg-type]
    cloud.mutable_xyzs()[:] = pts.astype(np.float32)
    meshcat.SetObject(f"{path}/points", cloud, max(float(marker.scale.x), 1e-4), rgba(marker.color))
    return note


_CUBE_VERTICES = np.array(
    [[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)], dtype=float
).T
_CUBE_FACES = np.array(
    [
        [0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
        [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3],
    ],
    dtype=np.int32,
).T  # fmt: skip


def _midpoint(vertices: list[np.ndarray], cache: dict[tuple[int, int], int], a: int, b: int) -> int:
    key = (min(a, b), max(a, b))
    if key not in cache:
        v = vertices[a] + vertices[b]
        vertices.append(v / np.linalg.norm(v))
        cache[key] = len(vertices) - 1
    return cache[key]


def _octahedron_sphere() -> tuple[np.ndarray, np.ndarray]:
    """A twice subdivided octahedron: a 0.5-radius sphere of 66 vertices."""
    vertices = [
        np.array(v, float)
        for v in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1))
    ]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(2):
        cache: dict[tuple[int, int], int] = {}
        new_faces = []
        for a, b, c in faces:
            ab = _midpoint(vertices, cache, a, b)
            bc = _midpoint(vertices, cache, b, c)
            ca = _midpoint(vertices, cache, c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return 0.5 * np.array(vertices).T, np.array(faces, dtype=np.int32).T


_SPHERE_VERTICES, _SPHERE_FACES = _octahedron_sphere()


def _solid_list(meshcat: Any, path: str, marker: Any) -> str | None:
    pts = points_array(marker.points)
    n = pts.shape[1]
    base_v, base_f = (
        (_CUBE_VERTICES, _CUBE_FACES)
        if marker.type == mc.CUBE_LIST
        else (_SPHERE_VERTICES, _SPHERE_FACES)
    )
    scale = np.array([marker.scale.x, marker.scale.y, marker.scale.z], float)[:, None]
    nv = base_v.shape[1]
    vertices = (base_v * scale)[:, None, :] + pts[:, :, None]  # (3, n, nv)
    faces = base_f[:, None, :] + (np.arange(n, dtype=np.int32) * nv)[None, :, None]
    if marker.colors:
        per_point = colors_array(marker.colors)[:3]
    else:
        c = marker.color
        per_point = np.tile(np.array([[c.r], [c.g], [c.b]], float), (1, n))
    colors = np.repeat(per_point[:, :, None], nv, axis=2)
    meshcat.SetTriangleColorMesh(
        f"{path}/solids",
        np.asfortranarray(vertices.reshape(3, -1)),
        np.asfortranarray(faces.reshape(3, -1)),
        np.asfortranarray(colors.reshape(3, -1)),
    )
    return None


def _triangles(meshcat: Any, path: str, marker: Any) -> str | None:
    pts = points_array(marker.points) * np.array(
        [[marker.scale.x], [marker.scale.y], [marker.scale.z]]
    )
    faces = np.arange(pts.shape[1], dtype=np.int32).reshape(-1, 3).T
    if marker.colors:
        colours = colors_array(marker.colors)[:3]
        if colours.shape[1] * 3 == pts.shape[1]:  # one colour per triangle
            colours = np.repeat(colours, 3, axis=1)
        meshcat.SetTriangleColorMesh(
            f"{path}/triangles",
            np.asfortranarray(pts),
            np.asfortranarray(faces),
            np.asfortranarray(colours),
        )
    else:
        meshcat.SetTriangleMesh(
            f"{path}/triangles",
            np.asfortranarray(pts),
            np.asfortranarray(faces),
            rgba(marker.color),
        )
    return None


def _mesh(
    meshcat: Any, path: str, marker: Any, resolve_mesh: Callable[[str], Path] | None
) -> str | None:
    from pydrake.geometry import Mesh

    if resolve_mesh is None:
        return "no mesh resolver"
    try:
        file = resolve_mesh(marker.mesh_resource)
    except Exception as error:  # noqa: BLE001 - a missing mesh is the marker's status
        return f"cannot load mesh {marker.mesh_resource}: {error}"
    colour = rgba(marker.color)
    meshcat.SetObject(f"{path}/mesh", Mesh(str(file)), colour)  # type: ignore[call-overload]
    meshcat.SetProperty(
        f"{path}/mesh",
        "scale",
        [float(marker.scale.x), float(marker.scale.y), float(marker.scale.z)],
    )
    return None


def _rotation_x_to(direction: np.ndarray) -> np.ndarray:
    """A rotation whose x axis is ``direction`` (a unit vector)."""
    x = direction
    helper = np.array([0.0, 0.0, 1.0]) if abs(x[2]) < 0.9 else np.array([0.0, 1.0, 0.0])
    y = np.cross(helper, x)
    y /= np.linalg.norm(y)
    z = np.cross(x, y)
    return np.column_stack([x, y, z])


def _transform(R: np.ndarray, p: np.ndarray) -> Any:
    from pydrake.math import RigidTransform, RotationMatrix

    return RigidTransform(RotationMatrix(R), np.asarray(p, dtype=float))  # type: ignore[arg-type]
