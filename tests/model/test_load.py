"""Loading descriptions into Drake: the workbench.model contract."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import ModelError
from workbench.model import JointInfo, LinkInfo, Robot, load_robot, resolve_robot_path


@pytest.fixture(scope="module")
def arm() -> Robot:
    return load_robot("robot_arm")


@pytest.fixture(scope="module")
def arm3() -> Robot:
    return load_robot("arm3")


def test_resolve_name_and_path(repo_root):
    path = resolve_robot_path("robot_arm")
    assert path == (repo_root / "urdf" / "robot_arm.urdf").resolve()
    assert resolve_robot_path(str(path)) == path


def test_resolve_unknown_name_lists_what_was_tried():
    with pytest.raises(ModelError) as info:
        resolve_robot_path("no_such_robot")
    message = info.value.one_line()
    assert "no_such_robot.urdf" in message and "no_such_robot.sdf" in message
    assert "robot_arm" in message  # the hint lists the known names


def test_robot_arm_joints_keep_the_manual_values(arm):
    assert arm.name == "robot_arm"
    assert arm.root_link == "base_link"
    assert arm.joint_names == [
        "shoulder_pan_joint",
        "shoulder_pitch_joint",
        "elbow_roll_joint",
        "elbow_pitch_joint",
        "wrist_roll_joint",
        "finger_joint1",
        "finger_joint2",
    ]
    pan = arm.joint("shoulder_pan_joint")
    assert isinstance(pan, JointInfo)
    assert pan.type == "revolute" and pan.parent == "base_link"
    np.testing.assert_allclose(pan.axis, [-1, 0, 0])
    np.testing.assert_allclose(pan.rpy, [0, 1.570795, 0])
    assert pan.lower == pytest.approx(-2.61799387799)
    assert pan.upper == pytest.approx(1.98394848567)
    assert arm.joint("finger_joint2").effort == 1
    np.testing.assert_allclose(arm.lower_limits[-2:], [0.0, -0.03])
    np.testing.assert_allclose(arm.upper_limits[-2:], [0.03, 0.0])
    np.testing.assert_allclose(arm.velocity_limits, np.ones(7))


def test_robot_arm_links_have_collision_and_mass(arm):
    assert all(isinstance(link, LinkInfo) for link in arm.links)
    assert len(arm.links) == 9
    assert all(link.has_visual and link.has_collision for link in arm.links)
    assert all(link.mass is not None and link.mass > 0 for link in arm.links)
    assert arm.materials["Blue"] == (0.0, 0.0, 0.8, 1.0)


def test_forward_kinematics_of_arm3(arm3):
    poses = arm3.forward_kinematics(np.zeros(3))
    np.testing.assert_allclose(poses["tool_link"].translation(), [0, 0, 0.7], atol=1e-12)
    # Shoulder pitched +90 deg about y: the arm points along +x.
    poses = arm3.forward_kinematics(arm3.positions_from({"shoulder_pitch_joint": np.pi / 2}))
    np.testing.assert_allclose(poses["tool_link"].translation(), [0.55, 0, 0.15], atol=1e-9)


def test_frames_include_every_link(arm3):
    assert {link.name for link in arm3.links} <= set(arm3.frame_names)


def test_positions_from_rejects_unknown_names(arm3):
    with pytest.raises(ModelError, match="elbow_pitch_joint"):
        arm3.positions_from({"elbow_pitch": 0.1})


def test_default_positions_are_clipped_into_limits(arm):
    q = arm.default_positions()
    assert np.all(q >= arm.lower_limits) and np.all(q <= arm.upper_limits)


def test_unfinalized_plant_accepts_more_models():
    from pydrake.math import RigidTransform

    robot = load_robot("arm3", finalize=False)
    other = load_robot("arm3", plant=robot.plant, model_name="arm3_b", finalize=False)
    assert not robot.plant.is_finalized()
    robot.finalize()
    robot.finalize()  # idempotent
    assert robot.plant.num_positions() == 6
    assert other.joint_names == robot.joint_names
    X = other.forward_kinematics(np.zeros(3))["tool_link"]
    assert isinstance(X, RigidTransform)


def test_floating_base_adds_a_free_root():
    robot = load_robot("arm3", floating_base=True)
    assert robot.plant.num_positions() == 3 + 7
    assert robot.joint_names == ["base_yaw_joint", "shoulder_pitch_joint", "elbow_pitch_joint"]
    assert robot.forward_kinematics(np.zeros(3))["tool_link"].translation()[2] == pytest.approx(0.7)


def test_builder_is_used():
    from pydrake.systems.framework import DiagramBuilder

    builder = DiagramBuilder()
    robot = load_robot("arm3", builder=builder, time_step=0.001)
    assert robot.builder is builder
    assert robot.plant.time_step() == 0.001
    assert robot.scene_graph is not None


def test_a_world_link_is_drakes_world(tmp_path):
    source = tmp_path / "on_a_pedestal.urdf"
    source.write_text("""<?xml version="1.0"?>
<robot name="on_a_pedestal">
  <link name="world"/>
  <link name="base_link"/>
  <joint name="pedestal" type="fixed">
    <parent link="world"/><child link="base_link"/><origin xyz="0 0 1"/>
  </joint>
  <link name="arm">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <joint name="hinge" type="revolute">
    <parent link="base_link"/><child link="arm"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>
""")
    robot = load_robot(source)
    assert robot.root_link == "world" and robot.joint_names == ["hinge"]
    poses = robot.forward_kinematics([0.5])
    assert set(poses) == {"world", "base_link", "arm"}
    np.testing.assert_allclose(poses["arm"].translation(), [0, 0, 1])
