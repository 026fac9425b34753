"""`workbench check` and `workbench graph` as a student runs them."""

from __future__ import annotations

import json

import pydot
import pytest

from workbench.cli import main


def test_check_prints_the_check_urdf_report(capsys):
    assert main(["check", "robot_arm"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[:4] == [
        "robot name is: robot_arm",
        "---------- Successfully Parsed XML ---------------",
        "root Link: base_link has 2 child(ren)",
        "    child(1):  bottom_link",
    ]
    assert "                        child(2):  gripper_finger_link2" in out
    assert out[-1] == "workbench found no problems"


def test_check_warns_on_simple_box_inertia(capsys, repo_root):
    assert main(["check", str(repo_root / "urdf" / "simple_box.urdf")]) == 0
    out = capsys.readouterr().out
    assert "simple_box.urdf:6: warning: link 'my_box': principal moments 1, 1, 100" in out


def test_check_json(capsys):
    assert main(["check", "--json", "flexible"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["robot"] == "visual" and report["root"] == "base_link"
    assert report["errors"] == 0 and report["warnings"] > 0
    codes = {finding["code"] for finding in report["findings"]}
    assert codes == {"missing-inertial", "no-collision"}
    head = next(f for f in report["findings"] if f["element"] == "link 'head'")
    assert isinstance(head["line"], int)


def test_check_in_a_real_process(run_cli, tmp_path):
    result = run_cli("check", "arm3", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("robot name is: arm3\n")


def test_graph_writes_gv_and_pdf_in_the_current_directory(run_cli, tmp_path, require_program):
    require_program("dot")
    result = run_cli("graph", "robot_arm", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "Created file robot_arm.gv\nCreated file robot_arm.pdf\n"
    assert (tmp_path / "robot_arm.pdf").read_bytes().startswith(b"%PDF")
    assert '"base_link" -> "shoulder_pan_joint"' in (tmp_path / "robot_arm.gv").read_text()


def test_graph_format_and_output(tmp_path, monkeypatch, capsys, require_program):
    require_program("dot")
    monkeypatch.chdir(tmp_path)
    assert main(["graph", "arm3", "--format", "svg"]) == 0
    assert (tmp_path / "arm3.svg").read_text().lstrip().startswith("<?xml")
    assert main(["graph", "arm3", "-o", "out/arm.png"]) == 1  # no such directory
    (tmp_path / "out").mkdir()
    assert main(["graph", "arm3", "-o", "out/arm.png"]) == 0
    assert (tmp_path / "out" / "arm.png").read_bytes().startswith(b"\x89PNG")
    assert (tmp_path / "out" / "arm.gv").is_file()
    assert main(["graph", "arm3", "-o", "only.gv"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[-1] == "Created file only.gv"
    assert not (tmp_path / "only.pdf").exists()


def test_graph_api_gives_a_pydot_graph_jupyter_can_show(require_program):
    from workbench.model.graph import robot_graph
    from workbench.model.loader import load_document

    graph = robot_graph(load_document("arm3"))
    assert isinstance(graph, pydot.Dot)
    names = {node.get_name().strip('"') for node in graph.get_nodes()}
    assert {"base_link", "tool_link", "elbow_pitch_joint"} <= names
    require_program("dot")
    svg = graph._repr_svg_()
    assert "<svg" in svg and "elbow_pitch_joint" in svg


@pytest.mark.parametrize("bad", [["graph"], ["check"], ["graph", "arm3", "--format", "gif"]])
def test_usage_errors_exit_2(bad):
    with pytest.raises(SystemExit) as info:
        main(bad)
    assert info.value.code == 2
