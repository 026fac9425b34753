"""RobotDescription: read and parse once, load into as many plants as needed."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

import workbench.model.description as description_module
import workbench.model.sources as sources_module
from workbench.errors import ModelError
from workbench.model import RobotDescription, describe_robot, load_document, load_robot
from workbench.paths import urdf_dir


@pytest.fixture
def counts(monkeypatch):
    counter: Counter[str] = Counter()
    real_xacro = sources_module.expand_xacro
    real_parse = description_module.parse_urdf_text

    def xacro(*args, **kwargs):
        counter["xacro"] += 1
        return real_xacro(*args, **kwargs)

    def parse(*args, **kwargs):
        counter["parse"] += 1
        return real_parse(*args, **kwargs)

    monkeypatch.setattr(sources_module, "expand_xacro", xacro)
    monkeypatch.setattr(description_module, "parse_urdf_text", parse)
    return counter


def test_xacro_expanded_and_parsed_once_for_several_plants(counts):
    description = RobotDescription.load(urdf_dir() / "table.urdf.xacro")
    assert description.expanded and description.format == "urdf"
    first = load_robot(description)
    second = load_robot(first)  # a loaded robot passes its description along
    third = description.instantiate(time_step=0.001)
    assert counts == Counter(xacro=1, parse=1)
    assert first.description is second.description is third.description is description
    assert first.plant is not second.plant and third.plant.time_step() == 0.001
    assert [j.name for j in first.joints] == [j.name for j in third.joints]


def test_a_name_still_reads_the_file(counts):
    robot = load_robot("robot_arm")
    assert counts == Counter(parse=1)
    assert robot.description.path == (urdf_dir() / "robot_arm.urdf").resolve()
    assert describe_robot(robot) is robot.description
    assert describe_robot(robot.description) is robot.description
    assert load_document("robot_arm").name == robot.description.name == "robot_arm"


def test_renamed_copies_share_one_description():
    description = RobotDescription.load("robot_arm")
    a = load_robot(description, finalize=False, model_name="left")
    b = load_robot(description, plant=a.plant, builder=a.builder, model_name="right")
    assert (a.name, b.name) == ("left", "right")
    assert description.name == "robot_arm" and description.document.root.get("name") == "robot_arm"
    q = b.default_positions() + 0.1
    poses_a, poses_b = a.forward_kinematics(q), b.forward_kinematics(q)
    np.testing.assert_allclose(
        poses_a["wrist_roll_link"].GetAsMatrix4(), poses_b["wrist_roll_link"].GetAsMatrix4()
    )


def test_from_text_resolves_meshes_beside_its_path():
    text = (urdf_dir() / "robot_arm.urdf").read_text()
    description = RobotDescription.from_text(text, urdf_dir() / "robot_description.urdf")
    robot = load_robot(description)
    assert robot.name == "robot_arm" and robot.num_positions > 0


def test_errors_are_model_errors():
    with pytest.raises(ModelError, match="not well-formed XML"):
        RobotDescription.from_text("<robot name='x'>")
    with pytest.raises(ModelError, match="no robot description 'no_such_robot'"):
        RobotDescription.load("no_such_robot")


def test_urdf_geometry_speaks_the_shape_vocabulary():
    from workbench import spatial

    document = RobotDescription.load("robot_arm").document
    shapes = [
        shape.geometry.to_shape()
        for link in document.links
        for shape in link.visuals + link.collisions
        if shape.geometry is not None
    ]
    assert shapes and all(
        isinstance(s, spatial.Box | spatial.Cylinder | spatial.Sphere | spatial.Mesh)
        for s in shapes
    )
    assert document.link("base_link").visuals[0].geometry.to_shape() == spatial.Box((0.1, 0.1, 0.1))


def test_xacro_arguments_cannot_change_an_expanded_description():
    description = RobotDescription.load("robot_arm")
    assert describe_robot(description, {}) is description
    with pytest.raises(ModelError, match="already expanded"):
        load_robot(description, mappings={"width": "2"})
