from __future__ import annotations

import json

import numpy as np
import pytest
from plan_core_helpers import DATA, SCENES, arm3_config  # noqa: F401


def test_plan_prints_the_summary_and_writes_json_and_csv(run_cli, tmp_path, arm3_config):  # noqa: F811
    out = tmp_path / "traj.json"
    csv_path = tmp_path / "traj.csv"
    plot = tmp_path / "traj.png"
    proc = run_cli(
        "plan",
        "arm3",
        "--config",
        arm3_config.path,
        "--to",
        "random",
        "--seed",
        "5",
        "--scene",
        SCENES / "arm3_table.yaml",
        "--json",
        out,
        "--csv",
        csv_path,
        "--plot",
        plot,
    )
    assert proc.returncode == 0, proc.stderr
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
        assert label in proc.stdout
    assert "RRTConnect" in proc.stdout and "passed" in proc.stdout
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


def test_plan_runs_setup_first_when_there_is_no_config(run_cli, tmp_path):
    proc = run_cli(
        "plan", "arm3", "--config", tmp_path / "cfg", "--to", "home", "--from", "q=0.5,0.2,0.1"
    )
    assert proc.returncode == 0, proc.stderr
    assert "running setup first" in proc.stdout
    assert (tmp_path / "cfg" / "planning.yaml").is_file()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--to", "q=0,0"], "has 3 joints"),
        (["--to", "random", "--planner", "RRTfoo"], "unknown planner 'RRTfoo'"),
        (
            ["--to", "home", "--scene", str(DATA / "bad_type.yaml")],
            "bad_type.yaml:5: object 'cone' has unknown type",
        ),
        (["--to", "xyz=2,2,2"], "no joint values within the limits"),
        (["--to", "random", "--time-limit", "-1"], "--time-limit must be positive"),
    ],
)
def test_plan_bad_input_is_one_line(run_cli, arm3_config, args, message):  # noqa: F811
    proc = run_cli("plan", "arm3", "--config", arm3_config.path, *args)
    assert proc.returncode == 1
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    assert lines[0].startswith("workbench plan: error: ")
    assert message in lines[0], lines[0]


def test_unknown_robot(run_cli, tmp_path):
    proc = run_cli("plan", "no_such_robot", "--config", tmp_path / "x", "--to", "home")
    assert proc.returncode == 1
    assert "no_such_robot" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
