"""Gazebo model folders and mesh files written for the tests, in the shapes of the real ones.

A model folder is ``NAME/model.config`` (``<sdf version>`` entries naming the model
files) beside ``model.sdf`` and ``meshes/``, as in osrf/gazebo_models and
turtlebot3_gazebo/models; a mesh-only folder (turtlebot3_common_meshes) has no
model.config. Meshes are written as COLLADA (with ``<unit meter>`` and ``<up_axis>``
as SketchUp writes them), binary and ASCII STL, and OBJ.
"""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np


def model_folder(
    root: Path, name: str, sdf: str, *, versions: dict[str, str] | None = None
) -> Path:
    """Write ``root/name/model.config`` and ``model.sdf`` (``versions``: more ``<sdf>`` entries)."""
    folder = root / name
    folder.mkdir(parents=True, exist_ok=True)
    entries = (
        "".join(f'  <sdf version="{v}">{f}</sdf>\n' for v, f in (versions or {}).items())
        or '  <sdf version="1.6">model.sdf</sdf>\n'
    )
    (folder / "model.config").write_text(
        f'<?xml version="1.0"?>\n<model>\n  <name>{name}</name>\n  <version>1.0</version>\n'
        f"{entries}  <author><name>test</name></author>\n"
        "  <description>written for a test</description>\n</model>\n"
    )
    if sdf:
        (folder / "model.sdf").write_text(sdf)
    return folder


def prism(outline: np.ndarray, height: float) -> tuple[np.ndarray, np.ndarray]:
    """A closed, outward-wound prism over a counter-clockwise convex ``outline`` (n, 2)."""
    n = len(outline)
    bottom = np.column_stack([outline, np.zeros(n)])
    top = np.column_stack([outline, np.full(n, height)])
    vertices = np.vstack([bottom, top])
    faces = []
    for i in range(1, n - 1):
        faces.append([0, i + 1, i])  # bottom, facing down
        faces.append([n, n + i, n + i + 1])  # top, facing up
    for i in range(n):
        j = (i + 1) % n
        faces += [[i, j, n + j], [i, n + j, n + i]]
    return vertices, np.array(faces)


def square_ring(inner: float, outer: float, height: float) -> tuple[np.ndarray, np.ndarray]:
    """A closed square wall round the origin: inner and outer half sizes, from z = 0 up (concave)."""
    rings = [np.array([[-h, -h], [h, -h], [h, h], [-h, h]], dtype=float) for h in (outer, inner)]
    vertices = np.vstack(
        [np.column_stack([r, np.full(4, z)]) for z in (0.0, height) for r in rings]
    )  # 0-3 outer bottom, 4-7 inner bottom, 8-11 outer top, 12-15 inner top
    faces = []
    for i in range(4):
        j = (i + 1) % 4
        ob, ib, ot, it = i, 4 + i, 8 + i, 12 + i
        ob2, ib2, ot2, it2 = j, 4 + j, 8 + j, 12 + j
        faces += [[ob, ob2, ot2], [ob, ot2, ot]]  # outer face, facing out
        faces += [[ib, it2, ib2], [ib, it, it2]]  # inner face, facing in (towards the origin)
        faces += [[ot, ot2, it2], [ot, it2, it]]  # top
        faces += [[ob, ib2, ob2], [ob, ib, ib2]]  # bottom
    return vertices, np.array(faces)


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray) -> Path:
    lines = [f"v {x:.9g} {y:.9g} {z:.9g}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("# written for a test\n" + "\n".join(lines) + "\n")
    return path


def write_stl(path: Path, vertices: np.ndarray, faces: np.ndarray, *, binary: bool = True) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    triangles = vertices[faces]
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    if binary:
        data = bytearray(b"written for a test".ljust(80, b" "))
        data += struct.pack("<I", len(faces))
        for normal, triangle in zip(normals, triangles, strict=True):
            data += struct.pack("<12fH", *normal, *triangle.ravel(), 0)
        path.write_bytes(bytes(data))
        return path
    lines = ["solid test"]
    for normal, triangle in zip(normals, triangles, strict=True):
        lines.append(f"  facet normal {normal[0]:.6g} {normal[1]:.6g} {normal[2]:.6g}")
        lines.append("    outer loop")
        lines += [f"      vertex {x:.9g} {y:.9g} {z:.9g}" for x, y, z in triangle]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid test")
    path.write_text("\n".join(lines) + "\n")
    return path


def write_dae(
    path: Path,
    vertices: np.ndarray,
    faces: np.ndarray,
    *,
    meter: float = 1.0,
    unit: str = "meter",
    up_axis: str = "Z_UP",
    image_without_file: bool = False,
) -> Path:
    """A COLLADA 1.4.1 file with one triangle mesh, in the given unit (vertices in that unit);
    ``image_without_file``: with an ``<image>`` that names no file, as 3ds Max's OpenCOLLADA
    exporter writes (gazebo_models' arm_part)."""
    positions = " ".join(f"{v:.9g}" for v in vertices.ravel())
    indices = " ".join(str(i) for i in faces.ravel())
    text = f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>
    <contributor><authoring_tool>a test</authoring_tool></contributor>
    <unit name="{unit}" meter="{meter}"/>
    <up_axis>{up_axis}</up_axis>
  </asset>{{images}}
  <library_geometries>
    <geometry id="ID2" name="shape">
      <mesh>
        <source id="ID3">
          <float_array id="ID4" count="{vertices.size}">{positions}</float_array>
          <technique_common>
            <accessor count="{len(vertices)}" source="#ID4" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="ID5"><input semantic="POSITION" source="#ID3"/></vertices>
        <triangles count="{len(faces)}">
          <input offset="0" semantic="VERTEX" source="#ID5"/>
          <p>{indices}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="ID1">
      <node name="SketchUp">
        <instance_geometry url="#ID2"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#ID1"/></scene>
</COLLADA>
"""
    if image_without_file:  # a textured material whose image names no file
        text = text.replace("{images}", _TEXTURED_MATERIAL)
        text = text.replace("<triangles ", '<triangles material="paint" ')
        text = text.replace(
            '<instance_geometry url="#ID2"/>',
            '<instance_geometry url="#ID2"><bind_material><technique_common>'
            '<instance_material symbol="paint" target="#paint-material"/>'
            "</technique_common></bind_material></instance_geometry>",
        )
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text.replace("{images}", ""))
    return path


_TEXTURED_MATERIAL = """
  <library_effects>
    <effect id="paint-effect"><profile_COMMON>
      <newparam sid="tray-surface"><surface type="2D"><init_from>TrayParts_png</init_from></surface></newparam>
      <newparam sid="tray-sampler"><sampler2D><source>tray-surface</source></sampler2D></newparam>
      <technique sid="common"><blinn><diffuse><texture texture="tray-sampler" texcoord="CHANNEL1"/></diffuse></blinn></technique>
    </profile_COMMON></effect>
  </library_effects>
  <library_materials>
    <material id="paint-material" name="paint"><instance_effect url="#paint-effect"/></material>
  </library_materials>
  <library_images>
    <image id="TrayParts_png">
      <!--<init_from>trayParts.png</init_from>-->
    </image>
  </library_images>"""
