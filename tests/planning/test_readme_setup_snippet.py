"""The README's setup-assistant snippet runs as printed and its comments tell the truth."""

from __future__ import annotations

import ast
import re
import shutil
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]


def _snippet() -> str:
    text = (REPO_ROOT / "README.md").read_text()
    match = re.search(r"<!-- setup-snippet -->\s*```python\n(.+?)\n```", text, re.S)
    assert match, "README.md has no ```python block after <!-- setup-snippet -->"
    return match.group(1)


def test_the_setup_snippet_runs_and_its_comments_hold(tmp_path, monkeypatch):
    for folder in ("urdf", "planning", "mapping", "examples"):
        shutil.copytree(REPO_ROOT / folder, tmp_path / folder)
    monkeypatch.setenv("WORKBENCH_HOME", str(tmp_path))
    code = _snippet()
    namespace: dict = {}
    exec(compile(code, "README.md setup snippet", "exec"), namespace)  # noqa: S102

    config = namespace["config"]
    assert config.path == tmp_path / "planning" / "robot_arm"
    summary = re.search(r"summary\(\)\s*# (\{.+?), \.\.\.\}", code)
    assert summary, "the summary() line lost its comment"
    claimed = ast.literal_eval(summary.group(1) + "}")
    from workbench.planning.setup import run_setup

    matrix = run_setup("robot_arm", samples=10000, seed=0, write=False).collision_matrix
    assert {k: matrix.summary()[k] for k in claimed} == claimed
    joints = config.srdf.group_joints("arm", namespace["robot"])
    assert joints[0] == "shoulder_pan_joint" and joints[-1] == "wrist_roll_joint"
    assert config.velocity_limits(["shoulder_pan_joint"]) == [1.0]
    assert namespace["srdf"].name == "robot_arm"
    prose = (REPO_ROOT / "README.md").read_text()
    stated = re.search(r"Never\* entries, and (\d+) pairs", prose)
    assert stated and int(stated.group(1)) == matrix.summary()["Check"]
