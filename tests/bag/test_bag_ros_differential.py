"""Bags in both directions against ROS 1's own rosbag (Debian's python3-rosbag, ros_comm 1.15).

Every compression: workbench writes, ROS reads the same messages; ROS writes,
workbench reads them back. Skips (fails under WORKBENCH_REQUIRE_ALL=1) without
``/usr/bin/python3`` able to ``import rosbag``; ``.ci/run`` installs it.
"""

from __future__ import annotations

import json
import subprocess

import numpy as np
import pytest
from skipping import ros_python as find_ros_python

from workbench.bag import BagWriter, read_messages
from workbench.msgs.geometry_msgs import Twist, Vector3


@pytest.fixture(scope="module")
def ros_python() -> str:
    return find_ros_python("rosbag", "python3-rosbag")


def _values(seed: int, n: int = 500) -> list[float]:
    return [float(v) for v in np.random.default_rng(seed).normal(size=n)]


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_ros_reads_what_workbench_writes(tmp_path, ros_python, compression):
    values = _values(1)
    path = tmp_path / f"wb_{compression}.bag"
    with BagWriter(path, compression=compression, chunk_size=4096) as bag:
        for i, value in enumerate(values):
            bag.write("/cmd_vel", Twist(linear=Vector3(x=value)), 100.0 + 0.01 * i)
    script = (
        "import json, sys, rosbag\n"
        "bag = rosbag.Bag(sys.argv[1])\n"
        "print(json.dumps([[t, m.linear.x, s.to_nsec()] for t, m, s in bag.read_messages()]))\n"
    )
    done = subprocess.run([ros_python, "-c", script, str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    read = json.loads(done.stdout)
    assert [row[1] for row in read] == values
    assert {row[0] for row in read} == {"/cmd_vel"}
    assert read[3][2] == 100_030_000_000


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_workbench_reads_what_ros_writes(tmp_path, ros_python, compression):
    values = _values(2)
    path = tmp_path / f"ros_{compression}.bag"
    script = (
        "import json, sys, rosbag, rospy\n"
        "from geometry_msgs.msg import Twist\n"
        "values = json.loads(sys.argv[3])\n"
        "with rosbag.Bag(sys.argv[1], 'w', compression=sys.argv[2], chunk_threshold=4096) as bag:\n"
        "    for i, v in enumerate(values):\n"
        "        m = Twist(); m.linear.x = v\n"
        "        bag.write('/cmd_vel', m, rospy.Time(100, i * 10000000))\n"
    )
    done = subprocess.run(
        [ros_python, "-c", script, str(path), compression, json.dumps(values)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    read = list(read_messages(path))
    assert [m.msg.linear.x for m in read] == values


def _ros(ros_python: str, script: str, *args: str) -> str:
    done = subprocess.run(
        [ros_python, "-c", script, *args], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


READ_ALL = (
    "import json, sys, rosbag\n"
    "bag = rosbag.Bag(sys.argv[1])\n"
    "conns = {c.id: {k: v.decode() for k, v in c.header.items() if k != 'message_definition'}\n"
    "         for c in bag._connections.values()}\n"
    "rows = [[t, m.linear.x, h.get('callerid', b'').decode()] for t, m, s, h in\n"
    "        bag.read_messages(return_connection_header=True)]\n"
    "print(json.dumps({'connections': sorted(conns.values(), key=str), 'rows': rows}))\n"
)


def test_ros_sees_each_publisher_as_its_own_connection(tmp_path, ros_python):
    path = tmp_path / "callers.bag"
    with BagWriter(path) as bag:
        for i in range(4):
            name = "/left" if i % 2 else "/right"
            bag.write("/cmd_vel", Twist(linear=Vector3(x=i)), 100.0 + i, callerid=name)
        bag.write("/latched", Twist(), 105.0, callerid="/static", latching=True)
    seen = json.loads(_ros(ros_python, READ_ALL, str(path)))
    headers = {(h["topic"], h["callerid"]): h for h in seen["connections"]}
    assert sorted(headers) == [
        ("/cmd_vel", "/left"),
        ("/cmd_vel", "/right"),
        ("/latched", "/static"),
    ]
    assert headers[("/latched", "/static")]["latching"] == "1"
    assert "latching" not in headers[("/cmd_vel", "/left")]
    assert headers[("/cmd_vel", "/left")]["type"] == "geometry_msgs/Twist"
    assert [row[1:] for row in seen["rows"][:4]] == [
        [0.0, "/right"],
        [1.0, "/left"],
        [2.0, "/right"],
        [3.0, "/left"],
    ]


def test_ros_reads_a_recording_that_was_cut_off_after_a_chunk_was_written_out(tmp_path, ros_python):
    bag = BagWriter(tmp_path / "live", chunk_seconds=60.0).open()
    for i in range(10):
        bag.write("/cmd_vel", Twist(linear=Vector3(x=i)), 100.0 + i)
    bag.flush()  # what the recorder does every second
    bag.write("/cmd_vel", Twist(linear=Vector3(x=10)), 110.0)  # still in memory
    killed = tmp_path / "killed.bag.active"
    killed.write_bytes(bag.active_path.read_bytes())
    bag.close()
    # an indexed file as it is: no 'rosbag reindex' needed
    rows = json.loads(_ros(ros_python, READ_ALL, str(killed)))["rows"]
    assert [row[1] for row in rows] == [float(i) for i in range(10)]


def test_ros_reindexes_an_unindexed_workbench_recording(tmp_path, ros_python):
    # rosbag rewrites the bag header in place: it must not overwrite the first chunk
    bag = BagWriter(tmp_path / "live", chunk_size=1024).open()
    for i in range(100):
        bag.write("/cmd_vel", Twist(linear=Vector3(x=i)), 100.0 + i)
    cut = tmp_path / "cut.bag"
    cut.write_bytes(bag.active_path.read_bytes())
    bag.close()
    written = len(list(read_messages(cut)))
    assert 0 < written < 100
    reindex = (
        "import sys, rosbag\n"
        "bag = rosbag.Bag(sys.argv[1], 'a', allow_unindexed=True)\n"
        "for _ in bag.reindex(): pass\n"
        "bag.close()\n"
    )
    _ros(ros_python, reindex, str(cut))
    rows = json.loads(_ros(ros_python, READ_ALL, str(cut)))["rows"]
    assert [row[1] for row in rows] == [float(i) for i in range(written)]
    assert [m.msg.linear.x for m in read_messages(cut)] == [float(i) for i in range(written)]


# --- empty bags: a recording in which nothing was published ---------------------------

ROS_INFO = (
    "import sys, rosbag\n"
    "bag = rosbag.Bag(sys.argv[1])\n"
    "print(bag)\n"
    "print(bag.get_message_count(), len(list(bag.read_messages())))\n"
)


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_workbench_reads_an_empty_bag_ros_writes(tmp_path, ros_python, compression, capsys):
    """rosbag closes an empty bag with its index at the very end of the file
    (``index_pos`` = file size, no connection or chunk records): a valid, empty bag."""
    from workbench.bag import summarize
    from workbench.cli import main

    script = "import sys, rosbag\nrosbag.Bag(sys.argv[1], 'w', compression=sys.argv[2]).close()\n"
    _ros(ros_python, script, str(tmp_path / "empty.bag"), compression)
    path = tmp_path / "empty.bag"
    assert list(read_messages(path)) == []
    summary = summarize(path)
    assert summary.message_count == 0 and summary.indexed and summary.damage is None
    # `rosbag info` prints rosbag's Bag.__str__: path, version and size, nothing else.
    ros_info = _ros(ros_python, ROS_INFO, str(path)).splitlines()
    assert ros_info[-1] == "0 0"
    assert main(["bag", "info", str(path)]) == 0
    assert capsys.readouterr().out.splitlines() == ros_info[:-1]


def test_ros_reads_an_empty_bag_workbench_writes(tmp_path, ros_python):
    path = tmp_path / "wb_empty.bag"
    with BagWriter(path):
        pass
    assert _ros(ros_python, ROS_INFO, str(path)).splitlines()[-1] == "0 0"
    _ros(
        ros_python,
        "import sys, rosbag\nrosbag.Bag(sys.argv[1], 'w').close()\n",
        str(tmp_path / "r.bag"),
    )
    assert path.read_bytes() == (tmp_path / "r.bag").read_bytes()  # rosbag's own bytes
