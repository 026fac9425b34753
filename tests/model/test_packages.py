"""package:// resolution, mesh conversion, xacro and SDF sources."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from workbench.errors import ModelError
from workbench.model import load_robot
from workbench.model.meshes import prepare_mesh
from workbench.model.packages import PackageResolver

FINGER = Path(__file__).resolve().parents[2] / "urdf" / "meshes" / "l_finger.obj"

ROBOT_WITH_MESH = """<?xml version="1.0"?>
<robot name="gripper">
  <link name="base_link">
    <visual>
      <geometry><mesh filename="{uri}"/></geometry>
    </visual>
  </link>
</robot>
"""


def _package(root: Path, name: str) -> Path:
    directory = root / name
    (directory / "meshes").mkdir(parents=True)
    (directory / "package.xml").write_text(
        f'<?xml version="1.0"?><package format="2"><name>{name}</name></package>'
    )
    return directory


@pytest.fixture(autouse=True)
def _isolated(monkeypatch, tmp_path):
    monkeypatch.delenv("WORKBENCH_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))


def test_checkout_package_resolves():
    resolver = PackageResolver(None)
    assert resolver.resolve("package://workbench_urdf/meshes/l_finger.obj", None) == FINGER


def test_own_package_xml_upwards(tmp_path):
    package = _package(tmp_path, "my_bot")
    shutil.copy(FINGER, package / "meshes" / "finger.obj")
    (package / "urdf").mkdir()
    model = package / "urdf" / "gripper.urdf"
    model.write_text(ROBOT_WITH_MESH.format(uri="package://my_bot/meshes/finger.obj"))
    robot = load_robot(model)
    assert robot.links[0].has_visual


@pytest.mark.parametrize("variable", ["WORKBENCH_PACKAGE_PATH", "ROS_PACKAGE_PATH"])
def test_search_path_variables(tmp_path, monkeypatch, variable):
    workspace = tmp_path / "ws" / "src"
    package = _package(workspace, "lab_meshes")
    shutil.copy(FINGER, package / "meshes" / "finger.obj")
    model = tmp_path / "gripper.urdf"
    model.write_text(ROBOT_WITH_MESH.format(uri="package://lab_meshes/meshes/finger.obj"))
    with pytest.raises(ModelError, match="unknown package 'lab_meshes'"):
        load_robot(model)
    monkeypatch.setenv(variable, str(tmp_path / "ws"))
    assert load_robot(model).name == "gripper"


def test_stl_is_converted_to_obj_once(tmp_path):
    import trimesh

    stl = tmp_path / "cube.stl"
    trimesh.creation.box(extents=(0.1, 0.2, 0.3)).export(str(stl))
    converted = prepare_mesh(stl)
    assert converted.suffix == ".obj" and converted.parent == tmp_path / "cache" / "meshes"
    mesh = trimesh.load(str(converted), force="mesh")
    assert mesh.extents == pytest.approx([0.1, 0.2, 0.3])
    assert prepare_mesh(stl) == converted
    model = tmp_path / "cube.urdf"
    model.write_text(ROBOT_WITH_MESH.format(uri="cube.stl"))
    assert load_robot(model).links[0].has_visual


def test_unreadable_dae_is_reported_clearly(tmp_path):
    dae = tmp_path / "finger.dae"
    dae.write_text("<COLLADA>broken</COLLADA>")
    with pytest.raises(ModelError) as info:
        prepare_mesh(dae, where=tmp_path / "robot.urdf", line=7)
    message = info.value.one_line()
    assert message.startswith(f"{tmp_path / 'robot.urdf'}:7: cannot convert mesh")
    assert ".obj" in message


def test_sdf_model_loads(tmp_path):
    sdf = tmp_path / "pendulum.sdf"
    sdf.write_text("""<?xml version="1.0"?>
<sdf version="1.7">
  <model name="pendulum">
    <link name="base"/>
    <link name="arm">
      <inertial><mass>1.0</mass>
        <inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.001</izz>
          <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
      <visual name="v"><geometry><box><size>0.05 0.05 0.5</size></box></geometry></visual>
    </link>
    <joint name="pivot" type="revolute">
      <parent>base</parent><child>arm</child>
      <axis><xyz>0 1 0</xyz><limit><lower>-1</lower><upper>1</upper></limit></axis>
    </joint>
  </model>
</sdf>
""")
    robot = load_robot(sdf)
    assert robot.name == "pendulum" and robot.root_link == "base"
    from workbench.model import check_robot

    report = check_robot(sdf)
    assert report.ok and report.tree_lines[2:] == [
        "root Link: base has 1 child(ren)",
        "    child(1):  arm",
    ]
    assert robot.joint_names == ["pivot"]
    assert robot.joint("pivot").type == "revolute"
    assert robot.upper_limits[0] == pytest.approx(1.0)


def test_xacro_arguments(tmp_path):
    source = tmp_path / "box.urdf.xacro"
    source.write_text("""<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="box">
  <xacro:arg name="size" default="0.5"/>
  <link name="base_link">
    <visual><geometry><box size="$(arg size) 1 1"/></geometry></visual>
  </link>
</robot>
""")
    robot = load_robot(source, mappings={"size": "0.25"})
    assert robot.document.links[0].visuals[0].geometry.size == (0.25, 1.0, 1.0)
