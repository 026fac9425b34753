"""The message-facing Buffer: TransformStamped in and out, transform(), waiting lookups."""

from __future__ import annotations

import math
import threading

import pytest

from workbench.msgs import Duration, Time
from workbench.msgs.geometry_msgs import (
    PointStamped,
    PoseStamped,
    QuaternionStamped,
    TransformStamped,
    Vector3Stamped,
)
from workbench.tf import (
    Buffer,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformDataWarning,
)
from workbench.tf import transformations as tft


def stamped(parent, child, t, xyz=(0.0, 0.0, 0.0), q=(0.0, 0.0, 0.0, 1.0)):
    m = TransformStamped()
    m.header.frame_id = parent
    m.header.stamp = Time(float(t)) if t else Time()
    m.child_frame_id = child
    m.transform.translation.x, m.transform.translation.y, m.transform.translation.z = xyz
    r = m.transform.rotation
    r.x, r.y, r.z, r.w = (float(v) for v in q)
    return m


def robot_setup_buffer():
    """Additional Experiment 2: base_laser is 10 cm forward and 20 cm above base_link."""
    buf = Buffer()
    assert buf.set_transform(stamped("base_link", "base_laser", 0, (0.1, 0.0, 0.2)), "robot_tf")
    return buf


def test_set_and_lookup_messages():
    buf = Buffer(cache_time=Duration(5))
    assert buf.cache_time == 5.0
    assert buf.set_transform(stamped("world", "turtle1", 10.0, (1, 2, 0)), "turtle1_tf_broadcaster")
    assert buf.set_transform(stamped("world", "turtle1", 11.0, (3, 2, 0)), "turtle1_tf_broadcaster")
    out = buf.lookup_transform("world", "turtle1", Time(10.5))
    assert out._type == "geometry_msgs/TransformStamped"
    assert out.header.frame_id == "world" and out.child_frame_id == "turtle1"
    assert out.header.stamp == Time(10, 500_000_000)
    assert out.transform.translation.x == pytest.approx(2.0)
    latest = buf.lookup_transform("world", "turtle1", Time())
    assert latest.header.stamp == Time(11)
    assert buf.can_transform("world", "turtle1", Time(10.5))
    assert buf.can_transform("world", "turtle1", Time(12.0), return_debug_tuple=True)[0] is False


def test_bad_message_refused_with_warning():
    buf = Buffer()
    with pytest.warns(TransformDataWarning, match="TF_NAN_INPUT"):
        assert not buf.set_transform(stamped("a", "b", 1.0, (math.nan, 0, 0)), "x")
    with pytest.raises(InvalidArgumentException, match="TransformStamped"):
        buf.set_transform("not a message", "x")


def test_transform_point_robot_setup_tf():
    """The manual's line: base_laser: (1.00, 0.20, 0.00) -----> base_link: (1.10, 0.20, 0.20)."""
    buf = robot_setup_buffer()
    p = PointStamped()
    p.header.frame_id = "base_laser"
    p.point.x, p.point.y, p.point.z = 1.0, 0.2, 0.0
    out = buf.transform(p, "base_link")
    assert out._type == "geometry_msgs/PointStamped"
    assert out.header.frame_id == "base_link"
    assert (round(out.point.x, 2), round(out.point.y, 2), round(out.point.z, 2)) == (1.1, 0.2, 0.2)


def test_transform_pose_vector_quaternion():
    buf = Buffer()
    q = tft.quaternion_from_euler(0, 0, math.pi / 2)
    buf.set_transform(stamped("world", "robot", 0, (1.0, 0.0, 0.0), q), "x")
    pose = PoseStamped()
    pose.header.frame_id = "robot"
    pose.pose.position.x = 1.0
    pose.pose.orientation.w = 1.0
    out = buf.transform(pose, "world")
    assert (out.pose.position.x, out.pose.position.y) == pytest.approx((1.0, 1.0))
    assert tft.euler_from_quaternion(
        [
            out.pose.orientation.x,
            out.pose.orientation.y,
            out.pose.orientation.z,
            out.pose.orientation.w,
        ]
    )[2] == pytest.approx(math.pi / 2)
    v = Vector3Stamped()
    v.header.frame_id = "robot"
    v.vector.x = 1.0
    out_v = buf.transform(v, "world")  # vectors rotate but do not translate
    assert (out_v.vector.x, out_v.vector.y, out_v.vector.z) == pytest.approx((0.0, 1.0, 0.0))
    qs = QuaternionStamped()
    qs.header.frame_id = "robot"
    qs.quaternion.w = 1.0
    out_q = buf.transform(qs, "world")
    assert [out_q.quaternion.z, out_q.quaternion.w] == pytest.approx(list(q[2:]))
    with pytest.raises(InvalidArgumentException, match="does not know how to transform"):
        buf.transform(stamped("robot", "x", 0), "world")


def test_transform_points_array():
    buf = robot_setup_buffer()
    pts = buf.transform_points([[1.0, 0.2, 0.0], [0.0, 0.0, 0.0]], "base_link", "base_laser")
    assert pts.ravel().tolist() == pytest.approx([1.1, 0.2, 0.2, 0.1, 0.0, 0.2])


def test_lookup_without_timeout_raises_core_errors():
    buf = robot_setup_buffer()
    with pytest.raises(LookupException, match="turtle1"):
        buf.lookup_transform("base_link", "turtle1", Time())


def test_waiting_lookup_raises_the_core_error_after_its_timeout():
    """tf2_ros Buffer.lookup_transform(timeout): can_transform waits, then the core lookup raises.

    The exception is the one tf2 raises without waiting (never TimeoutException), with
    tf2's text; a second line says how long it waited.
    """
    buf = Buffer()
    buf.set_transform(stamped("world", "turtle1", 10.0), "x")
    with pytest.raises(ExtrapolationException) as exc:
        buf.lookup_transform("world", "turtle1", Time(20.0), timeout=Duration(0, 50_000_000))
    assert str(exc.value).split("\n") == [
        "Lookup would require extrapolation at time 20.000000000, but only time 10.000000000 "
        "is in the buffer, when looking up transform from frame [turtle1] to frame [world]",
        "(no data for frame 'turtle1' in 'world' at that time)",
        "(still failing after waiting 0.05 s)",
    ]
    assert not buf.can_transform("world", "turtle2", Time(), timeout=0.05)
    assert buf.can_transform("world", "turtle2", Time(), timeout=0.05, return_debug_tuple=True) == (
        False,
        "canTransform: source_frame turtle2 does not exist.",
    )
    with pytest.raises(LookupException, match="fixed_frame does not exist. \n") as exc:
        buf.lookup_transform_full("world", 0, "turtle1", 0, "map", timeout=0.05)
    assert str(exc.value).endswith("(still failing after waiting 0.05 s)")


def test_waiting_lookup_succeeds_when_data_arrives_from_another_thread():
    buf = Buffer()
    buf.set_transform(stamped("world", "turtle1", 1.0), "x")

    def later():
        buf.set_transform(stamped("world", "turtle1", 2.0, (5.0, 0, 0)), "x")

    timer = threading.Timer(0.05, later)
    timer.start()
    try:
        out = buf.lookup_transform("world", "turtle1", Time(2.0), timeout=5.0)
    finally:
        timer.join()
    assert out.transform.translation.x == 5.0


def test_waiting_uses_the_buffer_clock_and_a_stopped_clock_cannot_hang():
    buf = Buffer()
    frozen = 1_000_000_000
    buf.use_clock(lambda: frozen)  # a simulated clock that never advances
    with pytest.raises(LookupException, match="the clock stopped while waiting"):
        buf.lookup_transform("world", "turtle1", 0, timeout=0.05)
    ok, why = buf.can_transform("world", "turtle1", 0, timeout=0.05, return_debug_tuple=True)
    assert not ok
    assert (
        why
        == "canTransform: target_frame world does not exist. canTransform: source_frame turtle1 does not exist.\n(the clock stopped while waiting)"
    )


def test_lookup_full_message():
    buf = Buffer()
    for t in range(1, 11):
        buf.set_transform(stamped("world", "turtle1", t, (float(t), 0, 0)), "a")
        buf.set_transform(stamped("world", "turtle2", t, (0, 1.0, 0)), "b")
    out = buf.lookup_transform_full("turtle2", Time(10), "turtle1", Time(5), "world")
    assert (out.transform.translation.x, out.transform.translation.y) == pytest.approx((5, -1))
    assert buf.can_transform_full("turtle2", Time(10), "turtle1", Time(5), "world")
    assert not buf.can_transform_full("turtle2", Time(10), "turtle1", Time(50), "world")
    with pytest.raises(ExtrapolationException):
        buf.lookup_transform_full("turtle2", Time(10), "turtle1", Time(50), "world")


def test_waiting_timeout_is_measured_in_simulated_time():
    """With /use_sim_time the timeout counts simulated seconds (tf2_ros uses ros::Time)."""
    from workbench.bus import Bus, Node
    from workbench.tf import TransformBroadcaster, TransformListener
    from workbench.tf.broadcaster import make_transform

    bus = Bus()
    try:
        bus.clock.use_sim_time(True)
        bus.clock.set_time(100_000_000_000)
        buf = Buffer()
        TransformListener(buf, Node("listener", bus=bus))
        br = TransformBroadcaster(Node("broadcaster", bus=bus))
        stop = threading.Event()

        def simulate():  # 10x faster than real time; the transform appears at t = 102 s
            t = 100_000_000_000
            while not stop.is_set():
                t += 100_000_000
                bus.clock.set_time(t)
                if t == 102_000_000_000:
                    br.send_transform(
                        make_transform("world", "turtle1", (1, 0, 0), (0, 0, 0, 1), t / 1e9)
                    )
                stop.wait(0.01)

        sim = threading.Thread(target=simulate, daemon=True)
        sim.start()
        # 1 simulated second passes in about 0.1 s of wall time: too short
        with pytest.raises(LookupException, match="still failing after waiting 1 s"):
            buf.lookup_transform("world", "turtle1", Time(102), timeout=Duration(1))
        out = buf.lookup_transform("world", "turtle1", Time(102), timeout=Duration(5))
        assert out.transform.translation.x == 1.0
        stop.set()
        sim.join()
    finally:
        bus.shutdown()
