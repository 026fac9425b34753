"""The World publishes /clock and /joint_states on a bus while it advances."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.sim import JointTrajectory, World


def test_publishes_clock_and_joint_states():
    from workbench.bus import Bus, Node
    from workbench.msgs.rosgraph_msgs import Clock
    from workbench.msgs.sensor_msgs import JointState

    bus = Bus(threaded=False)  # callbacks run only when spun: deterministic
    states: list = []
    clocks: list = []
    listener = Node("listener", bus=bus)
    listener.create_subscription("/joint_states", JointState, states.append, queue_size=1000)
    listener.create_subscription("/clock", Clock, clocks.append, queue_size=1000)

    world = World(bus=bus, publish_period=0.01)
    world.add_robot("arm3")
    world.build()
    names = world.joint_names("arm3")
    t = np.array([0.0, 0.5])
    q = np.array([[0.0, 0.0, 0.0], [0.3, 0.0, 0.0]])
    world.track_trajectory("arm3", JointTrajectory(names, t, q, np.zeros_like(q)), settle_time=0.0)
    while bus.spin_once(0.0):
        pass

    assert len(clocks) == pytest.approx(51, abs=1)
    stamps = [c.clock.to_sec() for c in clocks]
    assert stamps == sorted(stamps)
    assert stamps[-1] == pytest.approx(0.5, abs=0.011)
    assert len(states) == len(clocks)
    last = states[-1]
    assert list(last.name) == names
    assert last.position[0] == pytest.approx(0.3, abs=0.01)
    assert last.header.stamp.to_sec() == pytest.approx(stamps[-1])
