"""Behaviour of the frame buffer, ported from tf2's own unit tests.

Each test names the upstream test it ports (ros/geometry2 on GitHub):
``tf2/test/cache_unittest.cpp`` (TimeCache), ``tf2/test/static_cache_test.cpp``,
``tf2/test/simple_tf2_core.cpp``, ``test_tf2/test/buffer_core_test.cpp`` (BufferCore),
``test_tf2/test/test_static_publisher.cpp``, and tf's ``tf_unittest.cpp`` whose
BufferCore checks tf2 kept. Expected values are computed independently with
scipy's Rotation, never with the buffer's own composition code.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.errors import TransformError
from workbench.msgs import Time
from workbench.tf import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformDataWarning,
    TransformException,
)

IDENTITY_Q = (0.0, 0.0, 0.0, 1.0)
NS = 1e-9  # one nanosecond, in seconds


def put(buf, parent, child, t, xyz=(0.0, 0.0, 0.0), q=IDENTITY_Q, static=False):
    assert buf.set_transform_values(parent, child, xyz, q, t, "authority", static=static)


def pose_matrix(xyz, q):
    m = np.identity(4)
    m[:3, :3] = Rotation.from_quat(q).as_matrix()
    m[:3, 3] = xyz
    return m


def assert_pose(result, xyz, q, tol=1e-9):
    np.testing.assert_allclose(result.translation, xyz, atol=tol)
    # q and -q are the same rotation
    got = np.asarray(result.rotation)
    want = np.asarray(q, dtype=float)
    assert min(np.abs(got - want).max(), np.abs(got + want).max()) < max(tol, 1e-9)


# --- set_transform refusals: buffer_core_test.cpp BufferCore_setTransform.* ---------------


def test_valid_transform_is_accepted():
    """simple_tf2_core.cpp tf2.setTransformValid: a complete transform is stored."""
    buf = BufferCore()
    assert buf.set_transform_values("foo", "child", (0, 0, 0), IDENTITY_Q, 1.0)
    assert buf.frame_exists("child") and buf.frame_exists("foo")


def test_default_transform_is_refused():
    """simple_tf2_core.cpp tf2.setTransformFail: an all-default transform is refused."""
    buf = BufferCore()
    with pytest.warns(TransformDataWarning) as record:
        assert not buf.set_transform_values("", "", (0, 0, 0), (0, 0, 0, 0), 0)
    text = " ".join(str(w.message) for w in record)
    assert "TF_NO_CHILD_FRAME_ID" in text and "TF_NO_FRAME_ID" in text
    assert "TF_DENORMALIZED_QUATERNION" in text


def test_no_insert_on_self_transform():
    """BufferCore_setTransform.NoInsertOnSelfTransform."""
    buf = BufferCore()
    with pytest.warns(TransformDataWarning, match='TF_SELF_TRANSFORM.*"same_frame"'):
        assert not buf.set_transform_values("same_frame", "same_frame", (0, 0, 0), IDENTITY_Q, 1e-8)


def test_no_insert_with_nan():
    """BufferCore_setTransform.NoInsertWithNan: NaN is refused after a valid insert."""
    buf = BufferCore()
    assert buf.set_transform_values("same_frame", "other_frame", (0, 0, 0), IDENTITY_Q, 1e-8)
    with pytest.warns(TransformDataWarning, match='TF_NAN_INPUT.*"other_frame"'):
        assert not buf.set_transform_values(
            "same_frame", "other_frame", (math.nan, 0, 0), IDENTITY_Q, 2e-8
        )
    # the refused value is not stored: only the first stamp is there
    assert buf.lookup("same_frame", "other_frame", 1e-8).translation == (0.0, 0.0, 0.0)
    with pytest.raises(ExtrapolationException):
        buf.lookup("same_frame", "other_frame", 2e-8)


def test_no_insert_with_no_frame_id():
    """BufferCore_setTransform.NoInsertWithNoFrameID: child "" and "/" are refused."""
    buf = BufferCore()
    for child in ("", "/"):
        with pytest.warns(TransformDataWarning, match="TF_NO_CHILD_FRAME_ID"):
            assert not buf.set_transform_values("same_frame", child, (0, 0, 0), IDENTITY_Q, 1.0)


def test_no_insert_with_no_parent_id():
    """BufferCore_setTransform.NoInsertWithNoParentID: parent "" and "/" are refused."""
    buf = BufferCore()
    for parent in ("", "/"):
        with pytest.warns(TransformDataWarning, match='TF_NO_FRAME_ID.*"some_frame"'):
            assert not buf.set_transform_values(parent, "some_frame", (0, 0, 0), IDENTITY_Q, 1.0)


def test_denormalized_quaternion_is_refused_but_small_error_is_normalised():
    """tf2 BufferCore::setTransform: |q|^2 off by >= 0.01 is TF_DENORMALIZED_QUATERNION."""
    buf = BufferCore()
    with pytest.warns(TransformDataWarning, match="TF_DENORMALIZED_QUATERNION"):
        assert not buf.set_transform_values("a", "b", (0, 0, 0), (0, 0, 0, 2.0), 1.0)
    assert buf.set_transform_values("a", "b", (0, 0, 0), (0, 0, 0, 1.004), 1.0)
    assert buf.lookup("a", "b", 1.0).rotation == (0.0, 0.0, 0.0, 1.0)


def test_leading_slash_is_stripped_on_insert():
    """tf2 BufferCore::setTransform strips a leading '/' from both frame ids."""
    buf = BufferCore()
    put(buf, "/world", "/turtle1", 1.0, (1, 2, 0))
    assert buf.frame_exists("world") and buf.frame_exists("turtle1")
    assert not buf.frame_exists("/world")


# --- TimeCache: cache_unittest.cpp --------------------------------------------------------


def test_repeatability_and_reverse_insert_order():
    """TimeCache.Repeatability / RepeatabilityReverseInsertOrder: exact stamps return what was stored."""
    for order in (range(1, 100), range(99, 0, -1)):
        buf = BufferCore()
        for i in order:
            put(buf, "p", "c", i * NS, (float(i), 0, 0))
        for i in range(1, 100):
            r = buf.lookup("p", "c", i * NS)
            assert r.translation[0] == float(i) and r.stamp_ns == i


def test_zero_at_front_means_latest():
    """TimeCache.ZeroAtFront: time 0 gives the newest entry, which moves as data arrives."""
    buf = BufferCore()
    for i in range(1, 101):
        put(buf, "p", "c", i * NS, (float(i), 0, 0))
    r = buf.lookup("p", "c", 0)
    assert r.translation[0] == 100.0 and r.stamp_ns == 100
    put(buf, "p", "c", 101 * NS, (101.0, 0, 0))
    assert buf.lookup("p", "c", 0).stamp_ns == 101


def test_cartesian_interpolation():
    """TimeCache.CartesianInterpolation: translation is linear between two stamps."""
    rng = np.random.default_rng(0)
    for _ in range(20):
        buf = BufferCore()
        values = rng.uniform(-10, 10, size=(2, 3))
        for step in range(2):
            put(buf, "p", "c", (200 + step * 100) * NS, values[step])
        for pos in range(0, 101, 7):
            got = buf.lookup("p", "c", (200 + pos) * NS).translation
            np.testing.assert_allclose(
                got, values[0] + (values[1] - values[0]) * pos / 100, atol=2e-6
            )


def test_angular_interpolation_is_slerp():
    """TimeCache.AngularInterpolation / Bullet.Slerp: rotation follows the slerp of the ends."""
    from scipy.spatial.transform import Slerp

    rng = np.random.default_rng(1)
    for _ in range(20):
        buf = BufferCore()
        rots = Rotation.from_euler("xyz", rng.uniform(-1.5, 1.5, size=(2, 3)))
        for step in range(2):
            put(buf, "p", "c", (200 + step * 100) * NS, (0, 0, 0), rots[step].as_quat())
        truth = Slerp([0.0, 1.0], rots)
        for pos in range(0, 101, 9):
            got = Rotation.from_quat(buf.lookup("p", "c", (200 + pos) * NS).rotation)
            assert (truth(pos / 100) * got.inv()).magnitude() < 1e-6
        # the midpoint is equidistant from both ends (Bullet.Slerp)
        mid = Rotation.from_quat(buf.lookup("p", "c", 250 * NS).rotation)
        d0 = (rots[0] * mid.inv()).magnitude()
        d1 = (rots[1] * mid.inv()).magnitude()
        assert abs(d0 - d1) < 1e-6


def test_slerp_takes_the_short_way_round():
    """tf2::slerp uses the shortest arc even when the stored quaternions have opposite signs."""
    buf = BufferCore()
    q0 = Rotation.from_euler("z", 0.1).as_quat()
    q1 = -Rotation.from_euler("z", 0.3).as_quat()  # same rotation as +q, opposite sign
    put(buf, "p", "c", 1.0, q=q0)
    put(buf, "p", "c", 2.0, q=q1)
    yaw = Rotation.from_quat(buf.lookup("p", "c", 1.5).rotation).as_euler("xyz")[2]
    assert yaw == pytest.approx(0.2, abs=1e-9)


def test_reparenting_interpolation_protection():
    """TimeCache.ReparentingInterpolationProtection: no interpolation across a parent change."""
    buf = BufferCore()
    put(buf, "world", "other", 1.0)
    put(buf, "world", "c", 555 * NS, (1.0, 2.0, 3.0))
    put(buf, "other", "c", 655 * NS, (7.0, 8.0, 9.0))
    for pos in range(0, 100, 11):
        assert buf.get_parent("c", (555 + pos) * NS) == "world"
        assert buf.lookup("world", "c", (555 + pos) * NS).translation == (1.0, 2.0, 3.0)
    assert buf.get_parent("c", 655 * NS) == "other"


def test_duplicate_entries_are_refused_without_nan():
    """TimeCache.DuplicateEntries: a repeated stamp leaves valid data (tf2 warns TF_REPEATED_DATA)."""
    buf = BufferCore()
    put(buf, "p", "c", 1 * NS, (1.0, 0, 0))
    with pytest.warns(TransformDataWarning, match="TF_REPEATED_DATA.*frame c"):
        assert not buf.set_transform_values("p", "c", (5.0, 0, 0), IDENTITY_Q, 1 * NS)
    r = buf.lookup("p", "c", 1 * NS)
    assert r.translation == (1.0, 0.0, 0.0)
    assert not any(math.isnan(v) for v in (*r.translation, *r.rotation))


def test_cache_time_prunes_and_refuses_old_data():
    """TimeCache::insertData/pruneList: keep cache_time behind the newest; refuse older (TF_OLD_DATA)."""
    buf = BufferCore(cache_time=10.0)
    for i in range(0, 31):
        put(buf, "p", "c", float(i), (float(i), 0, 0))
    # 30 is newest: everything older than 20 is gone
    with pytest.raises(ExtrapolationException, match="into the past.*earliest data is at time 20"):
        buf.lookup("p", "c", 15.0)
    assert buf.lookup("p", "c", 20.0).translation[0] == 20.0
    with pytest.warns(TransformDataWarning, match="TF_OLD_DATA.*frame c at time 5"):
        assert not buf.set_transform_values("p", "c", (0, 0, 0), IDENTITY_Q, 5.0)
    # inside the window an out-of-order stamp is accepted and interpolated around
    assert buf.set_transform_values("p", "c", (100.0, 0, 0), IDENTITY_Q, 25.5)
    assert buf.lookup("p", "c", 25.5).translation[0] == 100.0


def test_large_history_compacts_and_still_answers():
    """tf2 pruning with many entries: lookups stay exact after the list is compacted."""
    buf = BufferCore(cache_time=1.0)
    for i in range(5000):
        put(buf, "p", "c", i * 0.001, (float(i), 0, 0))
    assert buf.lookup("p", "c", 4.5).translation[0] == pytest.approx(4500.0)
    with pytest.raises(ExtrapolationException):
        buf.lookup("p", "c", 3.9)


# --- extrapolation limits: tf_unittest.cpp (tf) ------------------------------------------------


def test_extrapolation_from_one_value():
    """tf.ExtrapolationFromOneValue: one stamp answers only that stamp and time 0."""
    buf = BufferCore()
    put(buf, "parent", "child", 10.0)
    buf.lookup("parent", "child", 10.0)
    buf.lookup("parent", "child", 0)
    with pytest.raises(ExtrapolationException, match="only time 10.000000000 is in the buffer"):
        buf.lookup("parent", "child", 11.0)
    with pytest.raises(ExtrapolationException, match=r"from frame \[child\] to frame \[parent\]"):
        buf.lookup("parent", "child", 9.0)


def test_extrapolation_into_future_and_past_name_times_and_frames():
    """tf.Exceptions: before the oldest / after the newest stamp raise ExtrapolationException."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 100.0)
    put(buf, "world", "turtle1", 101.0)
    with pytest.raises(ExtrapolationException) as future:
        buf.lookup("world", "turtle1", 102.0)
    text = str(future.value)
    assert "into the future" in text and "102.000000000" in text and "101.000000000" in text
    assert "[turtle1]" in text and "[world]" in text
    with pytest.raises(ExtrapolationException, match="into the past.*99.5"):
        buf.lookup("world", "turtle1", 99.5)
    assert isinstance(future.value, TransformError)


def test_no_extrapolation_exception_from_parent():
    """tf.NoExtrapolationExceptionFromParent: siblings with data at the same stamps interpolate."""
    buf = BufferCore()
    for t in (1000 * NS, 10000 * NS):
        put(buf, "parent", "a", t, (1.0, 0, 0))
        put(buf, "parent", "b", t, (1.0, 0, 0))
    r = buf.lookup("a", "b", 5000 * NS)
    assert_pose(r, (0, 0, 0), IDENTITY_Q)


# --- lookups in tree configurations: buffer_core_test.cpp BufferCore_lookupTransform.* --------


@pytest.mark.parametrize("interpolation_space", [0.0, 1.0])
def test_i_configuration(interpolation_space):
    """BufferCore_lookupTransform.i_configuration: a->b->c, each +1 in x, at and between stamps."""
    buf = BufferCore()
    t = 10.0
    for parent, child in (("a", "b"), ("b", "c")):
        put(buf, parent, child, t - interpolation_space / 2, (1.0, 0, 0))
        if interpolation_space:
            put(buf, parent, child, t + interpolation_space / 2, (1.0, 0, 0))
    expected = {("a", "b"): 1, ("a", "c"): 2, ("b", "c"): 1, ("b", "a"): -1, ("c", "a"): -2}
    for (target, source), x in expected.items():
        assert_pose(buf.lookup(target, source, t), (x, 0, 0), IDENTITY_Q)
        assert_pose(buf.lookup(target, source, 0), (x, 0, 0), IDENTITY_Q)
    assert_pose(buf.lookup("a", "a", t), (0, 0, 0), IDENTITY_Q)


def _ring45(buf, t, interpolation_space=0.0):
    """buffer_core_test.cpp setupTree("ring_45"): 8 links of 45 degrees on the unit circle.

    Both chains start at ``a``: ``a->b->...->i`` turning left and
    ``a->inverse_b->...->inverse_i`` turning right.
    """
    frames = "abcdefghi"
    for prefix, direction in (("inverse_", -1.0), ("", 1.0)):
        for i in range(1, len(frames)):
            xyz = (direction * (math.sqrt(2) / 2 - 1), direction * math.sqrt(2) / 2, 0.0)
            q = (0.0, 0.0, math.sin(direction * math.pi / 8), math.cos(direction * math.pi / 8))
            parent = prefix + frames[i - 1] if i > 1 else frames[0]
            child = prefix + frames[i]
            stamps = [t - interpolation_space / 2]
            if interpolation_space:
                stamps.append(t + interpolation_space / 2)
            for s in stamps:
                put(buf, parent, child, s, xyz, q)
    return frames


def _ring_truth(buf_edges, target, source):
    """World poses by independent matrix products along the known edges."""
    world = {}

    def pose_of(frame):
        if frame not in world:
            if frame not in buf_edges:
                world[frame] = np.identity(4)
            else:
                parent, m = buf_edges[frame]
                world[frame] = pose_of(parent) @ m
        return world[frame]

    return np.linalg.inv(pose_of(target)) @ pose_of(source)


@pytest.mark.parametrize("interpolation_space", [0.0, 2.0])
def test_ring_45_configuration(interpolation_space):
    """BufferCore_lookupTransform.ring_45: every pair of the 17-frame ring matches matrix products."""
    buf = BufferCore()
    t = 50.0
    frames = _ring45(buf, t, interpolation_space)
    edges = {}
    for prefix, direction in (("inverse_", -1.0), ("", 1.0)):
        for i in range(1, len(frames)):
            xyz = (direction * (math.sqrt(2) / 2 - 1), direction * math.sqrt(2) / 2, 0.0)
            q = (0.0, 0.0, math.sin(direction * math.pi / 8), math.cos(direction * math.pi / 8))
            parent = prefix + frames[i - 1] if i > 1 else frames[0]
            edges[prefix + frames[i]] = (parent, pose_matrix(xyz, q))
    names = buf.get_frame_strings()
    assert len(names) == 17
    for target in names:
        for source in names:
            r = buf.lookup(target, source, t)
            truth = _ring_truth(edges, target, source)
            np.testing.assert_allclose(pose_matrix(r.translation, r.rotation), truth, atol=1e-9)
    # 8 steps of 45 degrees come back to the start: a == i
    assert_pose(buf.lookup("a", "i", t), (0, 0, 0), IDENTITY_Q, tol=1e-9)
    # half way round: e is at (-2, 0) and turned by 180 degrees
    assert_pose(buf.lookup("a", "e", t), (-2, 0, 0), (0, 0, 1, 0), tol=1e-9)


def test_lookup_inverse_and_compound_are_consistent():
    """tf.ListOneInverse/ListTwoForward/TransformThrougRoot: random chains vs matrix products."""
    rng = np.random.default_rng(7)
    buf = BufferCore()
    edges = {}
    for parent, child in (("my_parent", "child"), ("child", "grandchild"), ("my_parent", "childB")):
        xyz = rng.uniform(-10, 10, 3)
        q = Rotation.random(random_state=rng).as_quat()
        put(buf, parent, child, 1.0, xyz, q)
        edges[child] = (parent, pose_matrix(xyz, q))
    for target, source in (
        ("my_parent", "grandchild"),
        ("grandchild", "my_parent"),
        ("grandchild", "childB"),
        ("childB", "grandchild"),
    ):
        r = buf.lookup(target, source, 1.0)
        np.testing.assert_allclose(
            pose_matrix(r.translation, r.rotation), _ring_truth(edges, target, source), atol=1e-9
        )


# --- errors: frames, connectivity, loops, arguments ----------------------------------------


def test_lookup_nothing_exists():
    """simple_tf2_core / buffer_core_test LookupException_Nothing_Exists: unknown frames."""
    buf = BufferCore()
    with pytest.raises(
        LookupException, match='"a" passed to lookupTransform argument target_frame does not exist'
    ):
        buf.lookup("a", "b", 1.0)
    assert buf.can_lookup("a", "b", 1.0)[0] is False


def test_lookup_one_exists():
    """LookupException_One_Exists: a known target with an unknown source names the source."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 1.0)
    with pytest.raises(
        LookupException, match='"turtle3" passed to lookupTransform argument source_frame'
    ) as exc:
        buf.lookup("world", "turtle3", 1.0)
    assert "known frames: turtle1, world" in str(exc.value)


def test_identity_for_a_frame_to_itself():
    """BufferCore::lookupTransform short-circuit: target == source is the identity, even unknown."""
    buf = BufferCore()
    r = buf.lookup("nowhere", "nowhere", 3.0)
    assert_pose(r, (0, 0, 0), IDENTITY_Q)
    assert r.stamp_ns == 3_000_000_000
    put(buf, "world", "turtle1", 7.0)
    assert buf.lookup("turtle1", "turtle1", 0).stamp_ns == 7_000_000_000
    assert buf.can_lookup("nowhere", "nowhere")[0]


def test_disconnected_trees_raise_connectivity():
    """tf.TransformThroughNO_PARENT / tf2 CONNECTIVITY_ERROR: two unconnected trees."""
    buf = BufferCore()
    put(buf, "a", "b", 1.0)
    put(buf, "c", "d", 1.0)
    with pytest.raises(
        ConnectivityException, match="between 'b' and 'd'.*not part of the same tree"
    ):
        buf.lookup("b", "d", 1.0)
    with pytest.raises(ConnectivityException):
        buf.lookup("b", "d", 0)


def test_loop_is_a_lookup_error():
    """tf2 walkToTopParent: a loop in the frame graph raises LookupException, never hangs."""
    buf = BufferCore()
    put(buf, "a", "b", 1.0)
    put(buf, "b", "c", 1.0)
    put(buf, "c", "a", 1.0)
    put(buf, "x", "y", 1.0)
    with pytest.raises(LookupException, match="contains a loop"):
        buf.lookup("y", "b", 1.0)
    with pytest.raises(LookupException, match="contains a loop"):
        buf.lookup("y", "b", 0)


@pytest.mark.parametrize("bad", ["", "/world"])
def test_invalid_frame_arguments(bad):
    """tf2 validateFrameId: empty ids and ids starting with '/' are InvalidArgumentException."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 1.0)
    with pytest.raises(InvalidArgumentException, match="target_frame"):
        buf.lookup(bad, "turtle1", 1.0)
    with pytest.raises(InvalidArgumentException, match="source_frame"):
        buf.lookup("turtle1", bad, 1.0)


def test_invalid_time_argument():
    buf = BufferCore()
    put(buf, "world", "turtle1", 1.0)
    with pytest.raises(InvalidArgumentException, match="time must be"):
        buf.lookup("world", "turtle1", "yesterday")
    with pytest.raises(InvalidArgumentException, match="finite"):
        buf.lookup("world", "turtle1", math.nan)


# --- static frames: static_cache_test.cpp, test_static_publisher.cpp -----------------------------


def test_static_transform_is_valid_at_all_times():
    """StaticCache.Repeatability + StaticTranformPublsher.a_b_different_times."""
    buf = BufferCore()
    put(buf, "a", "b", 0, (1.0, 0, 0), static=True)
    put(buf, "b", "c", 5.0, (0, 1.0, 0), static=True)
    for t in (0, 1e-9, 100.0, 1000.0):
        assert_pose(buf.lookup("a", "c", t), (1, 1, 0), IDENTITY_Q)
    assert buf.lookup("a", "c", 0).stamp_ns == 0


def test_static_then_dynamic_link_a_d_different_times():
    """StaticTranformPublsher.a_d_different_times: static a->c plus dynamic c->d at 10."""
    buf = BufferCore()
    put(buf, "a", "b", 0, static=True)
    put(buf, "b", "c", 0, static=True)
    put(buf, "c", "d", 10.0)
    assert buf.can_lookup("c", "d", 10.0)[0]
    assert buf.can_lookup("a", "d", 0)[0]
    assert not buf.can_lookup("a", "d", 1.0)[0]
    assert buf.can_lookup("a", "d", 10.0)[0]
    assert not buf.can_lookup("a", "d", 100.0)[0]
    assert buf.lookup("a", "d", 0).stamp_ns == 10_000_000_000


def test_static_reparenting_replaces_the_old_parent():
    """StaticTranformPublsher.multiple_parent_test: re-sent static d with a new parent."""
    buf = BufferCore()
    put(buf, "a", "c", 0, static=True)
    put(buf, "c", "d", 10.0, static=True)
    assert buf.can_lookup("a", "d", 0)[0] and buf.can_lookup("a", "d", 1000.0)[0]
    put(buf, "new_parent", "d", 10.0, static=True)
    put(buf, "new_parent", "other_child", 10.0, static=True)
    assert buf.can_lookup("new_parent", "d", 0)[0]
    assert buf.can_lookup("new_parent", "other_child", 0)[0]
    assert not buf.can_lookup("a", "d", 0)[0]


# --- time zero and the latest common time: BufferCore::getLatestCommonTime ----------------------


def test_time_zero_is_latest_common_time_along_the_path():
    """tf.getLatestCommonTime: the newest time every link between the frames has data for."""
    buf = BufferCore()
    for t in (1.0, 2.0, 3.0):
        put(buf, "world", "turtle1", t, (t, 0, 0))
    for t in (1.0, 2.0):
        put(buf, "world", "turtle2", t, (0, t, 0))
    put(buf, "turtle1", "carrot1", 0, (0, 2, 0), static=True)
    assert buf.get_latest_common_time("turtle2", "turtle1") == 2_000_000_000
    r = buf.lookup("turtle2", "carrot1", 0)
    assert r.stamp_ns == 2_000_000_000
    assert_pose(r, (2, 0, 0), IDENTITY_Q)  # turtle1 at x=2, carrot +2y; turtle2 at y=2
    # along a path that avoids turtle2, the latest is turtle1's newest
    assert buf.lookup("world", "carrot1", 0).stamp_ns == 3_000_000_000
    # an ancestor/descendant pair only involves the links between them
    assert buf.get_latest_common_time("turtle1", "carrot1") == 0


def test_time_travel_through_a_fixed_frame():
    """tf2 lookupTransform(target, target_time, source, source_time, fixed): the manual's 5 s ago."""
    buf = BufferCore()
    for t in range(0, 11):
        put(buf, "world", "turtle1", float(t), (float(t), 0, 0))
        put(buf, "world", "turtle2", float(t), (0, 1.0, 0))
    r = buf.lookup_full("turtle2", 10.0, "turtle1", 5.0, "world")
    assert_pose(r, (5, -1, 0), IDENTITY_Q)
    assert r.stamp_ns == 10_000_000_000
    with pytest.raises(LookupException, match="fixed_frame"):
        buf.lookup_full("turtle2", 10.0, "turtle1", 5.0, "map")


# --- introspection ---------------------------------------------------------------------------


def test_all_frames_as_yaml_and_string():
    """tf2 allFramesAsYAML / allFramesAsString: one entry per child frame with its parent."""
    buf = BufferCore()
    assert buf.all_frames_as_yaml() == "[]"
    for t in (1.0, 1.5, 2.0):
        buf.set_transform_values(
            "world", "turtle1", (0, 0, 0), IDENTITY_Q, t, "/turtle1_tf_broadcaster"
        )
    text = buf.all_frames_as_yaml()
    assert "turtle1: \n  parent: 'world'\n  broadcaster: '/turtle1_tf_broadcaster'\n" in text
    assert "  rate: 3.000\n" in text and "  most_recent_transform: 2.000\n" in text
    assert "  oldest_transform: 1.000\n" in text and "  buffer_length: 1.000\n" in text
    assert buf.all_frames_as_string() == "Frame turtle1 exists with parent world.\n"
    buf.clear()
    assert buf.all_frames_as_yaml() == "[]"
    assert buf.all_frames_as_string() == "Frame turtle1 exists with parent NO_PARENT.\n"
    with pytest.raises(ExtrapolationException) as exc:
        buf.lookup("world", "turtle1", 1.0)
    # tf2's cache gives no text when empty: only the walk's part remains
    assert str(exc.value).split("\n") == [
        ", when looking up transform from frame [turtle1] to frame [world]",
        "(frame 'turtle1' has no data: its cache is empty since a clear())",
    ]


def test_clear_keeps_static_transforms():
    """tf2's StaticCache::clearList does nothing: /tf_static data survives BufferCore::clear."""
    buf = BufferCore()
    put(buf, "base_link", "laser", 0, (0.1, 0, 0.2), static=True)
    put(buf, "odom", "base_link", 5.0, (1.0, 0, 0))
    buf.clear()
    assert buf.lookup("base_link", "laser", 0).translation == pytest.approx((0.1, 0, 0.2))
    with pytest.raises(ExtrapolationException):
        buf.lookup("odom", "laser", 5.0)


# --- tf2's checking order and texts (the differential test checks them against tf2) ------


def test_extrapolation_texts_carry_the_amount():
    """TimeCache::findClosest (Noetic): the past and future texts say by how much."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 100.0)
    put(buf, "world", "turtle1", 101.5)
    with pytest.raises(ExtrapolationException) as past:
        buf.lookup("world", "turtle1", 95.195468320)
    assert str(past.value).split("\n")[0] == (
        "Lookup would require extrapolation 4.804531680s into the past.  Requested time "
        "95.195468320 but the earliest data is at time 100.000000000, when looking up "
        "transform from frame [turtle1] to frame [world]"
    )
    with pytest.raises(ExtrapolationException) as future:
        buf.lookup("turtle1", "world", 102.0)
    assert str(future.value).split("\n")[0] == (
        "Lookup would require extrapolation 0.500000000s into the future.  Requested time "
        "102.000000000 but the latest data is at time 101.500000000, when looking up "
        "transform from frame [world] to frame [turtle1]"
    )


def test_epoch_times_print_as_ros_time_to_sec():
    """ros::Time::toSec is sec + 1e-9 * nsec in doubles: its digits, not those of ns / 1e9."""
    buf = BufferCore()
    put(buf, "world", "turtle1", Time(1_700_000_000, 123_456_789))
    with pytest.raises(ExtrapolationException) as exc:
        buf.lookup("world", "turtle1", Time(1_700_000_001, 0))
    assert "but only time 1700000000.123456717 is in the buffer," in str(exc.value)


def test_unknown_and_invalid_frames_first_line_is_tf2s():
    """validateFrameId's texts as the first line; workbench's hints on the second."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 1.0)
    with pytest.raises(LookupException) as exc:
        buf.lookup("world", "turtle3", 1.0)
    assert str(exc.value).split("\n") == [
        '"turtle3" passed to lookupTransform argument source_frame does not exist. ',
        "(known frames: turtle1, world)",
    ]
    with pytest.raises(InvalidArgumentException) as exc:
        buf.lookup("/world", "turtle1", 1.0)
    assert str(exc.value).split("\n") == [
        'Invalid argument "/world" passed to lookupTransform argument target_frame in tf2 '
        "frame_ids cannot start with a '/' like: ",
        "(use 'world')",
    ]


def test_target_walk_failure_is_reported_before_the_source_walk():
    """walkToTopParent: missing data on the target's way up fails at once.

    The source's walk stops at its own missing link and the target's walk then fails on
    its own: tf2 reports the target's link, not the source's.
    """
    buf = BufferCore()
    put(buf, "world", "turtle1", 10.0)
    put(buf, "world", "turtle2", 20.0)
    with pytest.raises(ExtrapolationException, match="only time 20.000000000 is in the buffer"):
        buf.lookup("turtle2", "turtle1", 15.0)
    with pytest.raises(ExtrapolationException, match="only time 10.000000000 is in the buffer"):
        buf.lookup("turtle1", "turtle2", 15.0)
    # a source link without data, the target in another tree: the extrapolation wins
    put(buf, "map", "robot", 10.0)
    put(buf, "map", "robot", 15.0)
    with pytest.raises(
        ExtrapolationException, match="from frame \\[turtle1\\] to frame \\[robot\\]"
    ):
        buf.lookup("robot", "turtle1", 15.0)
    with pytest.raises(ConnectivityException) as exc:
        buf.lookup("robot", "turtle1", 10.0)
    assert str(exc.value) == (
        "Could not find a connection between 'robot' and 'turtle1' because they are not part "
        "of the same tree.Tf has two or more unconnected trees."
    )


def test_lookup_full_validates_all_frames_then_looks_up_source_first():
    """BufferCore::lookupTransform with a fixed frame: target, source, fixed validated first;
    then source -> fixed at the source time, then fixed -> target at the target time."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 10.0)
    put(buf, "world", "turtle2", 10.0)
    put(buf, "map", "robot", 10.0)
    with pytest.raises(LookupException, match="argument target_frame"):
        buf.lookup_full("ghost", 10.0, "turtle1", 10.0, "nowhere")
    with pytest.raises(LookupException, match="argument fixed_frame"):
        buf.lookup_full("turtle2", 10.0, "turtle1", 10.0, "nowhere")
    # both halves fail: the source half is reported
    with pytest.raises(
        ExtrapolationException, match="from frame \\[turtle1\\] to frame \\[world\\]"
    ):
        buf.lookup_full("turtle2", 11.0, "turtle1", 12.0, "world")
    with pytest.raises(ConnectivityException, match="between 'world' and 'robot'"):
        buf.lookup_full("robot", 10.0, "robot", 10.0, "world")


def test_get_latest_common_time_errors_as_tf2_py():
    """tf2_py get_latest_common_time: unknown frames (even against themselves) are
    LookupException; disconnected frames the base TransformException."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 10.0)
    put(buf, "map", "robot", 10.0)
    with pytest.raises(LookupException) as exc:
        buf.get_latest_common_time("ghost", "ghost")
    assert (
        str(exc.value).split("\n")[0] == '"ghost" passed to get_latest_common_time does not exist. '
    )
    with pytest.raises(InvalidArgumentException, match="get_latest_common_time"):
        buf.get_latest_common_time("", "world")
    with pytest.raises(TransformException) as exc:
        buf.get_latest_common_time("world", "robot")
    assert type(exc.value) is TransformException
    assert "not part of the same tree" in str(exc.value)
    assert buf.get_latest_common_time("turtle1", "turtle1") == 10_000_000_000
    assert buf.get_latest_common_time("world", "world") == 0


def test_can_transform_strings_are_tf2s(caplog):
    """BufferCore::canTransform: its own texts for unknown frames, "" (and a logged
    warning) for empty or '/' frames, the lookup's text otherwise."""
    buf = BufferCore()
    put(buf, "world", "turtle1", 10.0)
    assert buf.can_transform_core("ghost", "spook", 10.0) == (
        False,
        "canTransform: target_frame ghost does not exist. "
        "canTransform: source_frame spook does not exist.",
    )
    with caplog.at_level("WARNING", logger="workbench.tf"):
        assert buf.can_transform_core("world", "/turtle1", 10.0) == (False, "")
    assert "cannot start with a '/'" in caplog.text
    assert buf.can_transform_core("", "", 10.0) == (True, "")  # target == source first
    ok, why = buf.can_transform_core("world", "turtle1", 11.0)
    assert not ok and why.startswith("Lookup would require extrapolation at time 11.000000000")
    assert buf.can_transform_full_core("world", 10.0, "turtle1", 10.0, "map") == (
        False,
        "fixed_frame: mapdoes not exist.",
    )
    assert buf.can_transform_full_core("world", 10.0, "turtle1", 10.0, "world") == (True, "")
    # can_lookup: the first line of what lookup() would raise (what tf_echo prints)
    assert buf.can_lookup("world", "ghost", 10.0) == (
        False,
        '"ghost" passed to lookupTransform argument source_frame does not exist. ',
    )


def test_lookup_full_quaternion_sign_is_tf2s():
    """tf2 composes the two halves as matrices: the result's quaternion has w > 0 when the
    rotation's trace is positive."""
    buf = BufferCore()
    half_turn = (0.0, 0.0, math.sin(0.4), math.cos(0.4))
    put(buf, "world", "a", 1.0, (0, 0, 0), half_turn)
    put(buf, "world", "b", 1.0, (0, 0, 0), (0.0, 0.0, -math.sin(0.4), -math.cos(0.4)))
    r = buf.lookup_full("a", 1.0, "b", 1.0, "world")
    assert r.rotation[3] > 0
    assert_pose(r, (0, 0, 0), IDENTITY_Q)
