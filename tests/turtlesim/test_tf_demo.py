"""Experiment 4 in one process on simulated time (workbench.turtlesim.tf_demo): deterministic checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.turtlesim.tf_demo import TurtleTfDemo

CENTER = 5.544445


@pytest.fixture
def demo():
    d = TurtleTfDemo(turtle1_cmd=(0.0, 0.0))
    yield d
    d.close()


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def test_follow_turtle1_then_the_fixed_carrot(demo):
    demo.run(8.0)
    assert demo.errors == []
    assert dist(demo.pose("turtle2"), (CENTER, CENTER)) < 0.1
    demo.add_carrot(moving=False)
    demo.run(8.0, follow="carrot1")
    assert dist(demo.pose("turtle2"), (CENTER, CENTER + 2.0)) < 0.1
    # tf agrees with turtlesim about where the turtles are
    st = demo.buffer.lookup("world", "turtle2", 0)
    assert dist(st.translation, demo.pose("turtle2")) < 0.05


def test_moving_carrot_circles_turtle1(demo):
    demo.add_carrot(moving=True)
    demo.run(1.0)
    radii = []
    for _ in range(5):
        demo.run(0.2)
        st = demo.buffer.lookup("turtle1", "carrot1", 0)
        radii.append(math.hypot(*st.translation[:2]))
        t = st.stamp_ns / 1e9 * math.pi
        assert st.translation[0] == pytest.approx(2 * math.sin(t))
    np.testing.assert_allclose(radii, 2.0)


def test_manual_time_travel_waits_for_history_then_moves(demo):
    """Experiment 4.5: for 5 s there is no history (ExtrapolationException), then turtle2 moves."""
    demo.turtle1_cmd = (1.0, 0.5)
    demo.run(4.0, follow="turtle1", delay=5.0)
    assert demo.errors and all("ExtrapolationException" in e for e in demo.errors)
    assert dist(demo.pose("turtle2"), (4.0, 2.0)) < 1e-6
    demo.run(2.0, follow="turtle1", delay=5.0)  # history exists from t = 105 s
    demo.errors.clear()
    demo.run(2.0, follow="turtle1", delay=5.0)
    assert demo.errors == []
    assert dist(demo.pose("turtle2"), (4.0, 2.0)) > 0.5


def test_time_travel_full_goes_where_turtle1_was(demo):
    """lookupTransformFull through world: turtle2 chases turtle1's pose of 5 s ago."""
    demo.turtle1_cmd = (1.0, 0.5)
    rows = demo.run(20.0, follow="turtle1", delay=5.0, fixed_frame="world")
    t = rows[:, 0]
    now_gaps, past_gaps = [], []
    for row in rows[t > t[-1] - 5.0]:
        past = rows[np.argmin(np.abs(t - (row[0] - 5.0)))]
        now_gaps.append(math.hypot(row[3] - row[1], row[4] - row[2]))
        past_gaps.append(math.hypot(row[3] - past[1], row[4] - past[2]))
    # over the last 5 s turtle2 stays near where turtle1 was, far from where it is
    assert np.mean(past_gaps) < 0.5 * np.mean(now_gaps)
