"""SRDF reading, writing, group resolution and error messages."""

from __future__ import annotations

import pytest

from workbench.planning.srdf import (
    DisabledCollision,
    Srdf,
    SrdfError,
    parse_srdf,
    read_srdf,
    write_srdf,
)


@pytest.fixture(scope="module")
def robot_arm():
    from workbench.model import load_robot

    return load_robot("robot_arm")


@pytest.fixture(scope="module")
def moveit_srdf(data_dir):
    return read_srdf(data_dir / "planning" / "moveit_style.srdf")


def test_reads_every_moveit_element(moveit_srdf):
    s = moveit_srdf
    assert s.name == "robot_arm"
    assert s.group_names == ["robot_arm", "hand", "wrist", "arm_and_hand"]
    assert s.group("robot_arm").chains == [("base_link", "wrist_roll_link")]
    assert s.group("hand").links == ["gripper_finger_link1", "gripper_finger_link2"]
    assert s.group("wrist").joints == ["elbow_pitch_joint", "wrist_roll_joint"]
    assert s.group("arm_and_hand").subgroups == ["robot_arm", "hand"]
    home = s.group_state("robot_arm", "home")
    assert home.values["elbow_roll_joint"] == pytest.approx(-1.0416)
    assert s.group_state_names("hand") == ["open"]
    (ee,) = s.end_effectors
    assert (ee.name, ee.group, ee.parent_link, ee.parent_group) == (
        "hand",
        "hand",
        "wrist_roll_link",
        "robot_arm",
    )
    assert s.end_effector_of("robot_arm") is ee
    (vj,) = s.virtual_joints
    assert (vj.type, vj.parent_frame, vj.child_link) == ("floating", "world", "base_link")
    assert s.passive_joints == ["finger_joint2"]
    assert DisabledCollision("base_link", "bottom_link", "Adjacent") in s.disabled_collisions
    # a pair without reason is a user choice, as in MoveIt
    assert DisabledCollision("bottom_link", "wrist_roll_link", "User") in s.disabled_collisions
    assert frozenset(("gripper_finger_link1", "gripper_finger_link2")) in s.disabled_pairs()
    assert len(s.extra) == 1 and "link_sphere_approximation" in s.extra[0]
    assert s.line_of("group", "hand") == 13


def test_round_trip_keeps_everything(moveit_srdf, tmp_path):
    path = write_srdf(moveit_srdf, tmp_path / "out" / "robot_arm.srdf")
    again = read_srdf(path)
    for attr in (
        "name",
        "virtual_joints",
        "groups",
        "group_states",
        "end_effectors",
        "passive_joints",
        "disabled_collisions",
        "extra",
    ):
        assert getattr(again, attr) == getattr(moveit_srdf, attr), attr
    assert again.to_xml() == moveit_srdf.to_xml()


def test_groups_resolve_against_the_robot(moveit_srdf, robot_arm):
    s = moveit_srdf
    s.validate(robot_arm)
    arm = [
        "shoulder_pan_joint",
        "shoulder_pitch_joint",
        "elbow_roll_joint",
        "elbow_pitch_joint",
        "wrist_roll_joint",
    ]
    assert s.group_joints("robot_arm", robot_arm) == arm
    # the passive finger joint is not planned for
    assert s.group_joints("hand", robot_arm) == ["finger_joint1"]
    assert s.group_joints("hand", robot_arm, movable_only=False) == [
        "finger_joint1",
        "finger_joint2",
    ]
    assert s.group_joints("arm_and_hand", robot_arm) == [*arm, "finger_joint1"]
    assert s.group_tip("robot_arm", robot_arm) == "wrist_roll_link"
    assert s.group_tip("wrist", robot_arm) == "wrist_roll_link"
    links = s.group_links("robot_arm", robot_arm)
    assert links[0] == "base_link" and links[-1] == "wrist_roll_link"
    assert "bottom_link" not in links


def test_unknown_group_and_state_suggest_names(moveit_srdf):
    with pytest.raises(
        SrdfError, match=r"unknown planning group 'robot_ram'.*did you mean 'robot_arm'"
    ):
        moveit_srdf.group("robot_ram")
    with pytest.raises(SrdfError, match=r"no named state 'hom'.*did you mean 'home'"):
        moveit_srdf.group_state("robot_arm", "hom")


@pytest.mark.parametrize(
    ("name", "line", "text"),
    [
        ("bad_unclosed.srdf", 5, "malformed SRDF"),
        ("bad_missing_attribute.srdf", 4, "<chain> lacks the attribute 'tip_link'"),
        ("bad_value.srdf", 7, "value 'zero', which is not a number"),
        ("bad_root.srdf", 2, "root element is <robt>"),
        ("bad_virtual_joint.srdf", 4, "type 'revolute'"),
    ],
)
def test_malformed_files_name_file_and_line(data_dir, name, line, text):
    path = data_dir / "planning" / name
    with pytest.raises(SrdfError) as info:
        read_srdf(path)
    message = info.value.one_line()
    assert message.startswith(f"{path}:{line}: ")
    assert text in message
    assert "\n" not in message


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("bad_unknown_link.srdf", "'wrist_rol_link' is not a link of the robot"),
        ("bad_not_a_chain.srdf", "is not a chain"),
    ],
)
def test_groups_that_do_not_fit_the_robot(data_dir, robot_arm, name, text):
    path = data_dir / "planning" / name
    srdf = read_srdf(path)
    with pytest.raises(SrdfError) as info:
        srdf.validate(robot_arm)
    assert info.value.one_line().startswith(f"{path}:3: ")
    assert text in info.value.one_line()


def test_missing_file():
    with pytest.raises(SrdfError, match="SRDF file not found"):
        read_srdf("/nonexistent/robot.srdf")


def test_state_naming_a_joint_outside_its_group(robot_arm):
    text = """<robot name="robot_arm">
      <group name="hand"><link name="gripper_finger_link1"/></group>
      <group_state name="bad" group="hand"><joint name="wrist_roll_joint" value="0"/></group_state>
    </robot>"""
    srdf = parse_srdf(text, path="inline.srdf")
    with pytest.raises(SrdfError, match=r"inline.srdf:3: state 'bad' .* 'wrist_roll_joint'"):
        srdf.validate(robot_arm)


def test_written_file_is_moveit_layout():
    srdf = Srdf(name="r")
    srdf.disabled_collisions.append(DisabledCollision("a", "b", "Never"))
    text = srdf.to_xml()
    assert text.startswith('<?xml version="1.0" encoding="UTF-8"?>\n<!--')
    assert '    <disable_collisions link1="a" link2="b" reason="Never"/>' in text
    assert parse_srdf(text).disabled_collisions == srdf.disabled_collisions
