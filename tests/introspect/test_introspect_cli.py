"""The msg/srv/bag commands, called as functions and from a terminal, and their one-line errors."""

from __future__ import annotations

import time

import pytest

from workbench.cli import bag, main, msg, srv

INPROC = {"WORKBENCH_MASTER_URI": "inproc"}


def _out(capsys) -> str:
    return capsys.readouterr().out


def test_msg_and_srv_commands(capsys):
    assert msg.show("geometry_msgs/Twist") == 0
    assert _out(capsys).splitlines()[:2] == ["geometry_msgs/Vector3 linear", "  float64 x"]
    assert msg.md5("turtlesim/Pose") == 0
    assert _out(capsys).strip() == "863b248d5016ca62ea2e895ae5265cf9"
    assert msg.list_messages("turtlesim") == 0
    assert _out(capsys).split() == ["turtlesim/Color", "turtlesim/Pose"]
    assert srv.show("turtlesim/Spawn") == 0
    assert _out(capsys).splitlines()[-2:] == ["---", "string name"]
    assert srv.list_services("turtlesim") == 0
    assert "turtlesim/Spawn" in _out(capsys).split()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("msg", "list", "no_such_pkg"), "no message types in package 'no_such_pkg'"),
        (("srv", "list", "no_such_pkg"), "no service types in package 'no_such_pkg'"),
        (("bag", "record", "-a", "-j", "--lz4"), "choose one compression"),
        (("bag", "record", "-a", "--duration", "0"), "--duration must be positive"),
        (("bag", "play", "x.bag", "-r", "0"), "--rate must be a speed factor"),
    ],
)
def test_bad_input_in_process_is_one_line(capsys, monkeypatch, tmp_path, args, message):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("WORKBENCH_MASTER_URI", "inproc")
    assert main(list(args)) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"workbench {args[0]}: error: ")
    assert message in err[0]
    assert not list(tmp_path.iterdir())  # rejected before anything was written


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("msg", "show", "geometry_msgs/Twst"), "unknown message type 'geometry_msgs/Twst'"),
        (("srv", "show", "turtlesim/Spawnn"), "turtlesim/Spawnn"),
        (("bag", "info", "missing.bag"), "missing.bag: bag file does not exist"),
        (("bag", "record", "-O", "no/such/dir/x", "/a"), "directory does not exist"),
        (("bag", "record"), "nothing to record"),
    ],
)
def test_bad_input_is_one_line(run_cli, tmp_path, args, message):
    result = run_cli(*args, cwd=tmp_path, env=INPROC)
    assert result.returncode == 1
    lines = result.stderr.strip().splitlines()
    assert message in lines[-1] and lines[-1].startswith(f"workbench {args[0]}: error: ")
    assert "Traceback" not in result.stderr


def test_bag_info_command(capsys, monkeypatch, tmp_path):
    from workbench.bag import BagWriter
    from workbench.msgs.turtlesim import Pose

    with BagWriter(tmp_path / "a.bag") as writer:
        writer.write("/turtle1/pose", Pose(x=1.0), 100.0)
        writer.write("/turtle1/pose", Pose(x=2.0), 101.5)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("TZ", "UTC")
    time.tzset()
    try:
        assert bag.info(["a.bag"]) == 0
    finally:
        monkeypatch.undo()
        time.tzset()
    stdout = capsys.readouterr().out
    assert stdout.splitlines() == [
        "path:        a.bag",
        "version:     2.0",
        "duration:    1.5s",
        "start:       Jan 01 1970 00:01:40.00 (100.00)",
        "end:         Jan 01 1970 00:01:41.50 (101.50)",
        f"size:        {stdout.split('size:')[1].split()[0]} KB",
        "messages:    2",
        "compression: none [1/1 chunks]",
        "types:       turtlesim/Pose [863b248d5016ca62ea2e895ae5265cf9]",
        "topics:      /turtle1/pose   2 msgs    : turtlesim/Pose",
    ]
