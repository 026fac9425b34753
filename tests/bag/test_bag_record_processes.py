"""``workbench bag record`` against publishers in other processes, checked with ROS's rosbag.

* A latched publisher that starts while recording is stored once, on a
  connection with the publisher's ``callerid`` and ``latching=1``, as
  ``rosbag record`` stores it; a silent topic (``/rosout``) leaves no connection.
* A recorder killed with SIGKILL keeps all but about the last second of what
  it received (its chunks are written out every second).
* A latched message that arrives both live and as the latched reply reaches
  a subscription once.

ROS's rosbag (``/usr/bin/python3``, Debian's python3-rosbag) reads the bags;
those checks skip (fail under WORKBENCH_REQUIRE_ALL=1) without it.
"""

from __future__ import annotations

import json
import signal
import subprocess
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from process_helpers import Processes, core_processes
from skipping import ros_python

from workbench.bag import read_messages, summarize

pytestmark = pytest.mark.multiprocess

LATCHED_PUBLISHER = """
from workbench.compat import rospy
from workbench.msgs.geometry_msgs import TransformStamped
from workbench.msgs.tf2_msgs import TFMessage

rospy.init_node("static_pub")
pub = rospy.Publisher("/tf_static", TFMessage, queue_size=10, latch=True)
pub.publish(TFMessage(transforms=[TransformStamped(child_frame_id="base")]))
print("published", flush=True)
rospy.spin()
"""

COUNTER = """
import os
import sys
from pathlib import Path
from workbench.compat import rospy
from workbench.msgs.std_msgs import Int64

rospy.init_node("counter")
pub = rospy.Publisher("/count", Int64, queue_size=100)
last = Path(sys.argv[1])
draft = last.with_suffix(".tmp")
rate = rospy.Rate(50)
i = 0
while not rospy.is_shutdown():
    pub.publish(Int64(i))
    draft.write_text(str(i))
    os.replace(draft, last)  # what has been published so far, never half-written
    i += 1
    rate.sleep()
"""


@pytest.fixture
def procs(tmp_path: Path) -> Iterator[Processes]:
    """A private ``workbench core`` on a free loopback port, and children joined to it."""
    with core_processes(tmp_path) as processes:
        yield processes


def _ros_reads(path: Path) -> dict:
    """What ROS's rosbag sees in ``path``: its connections' headers and the messages' topics."""
    script = (
        "import json, sys, rosbag\n"
        "bag = rosbag.Bag(sys.argv[1])\n"
        "conns = [{k: v.decode() for k, v in c.header.items() if k != 'message_definition'}\n"
        "         for c in bag._connections.values()]\n"
        "topics = [t for t, m, s in bag.read_messages(raw=True)]\n"
        "info = bag.get_type_and_topic_info()\n"
        "print(json.dumps({'connections': conns, 'topics': topics,\n"
        "                  'count': bag.get_message_count(), 'info_topics': sorted(info.topics)}))\n"
    )
    done = subprocess.run(
        [ros_python("rosbag", "python3-rosbag"), "-c", script, str(path)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_latched_publisher_started_while_recording_is_stored_once_as_rosbag_does(procs):
    recorder = procs.start("-m", "workbench", "bag", "record", "-a", "-O", "x", name="record")
    procs.wait_output(recorder, "Recording to")
    publisher = procs.start("-c", LATCHED_PUBLISHER, name="static_pub")
    procs.wait_output(publisher, "published")
    procs.wait_output(recorder, "Subscribing to /tf_static")
    time.sleep(1.0)  # a duplicate (live and latched reply) would have arrived by now
    recorder.send_signal(signal.SIGTERM)  # finishes the bag as Ctrl-C does
    recorder.wait(30)
    bag = procs.tmp / "x.bag"
    assert bag.is_file() and not (procs.tmp / "x.bag.active").exists(), procs.output(recorder)
    summary = summarize(bag)
    assert summary.indexed
    # one connection per topic that has messages: none for the silent /rosout
    assert summary.topic_counts() == {"/tf_static": 1}
    (conn,) = summary.connections.values()
    assert (conn.callerid, conn.latching) == ("/static_pub", True)
    seen = _ros_reads(bag)
    assert seen["topics"] == ["/tf_static"] and seen["count"] == 1
    (header,) = seen["connections"]
    assert header["callerid"] == "/static_pub"
    assert header["latching"] == "1"
    assert header["topic"] == "/tf_static" and header["type"] == "tf2_msgs/TFMessage"


def test_recorder_killed_outright_keeps_all_but_the_last_second(procs):
    last = procs.tmp / "last.txt"
    procs.start("-c", COUNTER, str(last), name="counter")
    recorder = procs.start("-m", "workbench", "bag", "record", "-O", "k", "/count", name="record")
    procs.wait_output(recorder, "Subscribing to /count")
    time.sleep(3.5)
    recorder.send_signal(signal.SIGKILL)
    published = int(last.read_text())  # the counter's last message when the recorder died
    recorder.wait(10)
    active = procs.tmp / "k.bag.active"
    assert active.is_file() and not (procs.tmp / "k.bag").exists()
    values = [m.msg.data for m in read_messages(active)]
    assert len(values) >= 50, f"{len(values)} messages of {published}"
    assert values == list(range(values[0], values[0] + len(values)))  # no gap, in order
    # at most about 1 s (50 messages) is lost; 75 leaves room for a busy machine
    assert published - values[-1] <= 75, (published, values[-1])
    # ROS reads the killed recording too: as it is when its index is current (nearly
    # always), after 'rosbag reindex' when killed while a chunk was being written
    if not summarize(active).indexed:
        script = (
            "import sys, rosbag\n"
            "bag = rosbag.Bag(sys.argv[1], 'a', allow_unindexed=True)\n"
            "for _ in bag.reindex(): pass\n"
            "bag.close()\n"
        )
        done = subprocess.run(
            [ros_python("rosbag", "python3-rosbag"), "-c", script, str(active)], capture_output=True
        )
        assert done.returncode == 0, done.stderr
    seen = _ros_reads(active)
    assert seen["count"] == len(values)


def test_latched_message_arriving_live_and_as_latched_reply_is_delivered_once(procs, monkeypatch):
    from workbench.bus import Bus, Node
    from workbench.bus.zenoh_transport import ZenohTransport
    from workbench.msgs.std_msgs import String

    fetch = ZenohTransport._fetch_latched_now

    def late_fetch(self, sub):  # the latched reply is asked for after the message went live
        time.sleep(0.5)
        fetch(self, sub)

    monkeypatch.setattr(ZenohTransport, "_fetch_latched_now", late_fetch)
    with Bus.connect(procs.uri) as pub_bus, Bus.connect(procs.uri) as sub_bus:
        pub = Node("latcher", bus=pub_bus).create_publisher("/latched", String, latch=True)
        pub.publish(String(data="before"))
        got: list[str] = []
        raw: list[tuple[str, bool]] = []
        listener = Node("listener", bus=sub_bus)
        listener.create_subscription("/latched", String, lambda m: got.append(m.data))
        listener.create_subscription(
            "/latched", String, lambda m: raw.append((m.callerid, m.latching)), raw=True
        )
        time.sleep(0.2)  # the subscriptions reached the publisher's session
        pub.publish(String(data="live"))
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and not (len(got) >= 1 and len(raw) >= 1):
            time.sleep(0.05)
        time.sleep(1.0)  # the latched replies (0.5 s late) have been answered by now
    assert got == ["live"]
    assert raw == [("/latcher", True)]
