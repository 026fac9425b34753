"""The msg/srv/bag commands from a terminal, and their one-line errors."""

from __future__ import annotations

import pytest

INPROC = {"WORKBENCH_MASTER_URI": "inproc"}


def test_msg_and_srv_commands(run_cli):
    shown = run_cli("msg", "show", "geometry_msgs/Twist")
    assert shown.returncode == 0
    assert shown.stdout.splitlines()[:2] == ["geometry_msgs/Vector3 linear", "  float64 x"]
    assert (
        run_cli("msg", "md5", "turtlesim/Pose").stdout.strip() == "863b248d5016ca62ea2e895ae5265cf9"
    )
    assert run_cli("msg", "list", "turtlesim").stdout.split() == [
        "turtlesim/Color",
        "turtlesim/Pose",
    ]
    assert run_cli("srv", "show", "turtlesim/Spawn").stdout.splitlines()[-2:] == [
        "---",
        "string name",
    ]


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


def test_bag_info_command(run_cli, tmp_path):
    from workbench.bag import BagWriter
    from workbench.msgs.turtlesim import Pose

    with BagWriter(tmp_path / "a.bag") as bag:
        bag.write("/turtle1/pose", Pose(x=1.0), 100.0)
        bag.write("/turtle1/pose", Pose(x=2.0), 101.5)
    result = run_cli("bag", "info", "a.bag", cwd=tmp_path, env={"TZ": "UTC"})
    assert result.returncode == 0
    assert result.stdout.splitlines() == [
        "path:        a.bag",
        "version:     2.0",
        "duration:    1.5s",
        "start:       Jan 01 1970 00:01:40.00 (100.00)",
        "end:         Jan 01 1970 00:01:41.50 (101.50)",
        f"size:        {result.stdout.split('size:')[1].split()[0]} KB",
        "messages:    2",
        "compression: none [1/1 chunks]",
        "types:       turtlesim/Pose [863b248d5016ca62ea2e895ae5265cf9]",
        "topics:      /turtle1/pose   2 msgs    : turtlesim/Pose",
    ]
