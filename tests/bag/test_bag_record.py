"""Recording from the bus: nothing received is lost, -a finds topics, the bag replays."""

from __future__ import annotations

import time

import pytest

from workbench.bag import play, read_messages, summarize
from workbench.bag.record import Recorder
from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist, Vector3
from workbench.msgs.turtlesim import Pose
from workbench.turtlesim.node import TurtlesimNode


@pytest.mark.parametrize("threaded", [False, True])
def test_recorder_loses_nothing(tmp_path, threaded):
    bus = Bus(threaded=threaded)
    talker = Node("talker", bus=bus, disable_rosout=True)
    pub = talker.create_publisher("/turtle1/pose", Pose)
    cmd = talker.create_publisher("/turtle1/cmd_vel", Twist)
    recorder = Recorder(
        Node("record", bus=bus, disable_rosout=True), tmp_path / "r.bag", all_topics=True
    )
    assert sorted(recorder.poll_topics()) == ["/turtle1/cmd_vel", "/turtle1/pose"]
    for i in range(5000):
        pub.publish(Pose(x=float(i)))
        if i % 10 == 0:
            cmd.publish(Twist(linear=Vector3(x=float(i))))
    path = recorder.close()
    bus.shutdown()
    assert summarize(path).topic_counts() == {"/turtle1/cmd_vel": 500, "/turtle1/pose": 5000}
    xs = [m.msg.x for m in read_messages(path, ["/turtle1/pose"])]
    assert xs == [float(i) for i in range(5000)]


def test_recorder_named_topics_and_exclude(tmp_path):
    bus = Bus(threaded=False)
    talker = Node("talker", bus=bus, disable_rosout=True)
    talker.create_publisher("/a", Pose).publish(Pose())
    talker.create_publisher("/b", Pose)
    node = Node("record", bus=bus, disable_rosout=True)
    named = Recorder(node, tmp_path / "n.bag", topics=["/b", "/later"])
    assert named.poll_topics() == ["/b"]
    named.close()
    everything = Recorder(node, tmp_path / "x.bag", all_topics=True, exclude="^/a$")
    assert everything.poll_topics() == ["/b"]
    everything.close()
    bus.shutdown()


def test_recorded_turtle_replays_the_same_poses(tmp_path):
    bus = Bus(threaded=False)
    sim = TurtlesimNode(Node("turtlesim", bus=bus, disable_rosout=True), start_timer=False)
    user = Node("user", bus=bus, disable_rosout=True)
    recorder = Recorder(
        Node("record", bus=bus, disable_rosout=True),
        tmp_path / "t.bag",
        topics=["/turtle1/cmd_vel", "/turtle1/pose"],
    )
    cmd = user.create_publisher("/turtle1/cmd_vel", Twist)
    recorder.poll_topics()
    for i in range(60):
        if i % 20 == 0:
            cmd.publish(Twist(linear=Vector3(x=2.0), angular=Vector3(z=1.8)))
        while bus.spin_once(0.0):
            pass
        sim.step()
    path = recorder.close()
    recorded = [m.msg for m in read_messages(path, ["/turtle1/pose"])]
    assert len(recorded) == 60
    # replay the commands into a fresh turtlesim stepped at the same moments
    bus2 = Bus(threaded=False)
    sim2 = TurtlesimNode(Node("turtlesim", bus=bus2, disable_rosout=True), start_timer=False)
    commands = [m for m in read_messages(path) if m.topic == "/turtle1/cmd_vel"]
    poses = [m for m in read_messages(path) if m.topic == "/turtle1/pose"]
    replayed = []
    pending = list(commands)
    for pose in poses:
        while pending and pending[0].stamp_ns <= pose.stamp_ns:
            c = pending.pop(0).msg
            sim2.sim.turtle("turtle1").command_velocity(c.linear.x, c.angular.z, sim2.sim.time)
        sim2.step()
        replayed.append(sim2.sim.turtle("turtle1").pose)
    flat = [v for p in replayed for v in (p.x, p.y, p.theta)]
    assert flat == pytest.approx([v for p in recorded for v in (p.x, p.y, p.theta)], abs=1e-5)
    assert recorded[-1].x != recorded[0].x  # the turtle did move
    # and play() publishes them in order
    seen = []
    clock = {"t": 0.0}
    play(
        path,
        lambda t, ty, m: seen.append(t),
        delay=0.0,
        sleep=lambda s: clock.__setitem__("t", clock["t"] + s),
        now=lambda: clock["t"],
    )
    assert len(seen) == 63
    bus.shutdown()
    bus2.shutdown()


def test_a_connection_per_publisher_with_its_name_and_latching_and_none_for_silent_topics(
    tmp_path,
):
    bus = Bus(threaded=False)
    first = Node("first", bus=bus)  # nodes advertise /rosout, and log nothing here
    second = Node("second", bus=bus)
    static = first.create_publisher("/tf_static", "tf2_msgs/TFMessage", latch=True)
    static.publish(static.data_class())
    poses = [node.create_publisher("/turtle1/pose", Pose) for node in (first, second)]
    recorder = Recorder(Node("record", bus=bus), tmp_path / "c.bag", all_topics=True)
    assert "/rosout" in recorder.poll_topics()
    for i in range(3):
        for pub in poses:
            pub.publish(Pose(x=float(i)))
    while bus.spin_once(0.0):
        pass
    summary = summarize(recorder.close())
    bus.shutdown()
    stored = sorted((c.topic, c.callerid, c.latching) for c in summary.connections.values())
    assert stored == [
        ("/tf_static", "/first", True),
        ("/turtle1/pose", "/first", False),
        ("/turtle1/pose", "/second", False),
    ]
    assert summary.topic_counts() == {"/tf_static": 1, "/turtle1/pose": 6}


def test_recorder_writes_chunks_out_while_it_runs(tmp_path, monkeypatch):
    from workbench.bag import record

    monkeypatch.setattr(record, "CHUNK_SECONDS", 0.1)
    bus = Bus(threaded=False)
    pub = Node("talker", bus=bus, disable_rosout=True).create_publisher("/turtle1/pose", Pose)
    recorder = Recorder(
        Node("record", bus=bus, disable_rosout=True), tmp_path / "w.bag", topics=["/turtle1/pose"]
    )
    recorder.poll_topics()
    for i in range(5):
        pub.publish(Pose(x=float(i)))
    active = tmp_path / "w.bag.active"
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and summarize(active).message_count < 5:
        time.sleep(0.05)  # no more messages: the flusher thread writes the chunk out
    summary = summarize(active)  # what a killed recorder would leave
    assert summary.indexed and summary.message_count == 5
    assert [m.msg.x for m in read_messages(active)] == [0.0, 1.0, 2.0, 3.0, 4.0]
    pub.publish(Pose(x=5.0))
    path = recorder.close()
    bus.shutdown()
    assert [m.msg.x for m in read_messages(path)] == [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
