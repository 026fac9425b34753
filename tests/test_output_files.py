"""Outputs go only where asked: folders are never made, other people's files are left alone."""

from __future__ import annotations

import json
import os
import stat

import pytest

from workbench.errors import PlanningError, WorkbenchError
from workbench.output_files import KINDS, check_output, write_output


def test_a_new_file_in_an_existing_folder(tmp_path):
    target = tmp_path / "traj.json"
    assert check_output(target, "trajectory-json") == target
    assert not target.exists()  # the check leaves nothing behind
    write_output(target, json.dumps({"joint_names": []}))
    assert json.loads(target.read_text()) == {"joint_names": []}


def test_the_folder_is_never_created(tmp_path):
    with pytest.raises(PlanningError, match="the folder .* does not exist"):
        check_output(tmp_path / "new" / "plan.html", "html-snapshot", error=PlanningError)
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize(("name", "kind"), [(".", "png"), ("/dev/full", "trajectory-json")])
def test_directories_and_devices_are_refused(tmp_path, name, kind):
    target = tmp_path if name == "." else name
    with pytest.raises(WorkbenchError, match="it is (a directory|not a regular file)"):
        check_output(target, kind, option="--out")


def test_a_folder_that_takes_no_files_fails_before_any_work():
    with pytest.raises(WorkbenchError, match="cannot write --json /proc/x.json"):
        check_output("/proc/x.json", "trajectory-json", option="--json")


@pytest.mark.parametrize(
    ("kind", "ours", "theirs"),
    [
        ("trajectory-json", b'{"joint_names": ["a"], "t": []}', b'{"name": "my-package"}'),
        ("trajectory-csv", b"t,q_a,qd_a\n0.0,1,2\n", b"name,phone\nann,123\n"),
        ("png", b"\x89PNG\r\n\x1a\n....", b"GIF89a...."),
        ("html-snapshot", b"<!DOCTYPE html>\n<!-- meshcat -->", b"<html><body>my page</body>"),
        ("graphviz", b"digraph G {\n}\n", b"graph notes\n"),
        ("planning-yaml", b"# Planning configuration written by `workbench setup`\n", b"a: 1\n"),
    ],
)
def test_only_files_of_the_same_kind_are_replaced(tmp_path, kind, ours, theirs):
    mine, someone_elses = tmp_path / "mine", tmp_path / "theirs"
    mine.write_bytes(ours)
    someone_elses.write_bytes(theirs)
    assert check_output(mine, kind) == mine
    with pytest.raises(WorkbenchError, match=f"will not overwrite .*: it is not {KINDS[kind][0]}"):
        check_output(someone_elses, kind)
    assert someone_elses.read_bytes() == theirs


def test_an_empty_file_may_be_replaced(tmp_path):
    target = tmp_path / "plot.png"
    target.touch()
    assert check_output(target, "png") == target


def test_a_replaced_file_keeps_its_permissions(tmp_path):
    target = tmp_path / "traj.csv"
    target.write_text("t\n")
    os.chmod(target, 0o640)
    write_output(target, "t,q_a\n")
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert target.read_text() == "t,q_a\n"
    assert [path.name for path in tmp_path.iterdir()] == ["traj.csv"]  # no temporary left


def test_a_failed_write_leaves_the_old_file(tmp_path, monkeypatch):
    target = tmp_path / "traj.json"
    target.write_text('{"joint_names": ["old"]}')

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(WorkbenchError, match="No space left on device"):
        write_output(target, '{"joint_names": ["new"]}')
    assert target.read_text() == '{"joint_names": ["old"]}'
    assert [path.name for path in tmp_path.iterdir()] == ["traj.json"]
