"""joint_state_publisher_gui: sliders read on the viewer's thread, messages published by a timer.

Drake's Meshcat answers only the thread that created it; a timer on the bus's
threads that polled it died silently and nothing was published (issue 14, item 9).
"""

from __future__ import annotations

import time

import pytest

from workbench.bus import Bus, Node
from workbench.msgs.sensor_msgs import JointState
from workbench.robot_state.joint_state_publisher import JointStatePublisher

_KEPT: list = []


def _viewer():
    from workbench.viz import Viewer

    if not _KEPT:
        _KEPT.append(Viewer())  # one per process: a Meshcat must die on its own thread
    _KEPT[0].clear()
    return _KEPT[0]


def test_slider_moves_reach_joint_states_from_the_timer():
    bus = Bus()
    viewer = _viewer()
    node = Node("joint_state_publisher", bus=bus)
    jsp = JointStatePublisher("arm3", node, rate=50.0, use_gui=True, viewer=viewer)
    heard: list = []
    Node("listener", bus=bus).create_subscription("joint_states", JointState, heard.append)
    slider = next(iter(jsp._sliders))
    joint = jsp._sliders[slider]
    viewer.meshcat.SetSliderValue(slider, 0.5)  # as a user dragging it
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        jsp.poll_gui()  # the node's main loop does this
        if heard and heard[-1].position[heard[-1].name.index(joint)] == pytest.approx(0.5):
            break
        time.sleep(0.02)
    assert heard, "the timer published nothing"
    assert heard[-1].position[heard[-1].name.index(joint)] == pytest.approx(0.5)
    count = len(heard)
    time.sleep(0.2)
    assert len(heard) > count  # the timer is still alive
    bus.shutdown()
