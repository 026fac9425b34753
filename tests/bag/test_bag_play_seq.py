"""`bag play` sends the recorded header.seq, as rosbag play does (issue 14, item 3).

rosbag play publishes the recorded bytes; a rospy publisher would renumber seq 1, 2, 3.
"""

from __future__ import annotations

import time

from workbench.bag import BagWriter
from workbench.bag.session import play
from workbench.bus import Bus, Node, set_default_bus
from workbench.msgs.geometry_msgs import PoseStamped


def test_recorded_seq_survives_playback(tmp_path):
    path = tmp_path / "seq.bag"
    with BagWriter(path) as bag:
        for i, seq in enumerate((42, 7, 1000)):
            pose = PoseStamped()
            pose.header.seq = seq
            pose.header.frame_id = "map"
            bag.write("/pose", pose, 1000.0 + 0.01 * i)
    bus = Bus()
    set_default_bus(bus)
    try:
        heard: list = []
        Node("listener", bus=bus).create_subscription("/pose", PoseStamped, heard.append)
        assert play(str(path), delay=0.0, quiet=True) == 0
        deadline = time.monotonic() + 10
        while len(heard) < 3 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert [m.header.seq for m in heard] == [42, 7, 1000]
        # a publisher of one's own still numbers its messages, as rospy's does
        own = Node("talker", bus=bus).create_publisher("/pose", PoseStamped)
        own.publish(PoseStamped())
        deadline = time.monotonic() + 10
        while len(heard) < 4 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert heard[-1].header.seq == 1
    finally:
        set_default_bus(None)
        bus.shutdown()
