"""Every robot in urdf/: checks as golden, graphs as golden, loads into Drake, draws every link."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench.model import load_robot
from workbench.model.check import check_robot
from workbench.model.graph import graph_source
from workbench.model.loader import load_document

REPO = Path(__file__).resolve().parents[2]
GOLDEN = REPO / "tests" / "data" / "urdf" / "golden"
MODELS = sorted(
    path.name
    for path in (REPO / "urdf").iterdir()
    if path.suffix == ".urdf" or path.name.endswith(".urdf.xacro")
)
EXPECTED_MODELS = {
    "myfirst.urdf",
    "multipleshapes.urdf",
    "origins.urdf",
    "materials.urdf",
    "visual.urdf",
    "flexible.urdf",
    "physics.urdf",
    "custom_bot.urdf",
    "robot_arm.urdf",
    "arm3.urdf",
    "simple_box.urdf",
    "table.urdf",
    "table.urdf.xacro",
    "spinning_top.urdf",
}


def _stem(name: str) -> str:
    stem = name.removesuffix(".xacro").removesuffix(".urdf")
    return stem + ".xacro" if name.endswith(".xacro") else stem


@pytest.fixture(autouse=True)
def _no_package_path(monkeypatch):
    monkeypatch.delenv("WORKBENCH_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)


def test_every_lab_model_is_there():
    assert set(MODELS) >= EXPECTED_MODELS
    assert (REPO / "urdf" / "package.xml").is_file()


@pytest.mark.parametrize("name", MODELS)
def test_check_report_matches_golden(name):
    report = check_robot(REPO / "urdf" / name)
    golden = (GOLDEN / f"{_stem(name)}.check.txt").read_text()
    assert report.format(f"urdf/{name}") == golden
    assert report.ok, report.format()
    assert report.loaded
    if name == "simple_box.urdf":
        # The manual's impossible inertia: ROS and Drake load it, so it is a warning.
        assert [finding.code for finding in report.warnings] == ["inertia-triangle-inequality"]


@pytest.mark.parametrize("name", MODELS)
def test_graph_matches_golden(name):
    assert (
        graph_source(load_document(REPO / "urdf" / name))
        == (GOLDEN / f"{_stem(name)}.gv").read_text()
    )


@pytest.mark.parametrize("name", MODELS)
def test_model_loads_and_its_snapshot_has_every_link(name, tmp_path):
    from workbench.viz import Viewer
    from workbench.viz.snapshot import snapshot_paths

    robot = load_robot(REPO / "urdf" / name)
    assert {link.name for link in robot.links} == set(robot.forward_kinematics())
    viewer = Viewer.instance()
    viewer.clear()
    prefix = viewer.show_robot(robot)
    paths = set(snapshot_paths(viewer.save_html(tmp_path / "scene.html")))
    viewer.clear()
    for link in robot.links:
        assert f"{prefix}/{link.name}" in paths
        if link.has_visual:
            assert f"{prefix}/{link.name}/visual_0" in paths


def test_movable_r2d2_has_the_manuals_joints():
    robot = load_robot("flexible")
    types = {joint.name: joint.type for joint in robot.movable_joints}
    assert types == {
        "right_front_wheel_joint": "continuous",
        "right_back_wheel_joint": "continuous",
        "left_front_wheel_joint": "continuous",
        "left_back_wheel_joint": "continuous",
        "gripper_extension": "prismatic",
        "left_gripper_joint": "revolute",
        "right_gripper_joint": "revolute",
        "head_swivel": "continuous",
    }
    index = robot.joint_names.index("gripper_extension")
    assert robot.lower_limits[index] == pytest.approx(-0.38)
    assert np.isinf(robot.upper_limits[robot.joint_names.index("head_swivel")])
    assert robot.materials["blue"] == (0.0, 0.0, 0.8, 1.0)


def test_physics_r2d2_has_collision_and_inertia_everywhere():
    robot = load_robot("physics")
    assert all(link.has_collision and link.mass and link.mass > 0 for link in robot.links)
    base = robot.document.link("base_link").inertial
    assert base.mass == 10
    np.testing.assert_allclose(np.diag(base.inertia), [0.4, 0.4, 0.2])


def test_custom_bot_keeps_its_gazebo_blocks():
    document = load_document("custom_bot")
    assert document.name == "gbj_bot"
    gazebo = document.root.findall("gazebo")
    assert len(gazebo) == 3
    plugins = [plugin.get("filename") for plugin in document.root.iter("plugin")]
    assert plugins == [
        "libgazebo_ros_diff_drive.so",
        "libgazebo_ros_joint_state_publisher.so",
        "libgazebo_ros_gpu_laser.so",
    ]
    sensor = document.root.find("gazebo[@reference='laser_scanner']/sensor")
    assert sensor.get("type") == "gpu_ray"
    assert sensor.findtext("ray/scan/horizontal/samples") == "720"


def test_table_urdf_is_the_expanded_xacro():
    expanded = load_document(REPO / "urdf" / "table.urdf.xacro")
    stored = load_document(REPO / "urdf" / "table.urdf")
    assert [link.name for link in expanded.links] == [link.name for link in stored.links]
    for ours, theirs in zip(expanded.joints, stored.joints, strict=True):
        assert ours.name == theirs.name
        np.testing.assert_allclose(ours.xyz, theirs.xyz)
    for ours, theirs in zip(expanded.links, stored.links, strict=True):
        np.testing.assert_allclose(ours.inertial.inertia, theirs.inertial.inertia)


def test_spinning_top_spins_freely():
    robot = load_robot("spinning_top", floating_base=True)
    assert robot.plant.num_positions() == 7
    inertia = robot.document.link("top").inertial.inertia
    assert inertia[2, 2] > inertia[0, 0]
