"""amcl's scan queue (its tf message filter) on its own: the newest ready scan goes first and
the older ones are dropped; scans older than the tf cache go at once, scans whose frame tf
cannot connect after a while; scans still waiting for their transform stay; the queue holds
at most 100 and drops the oldest."""

from __future__ import annotations

from workbench.navigation.amcl_scan_queue import (
    MISSING,
    NEVER,
    NO_TRANSFORM,
    OVERFLOW,
    QUEUE,
    READY,
    SUPERSEDED,
    WAIT,
    HeldScan,
    ScanQueue,
)


def held(n: int, frame: str = "laser", arrived: float = 0.0) -> HeldScan:
    return HeldScan(msg=n, frame=frame, arrived=arrived)


def by_stamp(states: dict[int, str]):
    """A status function: the scan's number -> its state (READY when not listed)."""
    looked: list[int] = []

    def status(scan: HeldScan) -> tuple[str, str]:
        looked.append(scan.msg)
        return states.get(scan.msg, READY), f"why {scan.msg}"

    return status, looked


def test_the_newest_ready_scan_goes_first_and_the_older_ones_are_dropped():
    queue = ScanQueue()
    for n in range(50):
        assert queue.add(held(n)) is None
    status, looked = by_stamp({})
    taken, dropped = queue.take(status, 0.0)
    assert taken is not None and taken.msg == 49
    assert [d.scan.msg for d in dropped] == list(range(49))
    assert {d.reason for d in dropped} == {SUPERSEDED}
    assert looked == [49]  # the older scans are not even looked at
    assert len(queue) == 0


def test_newer_scans_waiting_for_their_transform_stay():
    queue = ScanQueue()
    for n in range(5):
        queue.add(held(n))
    status, _ = by_stamp({4: WAIT, 3: WAIT})
    taken, dropped = queue.take(status, 0.0)
    assert taken is not None and taken.msg == 2
    assert [(d.scan.msg, d.reason) for d in dropped] == [(0, SUPERSEDED), (1, SUPERSEDED)]
    assert len(queue) == 2
    status, _ = by_stamp({4: WAIT})
    taken, dropped = queue.take(status, 0.0)
    assert taken is not None and taken.msg == 3 and dropped == []
    status, _ = by_stamp({4: WAIT})
    assert queue.take(status, 100.0) == (None, [])  # waiting for tf has no time limit
    assert len(queue) == 1


def test_scans_older_than_the_tf_cache_are_dropped_at_once():
    queue = ScanQueue(missing_wait=0.5)
    for n in range(3):
        queue.add(held(n, arrived=10.0))
    status, _ = by_stamp({0: NEVER, 1: NEVER, 2: WAIT})
    taken, dropped = queue.take(status, 10.0)
    assert taken is None
    assert [(d.scan.msg, d.reason, d.state, d.why) for d in dropped] == [
        (0, NO_TRANSFORM, NEVER, "why 0"),
        (1, NO_TRANSFORM, NEVER, "why 1"),
    ]
    assert len(queue) == 1


def test_a_frame_tf_cannot_connect_is_given_missing_wait_seconds():
    queue = ScanQueue(missing_wait=0.5)
    queue.add(held(0, frame="nowhere", arrived=10.0))
    status, _ = by_stamp({0: MISSING})
    assert queue.take(status, 10.4) == (None, [])
    taken, dropped = queue.take(status, 10.6)
    assert taken is None
    assert [(d.scan.frame, d.reason, d.state) for d in dropped] == [
        ("nowhere", NO_TRANSFORM, MISSING)
    ]
    assert len(queue) == 0


def test_a_full_queue_drops_the_oldest():
    queue = ScanQueue()
    for n in range(QUEUE):
        assert queue.add(held(n)) is None
    out = queue.add(held(QUEUE))
    assert out is not None and out.scan.msg == 0 and out.reason == OVERFLOW
    assert len(queue) == QUEUE
    status, _ = by_stamp({})
    taken, dropped = queue.take(status, 0.0)
    assert taken is not None and taken.msg == QUEUE and len(dropped) == QUEUE - 1
