"""ModelBuilder: the model editor's steps written as SDF and URDF that Drake and `check` accept."""

from __future__ import annotations

import math
import runpy
import sys
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import ModelError
from workbench.model import ModelBuilder, check_robot, load_robot

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "examples" / "gazebo" / "build_two_wheeled_robot.py"


def _manual_robot() -> ModelBuilder:
    return runpy.run_path(str(SCRIPT))["build"]()


def test_the_shipped_two_wheeled_robot_is_what_the_script_writes_now(tmp_path, monkeypatch):
    out = tmp_path / "robot.sdf"
    monkeypatch.setattr(sys, "argv", [str(SCRIPT), str(out)])
    runpy.run_path(str(SCRIPT), run_name="__main__")
    assert out.read_text() == (REPO / "urdf" / "two_wheeled_robot.sdf").read_text()


def test_align_places_the_wheels_beside_the_chassis_and_the_caster_under_its_top():
    robot = _manual_robot()
    # chassis 2 x 1 x 0.15 at z 0.4; wheels r 0.3, 0.25 wide; caster r 0.2
    np.testing.assert_allclose(robot.link_pose("wheel_1")[:3], [0.7, 0.625, 0.4])
    np.testing.assert_allclose(robot.link_pose("wheel_2")[:3], [0.7, -0.625, 0.4])
    np.testing.assert_allclose(robot.link_pose("caster")[:3], [-0.8, 0.0, 0.275])
    mass, com, inertia = robot.inertial("wheel_1")
    assert mass == 2.0
    np.testing.assert_allclose(com, 0.0, atol=1e-12)
    # a cylinder about its own axis: m r^2 / 2; across it: m (3 r^2 + h^2) / 12
    np.testing.assert_allclose(np.diag(inertia), [0.0554166667, 0.0554166667, 0.09], rtol=1e-6)


@pytest.mark.parametrize("suffix", [".sdf", ".urdf"])
def test_both_formats_load_into_drake_with_the_right_masses_and_axes(tmp_path, suffix):
    path = _manual_robot().save(tmp_path / f"robot{suffix}")
    robot = load_robot(path, floating_base=True)
    plant = robot.plant
    context = plant.CreateDefaultContext()
    assert plant.CalcTotalMass(context) == pytest.approx(25.0)
    chassis = plant.GetBodyByName("chassis")
    for wheel in ("wheel_1", "wheel_2"):
        joint = plant.GetJointByName(f"{wheel}_joint")
        assert joint.type_name() == "revolute"
        # the wheel axis, in the world, is along y (rolled cylinders)
        X_WJ = joint.frame_on_child().CalcPoseInWorld(context)
        axis_W = X_WJ.rotation().multiply(joint.revolute_axis())
        assert abs(abs(axis_W[1]) - 1.0) < 1e-6, axis_W
    caster = plant.GetJointByName("caster_joint")
    assert caster.type_name() == ("ball_rpy" if suffix == ".sdf" else "weld")
    # URDF's root link frame is the model frame (the chassis's 0.4 m moved into its
    # geometry); the wheels sit at the chassis height in both formats.
    wheel = plant.GetBodyByName("wheel_1")
    np.testing.assert_allclose(
        plant.EvalBodyPoseInWorld(context, wheel).translation(), [0.7, 0.625, 0.4], atol=1e-9
    )
    shapes = plant.GetCollisionGeometriesForBody(chassis)
    inspector = robot.scene_graph.model_inspector() if robot.scene_graph is not None else None
    if inspector is not None:
        X_WC = plant.EvalBodyPoseInWorld(context, chassis).multiply(
            inspector.GetPoseInFrame(shapes[0])
        )
        assert X_WC.translation()[2] == pytest.approx(0.4)


def test_the_urdf_passes_check_and_makes_the_caster_frictionless(tmp_path):
    path = _manual_robot().save(tmp_path / "robot.urdf")
    report = check_robot(path)
    assert report.ok, report.format()
    text = path.read_text()
    assert '<gazebo reference="caster"><mu1>0</mu1><mu2>0</mu2></gazebo>' in text


def test_a_plugin_element_is_written_with_its_parameters(tmp_path):
    robot = _manual_robot()
    robot.add_plugin("push", "model_push.py", x=0.5, enabled=True)
    sdf = robot.to_sdf()
    assert '<plugin name="push" filename="model_push.py">' in sdf
    assert "<x>0.5</x>" in sdf and "<enabled>true</enabled>" in sdf
    urdf = robot.to_urdf()
    assert '<gazebo>\n    <plugin name="push" filename="model_push.py">' in urdf


def test_inertia_of_an_offset_shape_uses_the_parallel_axis_theorem():
    robot = ModelBuilder("two_balls")
    robot.add_link("dumbbell", mass=2.0)
    robot.add_sphere("dumbbell", 0.1, pose=(0.5, 0, 0))
    robot.add_sphere("dumbbell", 0.1, pose=(-0.5, 0, 0))
    mass, com, inertia = robot.inertial("dumbbell")
    np.testing.assert_allclose(com, 0.0, atol=1e-12)
    sphere = 2.0 / 5.0 * 1.0 * 0.01
    np.testing.assert_allclose(
        np.diag(inertia), [2 * sphere, 2 * (sphere + 0.25), 2 * (sphere + 0.25)]
    )


def test_bad_steps_are_one_line_errors_naming_the_element():
    robot = ModelBuilder("bot")
    robot.add_link("base")
    with pytest.raises(ModelError, match="link 'base' already exists"):
        robot.add_link("base")
    with pytest.raises(ModelError, match="mass must be a positive number"):
        robot.add_link("heavy", mass=0.0)
    with pytest.raises(ModelError, match="box sizes must be 3 positive numbers"):
        robot.add_box("base", (1.0, -1.0, 1.0))
    with pytest.raises(ModelError, match="has no link 'nope'"):
        robot.add_sphere("nope", 0.1)
    with pytest.raises(ModelError, match="pose must be"):
        robot.add_link("nan", pose=(math.nan, 0, 0))
    robot.add_link("wheel")
    with pytest.raises(ModelError, match="parent link 'ghost' does not exist"):
        robot.add_joint("j", "revolute", "ghost", "wheel")
    with pytest.raises(ModelError, match="unknown type 'hinge'"):
        robot.add_joint("j", "hinge", "base", "wheel")
    with pytest.raises(ModelError, match="lower limit 1 is above upper limit -1"):
        robot.add_joint("j", "revolute", "base", "wheel", limits=(1.0, -1.0))
    with pytest.raises(ModelError, match="must have one root link, has 2"):
        robot.to_sdf()
    with pytest.raises(ModelError, match="name it .sdf or .urdf"):
        robot.save("robot.xml")
    with pytest.raises(ModelError, match="align: link 'wheel' has no shapes"):
        robot.align("wheel", "base", x="max")


def test_names_and_numbers_drake_cannot_take_are_refused_before_it_sees_them():
    with pytest.raises(ModelError, match="model name 'mmm.*' has 100,000 characters; at most 256"):
        ModelBuilder("m" * 100_000)
    robot = ModelBuilder("bot")
    with pytest.raises(ModelError, match="link name 'lll.*' has 5,000 characters"):
        robot.add_link("l" * 5_000)
    robot.add_link("base")
    with pytest.raises(
        ModelError, match=r"box sizes must be 3 positive numbers of at most 1e\+06 m"
    ):
        robot.add_box("base", (1e308, 1.0, 1.0))
    with pytest.raises(ModelError, match="cylinder sizes"):
        robot.add_cylinder("base", math.nan, 1.0)
    robot.add_link("arm")
    for bad in ({"effort": 1e400}, {"velocity": -1.0}, {"limits": (-math.inf, 0.0)}):
        with pytest.raises(ModelError, match="joint 'j'"):
            robot.add_joint("j", "revolute", "base", "arm", **bad)
    assert robot.joints == []
    robot.add_joint("j", "revolute", "base", "arm", effort=10.0, velocity=1.0)
    assert robot.joints == ["j"]
