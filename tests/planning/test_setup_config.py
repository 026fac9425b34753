"""planning.yaml loading: where it is looked for and what a bad file says."""

from __future__ import annotations

import shutil

import pytest

from workbench.planning.config import (
    ConfigError,
    ConfigNotFoundError,
    config_dir,
    find_config,
    load_config,
)
from workbench.planning.srdf import SrdfError


@pytest.fixture
def config_copy(repo_root, tmp_path):
    target = tmp_path / "robot_arm"
    shutil.copytree(repo_root / "planning" / "robot_arm", target)
    return target


def _edit(directory, old, new):
    path = directory / "planning.yaml"
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new))
    return path


def test_lookup_by_name_dir_and_file(repo_root, config_copy):
    assert config_dir("robot_arm") == repo_root / "planning" / "robot_arm"
    assert config_dir("/some/where/robot_arm.urdf") == repo_root / "planning" / "robot_arm"
    assert find_config("robot_arm") == repo_root / "planning" / "robot_arm" / "planning.yaml"
    assert find_config(config_copy) == config_copy / "planning.yaml"
    config = load_config(config_copy / "planning.yaml")
    assert config.path == config_copy
    assert config.robot_name == "robot_arm"
    assert config.acceleration_limits(["wrist_roll_joint"], scaled=False) == [2.0]


def test_missing_config_says_to_run_setup(tmp_path):
    with pytest.raises(ConfigNotFoundError, match="run: workbench setup no_such_bot"):
        load_config("no_such_bot")


def test_scaling_applies(config_copy):
    _edit(config_copy, "acceleration_scaling: 1.0", "acceleration_scaling: 0.25")
    config = load_config(config_copy)
    assert config.acceleration_limits(["shoulder_pan_joint"]) == [0.5]
    assert config.velocity_limits(["shoulder_pan_joint"]) == [1.0]


@pytest.mark.parametrize(
    ("old", "new", "error", "text"),
    [
        ("group: arm", "group: [arm", ConfigError, "planning.yaml:5: malformed YAML"),
        ("group: arm", "group: arms", ConfigError, "unknown planning group 'arms'"),
        ("velocity_scaling: 1.0", "velocity_scaling: 1.5", ConfigError, "velocity_scaling"),
        ("edge_resolution: 0.01", "edge_resolution: -1", ConfigError, "edge_resolution"),
        ("max_velocity: 1.0,", "max_velocity: -1,", ConfigError, "max_velocity must be"),
        ("type: inverse_dynamics", "type: magic", ConfigError, "controller type 'magic'"),
        ("default_planner", "planner_name", ConfigError, "unknown setting 'planner_name'"),
        ("robot: robot_arm", "robot: missing_bot", ConfigError, "robot 'missing_bot' not found"),
        ("srdf: robot_arm.srdf", "srdf: other.srdf", SrdfError, "SRDF file not found"),
    ],
)
def test_bad_settings_are_one_line(config_copy, old, new, error, text):
    _edit(config_copy, old, new)
    with pytest.raises(error) as info:
        load_config(config_copy)
    message = info.value.one_line()
    assert text in message
    assert "\n" not in message


def test_limits_for_unknown_joint(config_copy):
    config = load_config(config_copy)
    with pytest.raises(ConfigError, match="no limits for joint 'elbow'"):
        config.velocity_limits(["elbow"])
