"""The robot's nodes (robot_state.nodes): where they find the robot."""

from __future__ import annotations

import pytest

from workbench.bus import Bus, Node
from workbench.errors import ModelError
from workbench.model import load_robot
from workbench.paths import project_root
from workbench.robot_state.nodes import load_robot_from_params


@pytest.fixture
def bus():
    b = Bus(threaded=False)
    yield b
    b.shutdown()


def test_robot_from_the_private_parameter(bus):
    node = Node("robot_state_publisher", bus=bus, argv=["_robot:=robot_arm"])
    robot = load_robot_from_params(node)
    assert robot.joint_names == load_robot("robot_arm").joint_names != []


def test_robot_from_robot_description(bus):
    xml = (project_root() / "urdf" / "robot_arm.urdf").read_text()
    bus.params.set("/robot_description", xml)
    robot = load_robot_from_params(Node("joint_state_publisher", bus=bus))
    assert robot.joint_names == load_robot("robot_arm").joint_names != []


def test_no_robot_says_which_parameters(bus):
    with pytest.raises(ModelError, match="no robot given") as error:
        load_robot_from_params(Node("robot_state_publisher", bus=bus))
    assert "~robot" in error.value.one_line() and "robot_description" in error.value.one_line()
