"""``from workbench.compat import tf``: tf's Python API on a bus, in one process."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.bus import Bus, Node
from workbench.compat import tf
from workbench.msgs import Duration, Time
from workbench.msgs.geometry_msgs import PointStamped


@pytest.fixture
def bus():
    b = Bus(threaded=False)
    yield b
    b.shutdown()


def test_module_layout_matches_tf():
    assert tf.transformations.quaternion_from_euler(0, 0, 0).tolist() == [0, 0, 0, 1]
    from workbench.compat.tf.transformations import euler_from_quaternion

    assert euler_from_quaternion([0, 0, 0, 1]) == (0.0, 0.0, 0.0)
    for name in ("LookupException", "ConnectivityException", "ExtrapolationException"):
        assert issubclass(getattr(tf, name), tf.Exception)
    assert issubclass(tf.TimeoutException, tf.Exception)


def test_send_and_lookup_with_leading_slashes(bus):
    node = Node("turtle1_tf_broadcaster", bus=bus)
    br = tf.TransformBroadcaster(node=node)
    listener = tf.TransformListener(node=Node("listener", bus=bus))
    q = tf.transformations.quaternion_from_euler(0, 0, 1.056)
    br.sendTransform((3.984, 2.351, 0), q, Time(10), "turtle1", "world")
    br.sendTransform((1.0, 1.0, 0), (0, 0, 0, 1), Time(10), "/turtle2", "/world")
    bus.spin_until(lambda: listener.frameExists("turtle2"), timeout=2)
    trans, rot = listener.lookupTransform("/world", "/turtle1", Time(0))
    assert trans == pytest.approx([3.984, 2.351, 0.0])
    assert rot == pytest.approx(list(q))
    assert isinstance(trans, list) and isinstance(rot, list)
    # turtle1 seen from turtle2 (Experiment 4's tf_echo turtle1 turtle2 setting)
    trans, _ = listener.lookupTransform("turtle2", "turtle1", Time(0))
    assert trans == pytest.approx([2.984, 1.351, 0.0])
    assert listener.canTransform("/turtle2", "/turtle1", Time(0))
    assert listener.getLatestCommonTime("turtle1", "turtle2") == Time(10)
    assert sorted(listener.getFrameStrings()) == ["turtle1", "turtle2", "world"]
    assert "Frame turtle1 exists with parent world." in listener.allFramesAsString()
    assert '"world" -> "turtle1"' in listener.allFramesAsDot()
    # the lab's broadcaster builds a TransformBroadcaster per callback: one publisher per node
    assert tf.TransformBroadcaster(node=node)._broadcaster is br._broadcaster


def test_lab_exceptions(bus):
    listener = tf.TransformListener(node=Node("listener", bus=bus))
    with pytest.raises(tf.LookupException):
        listener.lookupTransform("/turtle2", "/turtle1", Time(0))
    br = tf.TransformBroadcaster(node=Node("b", bus=bus))
    br.sendTransform((0, 0, 0), (0, 0, 0, 1), Time(10), "turtle1", "world")
    br.sendTransform((0, 0, 0), (0, 0, 0, 1), Time(10), "turtle3", "elsewhere")
    bus.spin_until(lambda: listener.frameExists("turtle3"), timeout=2)
    with pytest.raises(tf.ConnectivityException):
        listener.lookupTransform("turtle3", "turtle1", Time(0))
    with pytest.raises(tf.ExtrapolationException):
        listener.lookupTransform("world", "turtle1", Time(20))
    # waitForTransform past its timeout: the manual catches it as tf.Exception
    with pytest.raises(tf.Exception, match="Timed out after 0.1 s"):
        listener.waitForTransform("/world", "/turtle1", Time(20), Duration(0, 100_000_000))


def test_wait_for_transform_spins_a_stepped_bus(bus):
    """On Bus(threaded=False) the waiting call itself delivers the queued /tf messages."""
    listener = tf.TransformListener(node=Node("listener", bus=bus))
    br = tf.TransformBroadcaster(node=Node("b", bus=bus))
    br.sendTransform((1, 0, 0), (0, 0, 0, 1), Time(5), "base_laser", "base_link")
    assert not listener.frameExists("base_laser")  # queued, not yet delivered
    listener.waitForTransform("base_link", "base_laser", Time(5), Duration(2))
    assert listener.canTransform("base_link", "base_laser", Time(5))


def test_transform_point_and_matrices(bus):
    listener = tf.TransformListener(node=Node("listener", bus=bus))
    br = tf.TransformBroadcaster(node=Node("robot_tf_publisher", bus=bus))
    br.sendTransform((0.1, 0.0, 0.2), (0, 0, 0, 1), Time(3), "base_laser", "base_link")
    bus.spin_until(lambda: listener.frameExists("base_laser"), timeout=2)
    p = PointStamped()
    p.header.frame_id = "base_laser"
    p.point.x, p.point.y = 1.0, 0.2
    out = listener.transformPoint("base_link", p)
    assert out.header.frame_id == "base_link"
    assert (out.point.x, out.point.y, out.point.z) == pytest.approx((1.1, 0.2, 0.2))
    m = listener.asMatrix("base_link", p.header)
    np.testing.assert_allclose(m @ [1.0, 0.2, 0.0, 1.0], [1.1, 0.2, 0.2, 1.0])
    m2 = listener.fromTranslationRotation(
        (1, 2, 3), tf.transformations.quaternion_about_axis(math.pi, (0, 0, 1))
    )
    np.testing.assert_allclose(m2 @ [1, 0, 0, 1], [0, 2, 3, 1], atol=1e-12)


def test_lookup_transform_full_time_travel(bus):
    listener = tf.TransformListener(node=Node("listener", bus=bus))
    br = tf.TransformBroadcaster(node=Node("b", bus=bus))
    for t in range(1, 11):
        br.sendTransform((float(t), 0, 0), (0, 0, 0, 1), Time(t), "turtle1", "world")
        br.sendTransform((0, 1.0, 0), (0, 0, 0, 1), Time(t), "turtle2", "world")
    listener.waitForTransformFull("/turtle2", Time(10), "/turtle1", Time(5), "/world", Duration(2))
    trans, _ = listener.lookupTransformFull("/turtle2", Time(10), "/turtle1", Time(5), "/world")
    assert trans == pytest.approx([5.0, -1.0, 0.0])
    assert listener.canTransformFull("turtle2", Time(10), "turtle1", Time(5), "world")
