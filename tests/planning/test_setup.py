"""The setup assistant: golden SRDF, group inference, planning.yaml, and the CLI."""

from __future__ import annotations

import pytest
import yaml

from workbench.errors import ModelError
from workbench.planning.config import load_config
from workbench.planning.setup import run_setup
from workbench.planning.srdf import SrdfError, read_srdf

REGENERATE = (
    "urdf/robot_arm.urdf or the setup changed: if deliberate, regenerate as "
    "tests/data/planning/README.md says"
)


@pytest.fixture(scope="module")
def robot_arm_setup(tmp_path_factory):
    out = tmp_path_factory.mktemp("robot_arm")
    lines: list[str] = []
    config = run_setup("robot_arm", out_dir=out, log=lines.append)
    return config, out, lines


def test_robot_arm_srdf_matches_golden(robot_arm_setup, data_dir):
    _, out, _ = robot_arm_setup
    golden = (data_dir / "planning" / "robot_arm.srdf").read_text()
    assert (out / "robot_arm.srdf").read_text() == golden, REGENERATE


def test_committed_configs_are_current(robot_arm_setup, repo_root, data_dir):
    golden = (data_dir / "planning" / "robot_arm.srdf").read_text()
    committed = (repo_root / "planning" / "robot_arm" / "robot_arm.srdf").read_text()
    assert committed == golden, REGENERATE
    for name in ("robot_arm", "arm3"):
        config = load_config(name)
        assert config.robot == repo_root / "urdf" / f"{name}.urdf"


def test_robot_arm_steps_and_groups(robot_arm_setup):
    config, _, lines = robot_arm_setup
    steps = [line for line in lines if line.startswith("[")]
    assert [line.split("]")[0] for line in steps][0] == "[1/12"
    assert {line.split("/")[0] for line in steps} == {f"[{i}" for i in range(1, 13)}
    srdf = config.srdf
    assert srdf.group("arm").chains == [("base_link", "wrist_roll_link")]
    assert srdf.group("hand").links == ["gripper_finger_link1", "gripper_finger_link2"]
    assert srdf.end_effectors[0].parent_link == "wrist_roll_link"
    assert srdf.virtual_joints[0].child_link == "base_link"
    assert srdf.group_state("arm", "home").values == {
        "shoulder_pan_joint": 0.0,
        "shoulder_pitch_joint": 0.0,
        "elbow_roll_joint": 0.0,
        "elbow_pitch_joint": 0.0,
        "wrist_roll_joint": 0.0,
    }
    reasons = {(d.link1, d.link2): d.reason for d in srdf.disabled_collisions}
    # every parent/child pair of the URDF is Adjacent
    for pair in [
        ("base_link", "bottom_link"),
        ("base_link", "shoulder_pan_link"),
        ("shoulder_pan_link", "shoulder_pitch_link"),
        ("elbow_roll_link", "shoulder_pitch_link"),
        ("elbow_pitch_link", "elbow_roll_link"),
        ("elbow_pitch_link", "wrist_roll_link"),
        ("gripper_finger_link1", "wrist_roll_link"),
        ("gripper_finger_link2", "wrist_roll_link"),
    ]:
        assert reasons[pair] == "Adjacent"
    # the fingers can touch each other, so that pair stays checked
    assert ("gripper_finger_link1", "gripper_finger_link2") not in reasons
    assert config.collision_matrix.sampled >= 10000


def test_planning_yaml_round_trip(robot_arm_setup):
    config, out, _ = robot_arm_setup
    data = yaml.safe_load((out / "planning.yaml").read_text())
    assert data["robot"] == "robot_arm"
    assert data["default_planner"] == "RRTConnect"
    loaded = load_config(out)
    assert loaded.group == "arm"
    assert loaded.joint_limits == config.joint_limits
    assert loaded.joint_limits["shoulder_pan_joint"] == {
        "max_velocity": 1.0,
        "max_acceleration": 2.0,
    }
    assert loaded.controller["joints"] == loaded.srdf.group_joints("arm", config_robot(loaded))
    assert loaded.srdf.disabled_collisions == config.srdf.disabled_collisions


def config_robot(config):
    from workbench.model import load_robot

    return load_robot(config.robot)


def test_arm3_without_hand(tmp_path):
    config = run_setup("arm3", out_dir=tmp_path, samples=500, seed=2)
    srdf = config.srdf
    assert srdf.group_names == ["arm"]
    assert srdf.group("arm").chains == [("base_link", "tool_link")]
    assert srdf.end_effectors == []
    limits = config.joint_limits
    assert limits["elbow_pitch_joint"] == {"max_velocity": 2.0, "max_acceleration": 4.0}
    assert config.velocity_limits(["base_yaw_joint", "elbow_pitch_joint"]) == [1.5, 2.0]


def test_flags_override_inference(tmp_path):
    config = run_setup(
        "robot_arm",
        out_dir=tmp_path,
        samples=200,
        group="robot_arm",
        tip_link="elbow_pitch_link",
        hand_links=[],
        poses={"ready": [0.1, 0.2, 0.3, 0.4]},
        velocity_scaling=0.5,
        write=False,
    )
    srdf = config.srdf
    assert srdf.group_names == ["robot_arm"]
    assert srdf.group("robot_arm").chains == [("base_link", "elbow_pitch_link")]
    assert srdf.group_state("robot_arm", "ready").values["elbow_pitch_joint"] == 0.4
    assert config.velocity_limits(["shoulder_pan_joint"]) == [0.5]
    assert not (tmp_path / "planning.yaml").exists()


def test_existing_srdf_is_kept(data_dir, tmp_path):
    lines: list[str] = []
    config = run_setup(
        "robot_arm",
        out_dir=tmp_path,
        srdf=data_dir / "planning" / "moveit_style.srdf",
        log=lines.append,
    )
    assert any("kept 4 disabled pairs" in line for line in lines)
    assert config.collision_matrix is None
    assert config.group == "robot_arm"
    again = read_srdf(tmp_path / "robot_arm.srdf")
    assert again.group_state("robot_arm", "home").values["wrist_roll_joint"] == 0.6856
    assert again.passive_joints == ["finger_joint2"]
    assert "finger_joint2" not in config.joint_limits


@pytest.mark.parametrize(
    ("kwargs", "error", "text"),
    [
        ({"tip_link": "nowhere"}, SrdfError, "no link 'nowhere'"),
        ({"poses": {"up": [1.0, 2.0]}}, SrdfError, "has 2 values; the arm group has 5 joints"),
        ({"poses": {"up": {"shoulder_pan_joint": 9.0}}}, SrdfError, "outside its limits"),
        ({"poses": {"up": {"finger_joint1": 0.0}}}, SrdfError, "not in the arm group"),
        ({"base_link": "wrist_roll_link", "tip_link": "base_link"}, SrdfError, "not a chain"),
    ],
)
def test_bad_arguments_fail_before_sampling(kwargs, error, text):
    lines: list[str] = []
    with pytest.raises(error, match=text):
        run_setup("robot_arm", write=False, log=lines.append, **kwargs)
    assert not any(line.startswith("[2/12]") for line in lines)


def test_unknown_robot():
    with pytest.raises(ModelError, match="no_such_robot"):
        run_setup("no_such_robot", write=False)


def test_cli_writes_and_prints_steps(run_cli, tmp_path):
    out = tmp_path / "cfg"
    result = run_cli("setup", "arm3", "-o", out, "--samples", "300", "--matrix")
    assert result.returncode == 0, result.stderr
    assert "[2/12] Self-collisions: 5 links with geometry, 10 pairs" in result.stdout
    assert "[12/12] Wrote" in result.stdout
    assert "forearm_link  upper_arm_link  Adjacent" in result.stdout
    assert (out / "arm3.srdf").is_file() and (out / "planning.yaml").is_file()


@pytest.mark.parametrize(
    ("args", "text"),
    [
        (["no_such_robot"], "no robot description 'no_such_robot'"),
        (["robot_arm", "--pose", "home=1,x"], "the values must be numbers"),
        (["robot_arm", "--velocity-scaling", "2"], "--velocity-scaling must be in (0, 1]"),
        (["robot_arm", "--srdf", "/nonexistent.srdf"], "SRDF file not found"),
    ],
)
def test_cli_bad_input_is_one_line(run_cli, tmp_path, args, text):
    result = run_cli("setup", *args, "-o", tmp_path / "x", "--samples", "10")
    assert result.returncode == 1
    err = result.stderr.strip()
    assert err.startswith("workbench setup: error: ")
    assert text in err
    assert len(err.splitlines()) == 1
    assert not (tmp_path / "x").exists()


def test_cli_malformed_srdf_names_file_and_line(run_cli, data_dir, tmp_path):
    bad = data_dir / "planning" / "bad_unclosed.srdf"
    result = run_cli("setup", "robot_arm", "--srdf", bad, "-o", tmp_path / "x")
    assert result.returncode == 1
    assert result.stderr.strip().startswith(f"workbench setup: error: {bad}:5: malformed SRDF")
    assert len(result.stderr.strip().splitlines()) == 1


def test_existing_srdf_without_pairs_gets_the_matrix(tmp_path):
    srdf = tmp_path / "in.srdf"
    srdf.write_text(
        '<robot name="arm3"><group name="reach">'
        '<chain base_link="base_link" tip_link="forearm_link"/></group></robot>'
    )
    config = run_setup("arm3", out_dir=tmp_path / "out", srdf=srdf, samples=200)
    assert config.group == "reach"
    assert config.collision_matrix is not None
    reasons = {(d.link1, d.link2): d.reason for d in config.srdf.disabled_collisions}
    assert reasons[("turret_link", "upper_arm_link")] == "Adjacent"
    assert config.srdf.virtual_joints[0].child_link == "base_link"
    assert config.srdf.group_state_names("reach") == []
