"""urdf/turtlebot3_burger.urdf: the Burger's published numbers, and it stands on its wheels.

Published: about 1 kg; wheels of 33 mm radius 160 mm apart; the LDS-01 lidar
on top (360 samples over a full turn, 0.12-3.5 m, 5 Hz) on frame base_scan;
turtlebot3_gazebo's differential drive on cmd_vel/odom with wheelSeparation
0.160 and wheelDiameter 0.066.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from lxml import etree

from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.loading import load_sim_model, sim_model_from_xml
from workbench.sim.server import SERVER_PHYSICS

URDF = urdf_dir() / "turtlebot3_burger.urdf"


@pytest.fixture(scope="module")
def tree():
    return etree.parse(str(URDF)).getroot()


def _joint(tree, name: str):
    (joint,) = tree.xpath(f"joint[@name='{name}']")
    return joint


def _xyz(element) -> np.ndarray:
    return np.array([float(v) for v in element.find("origin").get("xyz").split()])


def _plugin(tree, filename: str):
    (plugin,) = tree.xpath(f"//plugin[@filename='{filename}']")
    return {child.tag: (child.text or "").strip() for child in plugin}


def test_wheels_are_33_mm_and_160_mm_apart_as_the_drive_plugin_says(tree):
    left, right = _joint(tree, "wheel_left_joint"), _joint(tree, "wheel_right_joint")
    assert left.get("type") == right.get("type") == "continuous"
    separation = _xyz(left)[1] - _xyz(right)[1]
    assert separation == pytest.approx(0.160)
    radii = {
        float(c.get("radius"))
        for c in tree.xpath("link[starts-with(@name, 'wheel_')]/collision/geometry/cylinder")
    }
    assert radii == {0.033}
    drive = _plugin(tree, "libgazebo_ros_diff_drive.so")
    assert float(drive["wheelSeparation"]) == pytest.approx(separation)
    assert float(drive["wheelDiameter"]) == pytest.approx(2 * 0.033)
    assert (drive["leftJoint"], drive["rightJoint"]) == ("wheel_left_joint", "wheel_right_joint")
    assert drive["commandTopic"] == "cmd_vel" and drive["odometryTopic"] == "odom"
    assert drive["odometryFrame"] == "odom" and drive["robotBaseFrame"] == "base_footprint"
    assert drive["updateRate"] == "30" and drive["publishOdomTF"] == "true"
    assert drive["publishWheelTF"] == "false" and drive["publishWheelJointState"] == "true"
    # base_link 10 mm up, axle 23 mm above it: the wheels touch the ground plane of base_footprint
    assert _xyz(_joint(tree, "base_joint"))[2] + _xyz(left)[2] == pytest.approx(0.033)


def test_the_lidar_is_the_lds_01_on_base_scan_about_17_cm_up(tree):
    scan_height = _xyz(_joint(tree, "base_joint"))[2] + _xyz(_joint(tree, "scan_joint"))[2]
    assert 0.16 < scan_height < 0.19
    (sensor,) = tree.xpath("gazebo[@reference='base_scan']/sensor")
    assert sensor.get("type") == "ray"
    assert sensor.findtext("update_rate") == "5"
    horizontal = sensor.find("ray/scan/horizontal")
    assert int(horizontal.findtext("samples")) == 360
    assert float(horizontal.findtext("min_angle")) == 0.0
    assert float(horizontal.findtext("max_angle")) == pytest.approx(2 * math.pi, abs=1e-5)
    ray_range = sensor.find("ray/range")
    assert [float(ray_range.findtext(k)) for k in ("min", "max", "resolution")] == [
        0.12,
        3.5,
        0.015,
    ]
    assert float(sensor.findtext("ray/noise/stddev")) == 0.01
    laser = _plugin(tree, "libgazebo_ros_laser.so")
    assert laser["topicName"] == "scan" and laser["frameName"] == "base_scan"


def test_it_loads_without_warnings_and_weighs_about_a_kilogram():
    model = load_sim_model("turtlebot3_burger")
    assert model.warnings == []  # base_footprint and imu_link add no mass
    assert model.root_link == "base_footprint"
    assert [p.filename for p in model.plugins] == [
        "libgazebo_ros_diff_drive.so",
        "libgazebo_ros_imu_sensor.so",
        "libgazebo_ros_laser.so",
    ]
    world = World(**SERVER_PHYSICS)
    world.add_model(model, [0, 0, 0])
    world.build()
    context = world.plant.GetMyContextFromRoot(world.context)
    mass = world.plant.CalcTotalMass(context, [world.model_instance("turtlebot3_burger")])
    assert mass == pytest.approx(1.0, abs=0.05)


def _rest(model, z0: float = 0.0, seconds: float = 1.5):
    world = World(**SERVER_PHYSICS)
    world.add_model(model, [0, 0, z0])
    world.build()
    world.advance_to(1.0)
    first = world.get_model_pose(model.name)
    world.advance_to(seconds)
    return first, world.get_model_pose(model.name), world


def test_the_burger_rests_level_on_its_wheels_and_caster():
    first, last, world = _rest(load_sim_model("turtlebot3_burger"), z0=0.02)
    # base_footprint is the ground under the axle: it ends on z = 0 (less the contact's give)
    assert last.translation()[2] == pytest.approx(0.0, abs=2e-4)
    assert np.linalg.norm(last.translation() - first.translation()) < 1e-5
    assert np.allclose(last.rotation().matrix(), np.eye(3), atol=2e-3)  # level within 0.1 deg
    linear, angular = world.get_model_twist("turtlebot3_burger")
    assert np.linalg.norm(linear) < 1e-4 and np.linalg.norm(angular) < 1e-3


def test_the_lab_custom_bot_rests_on_its_three_wheels():
    first, last, _ = _rest(load_sim_model("custom_bot"), z0=0.09)
    # base_link's centre sits 50 mm above the axles, which are one wheel radius (35 mm) up
    assert last.translation()[2] == pytest.approx(0.085, abs=2e-4)
    assert np.linalg.norm(last.translation() - first.translation()) < 1e-4
    assert np.allclose(last.rotation().matrix(), np.eye(3), atol=2e-3)


def test_a_massless_frame_fixed_to_the_body_adds_no_mass_but_a_lone_one_gets_the_default():
    text = """<robot name="r">
  <link name="footprint"/>
  <joint name="j" type="fixed"><parent link="footprint"/><child link="body"/></joint>
  <link name="body"><inertial><mass value="2"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <joint name="k" type="continuous"><parent link="body"/><child link="flag"/></joint>
  <link name="flag"/>
</robot>"""
    model = sim_model_from_xml(text, name=None, source="test.urdf")
    # 'flag' moves: Gazebo cannot lump it, so it gets SDFormat's default like any free link
    assert [w.split(";")[0] for w in model.warnings] == ["test.urdf: link 'flag' has no <inertial>"]
    world = World(**SERVER_PHYSICS)
    world.add_model(model, [0, 0, 0.1])
    world.build()
    context = world.plant.GetMyContextFromRoot(world.context)
    assert world.plant.CalcTotalMass(context, [world.model_instance("r")]) == pytest.approx(3.0)
