"""``bag play`` timing: original spacing scaled by -r, the -d delay, -l loops and --clock.

rosbag play waits 0.2 s after advertising by default and publishes /clock every
10 ms of wall time with --clock (its --hz default of 100).
"""

from __future__ import annotations

import pytest

from workbench.bag import BagWriter, play
from workbench.errors import BagError
from workbench.msgs.turtlesim import Pose

T0 = 1700000000.0


class FakeClock:
    def __init__(self) -> None:
        self.t = 0.0

    def now(self) -> float:
        return self.t

    def sleep(self, s: float) -> None:
        assert s >= 0
        self.t += s


@pytest.fixture
def bag(tmp_path):
    with BagWriter(tmp_path / "p.bag") as writer:
        for i in range(5):
            writer.write("/turtle1/pose", Pose(x=float(i)), T0 + i * 0.5)
    return writer.path


def _run(bag, **kwargs):
    clock = FakeClock()
    seen = []
    report = play(
        bag,
        lambda topic, typename, msg: seen.append((clock.t, topic, typename, msg.x)),
        sleep=clock.sleep,
        now=clock.now,
        **kwargs,
    )
    return report, seen


def test_original_timing_after_the_default_delay(bag):
    report, seen = _run(bag)
    assert report.published == 5
    assert [s[0] for s in seen] == pytest.approx([0.2 + 0.5 * i for i in range(5)])
    assert [s[3] for s in seen] == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert seen[0][1:3] == ("/turtle1/pose", "turtlesim/Pose")


def test_rate_and_delay(bag):
    _, seen = _run(bag, rate=2.0, delay=1.0)
    assert [s[0] for s in seen] == pytest.approx([1.0 + 0.25 * i for i in range(5)])


def test_start_offset_skips_the_beginning(bag):
    _, seen = _run(bag, start=1.0, delay=0.0)
    assert [s[3] for s in seen] == [2.0, 3.0, 4.0]
    assert seen[0][0] == pytest.approx(0.0)


def test_loop(bag):
    report, seen = _run(bag, loop=True, max_loops=3, delay=0.0)
    assert report.loops == 3
    assert [s[3] for s in seen] == [0.0, 1.0, 2.0, 3.0, 4.0] * 3


def test_clock_publishes_bag_time_every_10ms(bag):
    clock = FakeClock()
    ticks = []
    play(
        bag,
        lambda *a: None,
        clock=lambda ns: ticks.append((clock.t, ns)),
        sleep=clock.sleep,
        now=clock.now,
        delay=0.0,
        rate=2.0,
    )
    # 2 s of bag at 2x is 1 s of wall: about 100 ticks, bag time advancing twice as fast
    assert 95 <= len(ticks) <= 110
    wall, stamp = ticks[50]
    assert (stamp / 1e9 - T0) == pytest.approx(2.0 * wall, abs=1e-6)


def test_bad_rate(bag):
    with pytest.raises(BagError, match="rate must be positive"):
        _run(bag, rate=0.0)
