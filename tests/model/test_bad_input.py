"""The bad-input corpus: every broken description gives its one-line cause, never a traceback."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from workbench.cli import main
from workbench.errors import ModelError
from workbench.model import load_robot

BAD = Path(__file__).resolve().parents[1] / "data" / "urdf" / "bad"
CASES = yaml.safe_load((BAD / "cases.yaml").read_text())


@pytest.fixture(autouse=True)
def _no_package_path(monkeypatch):
    monkeypatch.delenv("WORKBENCH_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)


def _expected(text: str, path: Path) -> str:
    return text.replace("{path}", str(path)).replace("{dir}", str(BAD))


def test_corpus_is_complete():
    files = {path.name for path in BAD.iterdir() if path.suffix != ".yaml"}
    assert files == {case["file"] for case in CASES}
    assert len(CASES) >= 15


@pytest.mark.parametrize("case", CASES, ids=[case["file"] for case in CASES])
def test_check_reports_the_cause(case, capsys):
    path = BAD / case["file"]
    status = main(["check", str(path)])
    captured = capsys.readouterr()
    expected = _expected(case["check"], path)
    stream = captured.err if expected.startswith("workbench check: error:") else captured.out
    assert status != 0
    assert expected in stream.splitlines()
    assert "Traceback" not in captured.out + captured.err
    if expected.startswith("workbench check: error:"):
        assert captured.err.count("\n") == 1  # exactly one line


@pytest.mark.parametrize("case", CASES, ids=[case["file"] for case in CASES])
def test_load_robot_raises_or_loads(case):
    path = BAD / case["file"]
    if case["load"] == "loads":
        robot = load_robot(path)
        assert robot.links
        return
    with pytest.raises(ModelError) as info:
        load_robot(path)
    assert info.value.one_line() == _expected(case["load"], path)
    assert str(path) in info.value.one_line()


def test_nonexistent_path(tmp_path, capsys):
    missing = tmp_path / "nowhere" / "robot.urdf"
    assert main(["check", str(missing)]) == 1
    error = capsys.readouterr().err
    assert (
        error == f"workbench check: error: {missing}: no such file "
        "(check the path, or give a name from urdf/)\n"
    )


@pytest.mark.parametrize(
    ("name", "commands"),
    [
        ("not_xml.urdf", ("check", "graph", "show")),
        ("failing.urdf.xacro", ("check", "graph", "show")),
        # A graph needs no meshes, so only check and show fail here.
        ("unknown_package.urdf", ("check", "show")),
    ],
)
def test_real_process_has_no_traceback(run_cli, tmp_path, name, commands):
    for command in commands:
        args = [command, str(BAD / name)]
        if command == "show":
            args += ["--html", "unused.html"]
        result = run_cli(*args, cwd=tmp_path, timeout=120)
        assert result.returncode == 1, (command, result.stdout, result.stderr)
        assert "Traceback" not in result.stderr + result.stdout
        assert str(BAD / name) in result.stdout + result.stderr


def test_json_output_for_an_unreadable_file(capsys):
    import json

    assert main(["check", "--json", str(BAD / "empty.urdf")]) == 1
    document = json.loads(capsys.readouterr().out)
    assert document["ok"] is False
    assert document["findings"][0]["message"] == "the file is empty"
