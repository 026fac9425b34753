"""A mesh that cannot be read gets workbench's one line; the converters stay silent.

trimesh and pycollada (which ``workbench.model.meshes`` converts STL and DAE with)
log tracebacks for textures they cannot find and raise multi-line errors for
damaged files. The CLI runs here in real processes, so whatever they print to
stderr or through logging would show: for each damaged mesh, ``show`` prints only
its one ``workbench show: error:`` line naming the file, line and mesh, and
``check`` only its finding; a DAE that converts despite missing textures prints
nothing of the converters at all.
"""

from __future__ import annotations

import struct
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROBOT = """<?xml version="1.0"?>
<robot name="meshy">
  <link name="base"/>
  <link name="finger">
    <inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    <visual>
      <geometry><mesh filename="{mesh}"/></geometry>
    </visual>
    <collision>
      <geometry><mesh filename="{mesh}"/></geometry>
    </collision>
  </link>
  <joint name="knuckle" type="revolute">
    <parent link="base"/><child link="finger"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>
"""
MESH_LINE = 7  # the <mesh> of the visual

TRIANGLE = "0 0 0 0.01 0 0 0 0.01 0"


def _dae(effect: str, images: str) -> str:
    """A one-triangle COLLADA file in the shape exporters write (effect, images, geometry)."""
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_images>{images}</library_images>
  <library_effects><effect id="skin"><profile_COMMON>{effect}</profile_COMMON></effect></library_effects>
  <library_materials><material id="skin-material"><instance_effect url="#skin"/></material></library_materials>
  <library_geometries><geometry id="tri"><mesh>
    <source id="tri-pos"><float_array id="tri-pos-array" count="9">{TRIANGLE}</float_array>
      <technique_common><accessor source="#tri-pos-array" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
    <triangles material="skin" count="1"><input semantic="VERTEX" source="#tri-vtx" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="finger">
    <instance_geometry url="#tri"><bind_material><technique_common>
      <instance_material symbol="skin" target="#skin-material"/>
    </technique_common></bind_material></instance_geometry>
  </node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
"""


def _sampler(name: str) -> str:
    return (
        f'<newparam sid="{name}-surface"><surface type="2D"><init_from>{name}</init_from>'
        f'</surface></newparam><newparam sid="{name}-sampler"><sampler2D>'
        f"<source>{name}-surface</source></sampler2D></newparam>"
    )


#: Colour, emission and bump textures whose images are missing, as in many DAE exports.
TEXTURED = _dae(
    _sampler("color")
    + _sampler("normals")
    + '<technique sid="common"><lambert>'
    + '<emission><texture texture="color-sampler" texcoord="TEX0"/></emission>'
    + '<diffuse><texture texture="color-sampler" texcoord="TEX0"/></diffuse></lambert>'
    + '<extra><technique profile="OpenCOLLADAMaya"><bump>'
    + '<texture texture="normals-sampler" texcoord="TEX1"/></bump></technique></extra>'
    + "</technique>",
    '<image id="color"><init_from>finger_color.png</init_from></image>'
    '<image id="normals"><init_from>finger_normals.png</init_from></image>',
)


def _binary_stl_truncated() -> bytes:
    """A binary STL whose header promises 1000 triangles and holds two bytes of one."""
    return b"meshy binary stl".ljust(80, b" ") + struct.pack("<I", 1000) + b"\x01\x02"


DAMAGED = {
    "truncated.dae": TEXTURED[: len(TEXTURED) // 2],
    "not_xml.dae": "solid finger\n  facet normal 0 0 1\n",
    "truncated.stl": _binary_stl_truncated(),
    "no_triangles.stl": "solid finger\n  facet normal 0 0 nan\n    outer loop\nendsolid finger\n",
    "bad_faces.obj": "v 0 0 0\nv 0.01 0 0\nf 1 2 7\nf x y z\n",
}


def _write(folder: Path, name: str, content: str | bytes) -> Path:
    mesh = folder / name
    if isinstance(content, bytes):
        mesh.write_bytes(content)
    else:
        mesh.write_text(content)
    robot = folder / f"{mesh.stem}_{mesh.suffix[1:]}.urdf"
    robot.write_text(ROBOT.format(mesh=name))
    return robot


@pytest.fixture
def quiet_env(tmp_path) -> dict[str, str]:
    """A cache of its own, so every run converts (and would print) afresh."""
    return {"WORKBENCH_CACHE_DIR": str(tmp_path / "cache"), "WORKBENCH_PACKAGE_PATH": ""}


@pytest.mark.parametrize("name", sorted(DAMAGED))
def test_a_damaged_mesh_gets_one_line(run_cli, tmp_path, quiet_env, name):
    robot = _write(tmp_path, name, DAMAGED[name])
    show = run_cli("show", robot, "--html", tmp_path / "out.html", env=quiet_env, timeout=300)
    assert show.returncode == 1, show.stderr
    lines = show.stderr.splitlines()
    assert len(lines) == 1, show.stderr
    assert lines[0].startswith(f"workbench show: error: {robot}:{MESH_LINE}: "), lines[0]
    assert str(tmp_path / name) in lines[0]
    assert not (tmp_path / "out.html").exists()

    check = run_cli("check", robot, env=quiet_env, timeout=300)
    assert check.returncode == 1
    assert check.stderr == ""  # urdfdom has nothing to say about a valid URDF; nor has trimesh
    errors = [line for line in check.stdout.splitlines() if ": error: " in line]
    assert len(errors) == 1, check.stdout
    assert errors[0].startswith(f"{robot}:{MESH_LINE}: error: link 'finger': ")
    assert str(tmp_path / name) in errors[0]


def test_missing_textures_convert_without_a_word(run_cli, tmp_path, quiet_env):
    robot = _write(tmp_path, "textured.dae", TEXTURED)
    check = run_cli("check", robot, env=quiet_env, timeout=300)
    assert check.returncode == 0, check.stdout + check.stderr
    assert check.stderr == ""
    assert "workbench found no problems" in check.stdout
    show = run_cli("show", robot, "--html", tmp_path / "out.html", env=quiet_env, timeout=300)
    assert show.returncode == 0, show.stderr
    assert (tmp_path / "out.html").is_file()
    noise = [line for line in show.stderr.splitlines() if "Meshcat listening" not in line]
    assert noise == []
