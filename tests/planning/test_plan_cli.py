from __future__ import annotations

import json

import numpy as np
import pytest
from plan_core_helpers import DATA, SCENES, arm3_config  # noqa: F401

from workbench.cli import main
from workbench.cli import plan as plan_cli
from workbench.planning.errors import GoalError, UnknownPlannerError
from workbench.planning.goals import check_goal, group_outline


def test_plan_prints_the_summary_and_writes_json_and_csv(capsys, tmp_path, arm3_config):  # noqa: F811
    out = tmp_path / "traj.json"
    csv_path = tmp_path / "traj.csv"
    plot = tmp_path / "traj.png"
    status = plan_cli.plan(
        "arm3",
        "random",
        config_dir=str(arm3_config.path),
        seed=5,
        scene=str(SCENES / "arm3_table.yaml"),
        json_out=str(out),
        csv_out=str(csv_path),
        plot=str(plot),
    )
    assert status == 0
    stdout = capsys.readouterr().out
    for label in (
        "planner",
        "solve",
        "simplify",
        "time parameterization",
        "path length",
        "duration",
        "peak velocity",
        "peak acceleration",
        "collision re-check",
    ):
        assert label in stdout
    assert "RRTConnect" in stdout and "passed" in stdout
    data = json.loads(out.read_text())
    assert set(data) == {"joint_names", "t", "q", "qd", "qdd"}
    assert data["joint_names"] == ["base_yaw_joint", "shoulder_pitch_joint", "elbow_pitch_joint"]
    q = np.array(data["q"])
    assert q.shape == (len(data["t"]), 3) and np.array(data["qdd"]).shape == q.shape
    assert data["t"][0] == 0.0 and np.all(np.diff(data["t"]) > 0)
    rows = csv_path.read_text().splitlines()
    assert rows[0].split(",")[:2] == ["t", "q_base_yaw_joint"]
    assert len(rows) == len(data["t"]) + 1
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plan_runs_setup_first_when_there_is_no_config(capsys, tmp_path, monkeypatch):
    import shutil

    from workbench.paths import urdf_dir

    home = tmp_path / "home"
    (home / "urdf").mkdir(parents=True)
    (home / "planning").mkdir()
    shutil.copy(urdf_dir() / "arm3.urdf", home / "urdf" / "arm3.urdf")
    monkeypatch.setenv("WORKBENCH_HOME", str(home))
    status = plan_cli.plan("arm3", "home", start="q=0.5,0.2,0.1")
    assert status == 0
    assert "running setup first" in capsys.readouterr().out
    assert (home / "planning" / "arm3" / "planning.yaml").is_file()


def test_plan_never_writes_a_config_into_the_folder_of_config(tmp_path, capsys):
    target = tmp_path / "etc" / "cfg"
    assert main(["plan", "arm3", "--to", "home", "--config", str(target)]) == 1
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and f"no planning configuration in {target}" in error
    assert f"workbench setup arm3 -o {target}" in error
    assert not (tmp_path / "etc").exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--to", "q=0,0"], "has 3 joints"),
        (["--to", "nowhere"], "has no named state 'nowhere'"),
        (
            ["--to", "home", "--from", "q=9,0,0"],
            "start: joint 'base_yaw_joint' = 9.0000 is outside",
        ),
        (["--to", "q=0,0,", "--seed", "-1"], "--seed must not be negative"),
        (
            ["--to", "home", "--json", "/no/such/dir/t.json"],
            "the folder /no/such/dir does not exist",
        ),
        (["--to", "random", "--planner", "RRTfoo"], "unknown planner 'RRTfoo'"),
        (
            ["--to", "home", "--scene", str(DATA / "bad_type.yaml")],
            "bad_type.yaml:5: object 'cone' has unknown type",
        ),
        (["--to", "xyz=2,2,2"], "no joint values within the limits"),
        (["--to", "random", "--time-limit", "-1"], "--time-limit must be a positive number"),
    ],
)
def test_plan_bad_input_is_one_line(capsys, arm3_config, args, message):  # noqa: F811
    assert main(["plan", "arm3", "--config", str(arm3_config.path), *args]) == 1
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1, lines
    assert lines[0].startswith("workbench plan: error: ")
    assert message in lines[0], lines[0]


def test_unknown_robot(run_cli, tmp_path):
    proc = run_cli("plan", "no_such_robot", "--config", tmp_path / "x", "--to", "home")
    assert proc.returncode == 1
    assert "no_such_robot" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1


def test_the_cheap_checks_see_the_planners_group(arm3_config):  # noqa: F811
    from workbench.planning.pipeline import MotionPlanner

    outline = group_outline(arm3_config)
    planner = MotionPlanner(config=arm3_config)
    assert list(outline.joint_names) == planner.joint_names
    assert np.allclose(outline.lower, planner.lower) and np.allclose(outline.upper, planner.upper)
    assert set(outline.state_names) == set(arm3_config.srdf.group_state_names(planner.group))


def test_check_goal_accepts_what_the_planner_accepts(arm3_config):  # noqa: F811
    outline = group_outline(arm3_config)
    assert check_goal("home", outline).name == "home"
    assert check_goal("q=0.1,0.2,0.3", outline).values == (0.1, 0.2, 0.3)
    assert check_goal("xyz=0.3,0.1,0.4", outline).xyz == (0.3, 0.1, 0.4)
    with pytest.raises(GoalError, match="start: group 'arm' has 3 joints"):
        check_goal("q=0", outline, "start")
    with pytest.raises(GoalError, match="cannot read goal"):
        check_goal("a=b", outline)


def test_check_options_without_a_robot():
    assert plan_cli.check_options("home", planner="rrtconnect") == "RRTConnect"
    assert plan_cli.check_options("random") is None
    with pytest.raises(UnknownPlannerError, match="RRTfoo"):
        plan_cli.check_options("home", planner="RRTfoo")
    with pytest.raises(GoalError, match="--time-limit"):
        plan_cli.check_options("home", time_limit=0.0)
    with pytest.raises(GoalError, match="q must be comma-separated numbers"):
        plan_cli.check_options("home", start="q=a,b")


CHEAP_PATH = """
import sys
from workbench.cli import main
status = main(["plan", "robot_arm", "--to", sys.argv[1]])
heavy = sorted(m for m in ("pydrake", "ompl", "toppra") if m in sys.modules)
print(status, ",".join(heavy) or "none")
"""


@pytest.mark.parametrize("goal", ["nonsense", "q=1,2", "q=9,0,0,0,0", "xyz=1,2"])
def test_a_bad_goal_is_rejected_without_loading_drake(goal):
    import subprocess
    import sys

    proc = subprocess.run(
        [sys.executable, "-c", CHEAP_PATH, goal], capture_output=True, text=True, timeout=300
    )
    assert proc.stdout.split() == ["1", "none"], proc.stderr
    assert proc.stderr.startswith("workbench plan: error: ") and proc.stderr.count("\n") == 1
