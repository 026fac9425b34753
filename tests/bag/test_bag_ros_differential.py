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
from skipping import skip_or_fail

from workbench.bag import BagWriter, read_messages
from workbench.msgs.geometry_msgs import Twist, Vector3

ROS_PYTHON = "/usr/bin/python3"


@pytest.fixture(scope="module")
def ros_python() -> str:
    try:
        done = subprocess.run([ROS_PYTHON, "-c", "import rosbag"], capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        done = None
    if done is None or done.returncode != 0:
        skip_or_fail("ROS 1's rosbag is not installed (apt-get install python3-rosbag)")
    return ROS_PYTHON


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
