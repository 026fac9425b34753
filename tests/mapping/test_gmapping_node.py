"""slam_gmapping on an in-process bus: a simulated robot with drifting odometry drives through
the demo rooms; the node publishes a latched, growing ``/map``, ``/map_metadata``, ``~entropy``
and a ``map -> odom`` transform that puts the robot where it truly is."""

from __future__ import annotations

import numpy as np
import pytest
from gmapping_feed import PARAMS, Feeder, drifting_odometry, start, wait_until

from workbench.bus import Node
from workbench.mapping.geometry import between, compose
from workbench.mapping.gmapping_node import SKIPPED_AT_START
from workbench.mapping.simulate import loop_trajectory
from workbench.msgs.nav_msgs import GetMap, MapMetaData, OccupancyGrid
from workbench.msgs.std_msgs import Float64
from workbench.tf import Buffer, TransformListener


def pose_of(t) -> np.ndarray:
    q = t.transform.rotation
    theta = 2 * np.arctan2(q.z, q.w)
    return np.array([t.transform.translation.x, t.transform.translation.y, theta])


def test_a_drive_through_the_rooms_maps_them_and_corrects_the_odometry(bus):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    feeder.mount()
    mapper = start(bus, PARAMS)
    truth = loop_trajectory(0.1)[:110]
    odom = drifting_odometry(truth)
    watcher = Node("watcher", bus=bus, disable_rosout=True)
    maps: list[OccupancyGrid] = []
    watcher.create_subscription("/map", OccupancyGrid, maps.append, 100)
    buffer = Buffer()
    TransformListener(buffer, watcher)
    errors, drift = [], []
    steps = [0] * SKIPPED_AT_START + list(range(len(truth)))
    for n, k in enumerate(steps):
        stamp = feeder.step(truth[k], odom[k])
        if n < SKIPPED_AT_START:
            continue
        assert wait_until(lambda n=n: mapper.processed == n - SKIPPED_AT_START + 1), n
        # the node's clock follows /clock on its own thread: publish once it reached the scan
        assert wait_until(lambda s=stamp: mapper.node.now().to_sec() >= s - 1e-9)
        mapper.publish_transform()
        assert wait_until(lambda s=stamp: buffer.can_transform("map", "base_link", s))
        estimate = pose_of(buffer.lookup_transform("map", "base_link", stamp))
        errors.append(np.hypot(*(estimate[:2] - truth[k][:2])))
        drift.append(np.hypot(*(odom[k][:2] - truth[k][:2])))
    assert max(drift) > 0.3  # odometry alone would be off by this much
    assert max(errors) < 0.1, max(errors)
    assert mapper.dropped == 0

    assert wait_until(lambda: len(maps) >= 3)
    first, last = maps[0], maps[-1]
    assert last.header.frame_id == "map"
    assert last.info.resolution == pytest.approx(0.05)
    known = [int((np.asarray(m.data) >= 0).sum()) for m in maps]
    assert known[-1] > 2 * known[0]  # the map grows as the robot explores
    assert (last.info.width, last.info.height) != (first.info.width, first.info.height)
    assert last.info.origin.position.x <= -2.0 and last.info.origin.position.y <= -2.0
    assert set(np.unique(np.asarray(last.data)).tolist()) <= {-1, 0, 100}

    # The walls of the demo rooms are where the map says (the room is 0..8 x 0..6 m).
    cells = np.asarray(last.data).reshape(last.info.height, last.info.width)
    rows, cols = np.nonzero(cells == 100)
    x = last.info.origin.position.x + (cols + 0.5) * last.info.resolution
    y = last.info.origin.position.y + (rows + 0.5) * last.info.resolution
    on_outer = (np.minimum(np.abs(x), np.abs(x - 8.0)) < 0.1) | (
        np.minimum(np.abs(y), np.abs(y - 6.0)) < 0.1
    )
    inside = (x > -0.1) & (x < 8.1) & (y > -0.1) & (y < 6.1)
    assert inside.mean() > 0.99 and on_outer.mean() > 0.6

    # Latched: a subscriber that comes late gets the latest map and metadata at once.
    late = Node("late", bus=bus, disable_rosout=True)
    got: list = []
    meta: list = []
    entropy: list = []
    late.create_subscription("/map", OccupancyGrid, got.append, 1)
    late.create_subscription("/map_metadata", MapMetaData, meta.append, 1)
    late.create_subscription("/slam_gmapping/entropy", Float64, entropy.append, 1)
    assert wait_until(lambda: got and meta and entropy)
    assert got[-1].info.width == maps[-1].info.width
    assert meta[-1].width == got[-1].info.width and meta[-1].height == got[-1].info.height
    assert np.isfinite(entropy[-1].data)
    response = late.create_client("/dynamic_map", GetMap).call(GetMap.Request(), timeout=5)
    assert response.map.info.width == got[-1].info.width


def test_the_transform_is_published_periodically_and_stamped_ahead(bus):
    feeder = Feeder(bus)
    feeder.tick(50.0)
    received: list = []
    watcher = Node("watcher", bus=bus, disable_rosout=True)
    from workbench.msgs.tf2_msgs import TFMessage

    watcher.create_subscription("/tf", TFMessage, received.append, 100)
    start(bus, {"transform_publish_period": 0.1, "tf_delay": 0.3})
    for k in range(1, 11):
        feeder.tick(50.0 + 0.1 * k)
        wait_until(lambda k=k: len(received) >= k, 2.0)
    transforms = [t for msg in received for t in msg.transforms]
    assert len(transforms) >= 5
    t = transforms[-1]
    assert (t.header.frame_id, t.child_frame_id) == ("map", "odom")
    assert pose_of(t) == pytest.approx(np.zeros(3))  # identity until the first scan
    assert t.header.stamp.to_sec() == pytest.approx(bus.clock.now().to_sec() + 0.3, abs=0.21)


def test_a_laser_mounted_upside_down_maps_the_same_room(bus, capsys):
    feeder = Feeder(bus)
    feeder.tick(feeder.t)
    feeder.mount(upside_down=True)
    mapper = start(bus, PARAMS)
    truth = loop_trajectory(0.1)[:30]
    for n, k in enumerate([0] * SKIPPED_AT_START + list(range(len(truth)))):
        msg = feeder.scan_msg(truth[k], 0.0)
        # Upside down, the beams sweep clockwise seen from above: reverse the readings.
        msg.ranges = np.asarray(msg.ranges)[(-np.arange(feeder.beams)) % feeder.beams]
        feeder.step(truth[k], truth[k], msg)
        if n >= SKIPPED_AT_START:
            assert wait_until(lambda n=n: mapper.processed == n - SKIPPED_AT_START + 1)
    assert "Laser is mounted upside down." in capsys.readouterr().out
    estimate = compose(mapper.map_to_odom(), truth[-1])
    assert np.hypot(*between(truth[-1], estimate)[:2]) < 0.05
