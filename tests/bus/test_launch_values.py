"""Values a launch file takes from outside: commands (xacro in-process), textfiles, dry runs."""

from __future__ import annotations

import pytest

from workbench.bus.launch import Deferred, LaunchError, load_launch
from workbench.cli.launch import launch
from workbench.cli.launch import run_command as cli_run_command


def test_a_dry_run_runs_and_reads_nothing(tmp_path, capsys):
    marker = tmp_path / "ran"
    path = tmp_path / "a.launch"
    path.write_text(
        f'<launch><param name="run" command="touch {marker}"/>'
        '<param name="secret" textfile="/etc/passwd"/>'
        '<rosparam file="/dev/zero" ns="z"/></launch>'
    )
    plan = load_launch(path, dry_run=True)
    assert plan.params["/run"] == Deferred("output of command", f"touch {marker}")
    assert plan.params["/secret"] == Deferred("contents of file", "/etc/passwd")
    assert plan.rosparam_files == [("/z", "/dev/zero")]
    assert launch(path, dry_run=True) == 0
    out = capsys.readouterr().out
    assert f"param /run = <output of command 'touch {marker}', not read in a dry run>" in out
    assert "root:" not in out
    assert not marker.exists()
    with pytest.raises(LaunchError, match="/dev/zero: is a device"):
        load_launch(path, command_runner=lambda command, file: "")  # a real run reads it


def test_xacro_commands_run_workbench_xacro_in_this_process(repo_root, tmp_path):
    table = repo_root / "examples" / "packages" / "gazebo_worlds" / "launch" / "table.launch"
    plan = load_launch(table, command_runner=cli_run_command)
    assert "<robot" in plan.params["/table_description"]
    xacro = tmp_path / "box.urdf.xacro"
    xacro.write_text(
        '<robot name="box" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:arg name="size" default="1"/><link name="l_$(arg size)"/></robot>'
    )
    path = tmp_path / "a.launch"
    path.write_text(
        '<launch><param name="d" command="xacro --inorder box.urdf.xacro size:=7"/></launch>'
    )
    assert 'link name="l_7"' in load_launch(path, command_runner=cli_run_command).params["/d"]
    # below the model layer, xacro is refused rather than run some other way
    with pytest.raises(LaunchError, match="needs workbench's xacro"):
        load_launch(path)


def test_a_failing_xacro_names_the_launch_file_and_the_xacro(tmp_path):
    bad = tmp_path / "bad.urdf.xacro"
    bad.write_text('<robot name="b" xmlns:xacro="http://www.ros.org/wiki/xacro">${nope}</robot>')
    path = tmp_path / "a.launch"
    path.write_text('<launch><param name="d" command="xacro bad.urdf.xacro"/></launch>')
    with pytest.raises(LaunchError) as info:
        load_launch(path, command_runner=cli_run_command)
    line = info.value.one_line()
    assert line.startswith(f"{path}:1: <param> line 1: {bad}: xacro failed"), line


def test_commands_are_bounded_in_output(tmp_path, require_program):
    require_program("yes")
    path = tmp_path / "a.launch"
    path.write_text('<launch><param name="y" command="yes"/></launch>')
    with pytest.raises(LaunchError, match="param command 'yes' printed more than 16 MiB"):
        load_launch(path)
    path.write_text(
        '<launch><param name="e" command="sh -c \'echo oops >&amp;2; exit 3\'"/></launch>'
    )
    with pytest.raises(LaunchError, match="exited with 3: oops"):
        load_launch(path)
    path.write_text('<launch><param name="n" command="/no/such/program"/></launch>')
    with pytest.raises(LaunchError, match="failed: No such file or directory"):
        load_launch(path)
