"""amcl with bad input: a scan frame tf does not know, NaN and inf readings, scans before the
map, a base frame that is not in the tree, negative ranges, a map in another frame and
parameters of the wrong type. Each gets amcl's (or tf2's) line and the node keeps running."""

from __future__ import annotations

import numpy as np
import pytest
from amcl_feed import (
    Output,
    Robot,
    amcl_map,
    bus,
    initial_guess,
    loaded_map,
    noisy_odometry,
    serve_map,
    start,
    tour,
    wait_until,
)

from workbench.bus import Node
from workbench.mapping.map_server_node import MapServer
from workbench.navigation.amcl_params import AmclError, read_params

__all__ = ["bus"]  # the fixture


def robot_with_map(bus) -> Robot:
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    return robot


def test_a_scan_frame_without_a_transform_is_dropped_with_a_warning(bus, capsys):
    robot = robot_with_map(bus)
    amcl = start(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    pose = tour()[0]
    output = Output(capsys)
    for _ in range(2):
        robot.step(pose, pose, robot.scan_msg(pose, 0.0, frame="nowhere"))
        assert amcl.wait_idle()
    assert amcl.dropped == 2 and amcl.processed == 0
    assert output.has(
        "MessageFilter [target=odom]: Dropped 100.00% of messages so far. Please turn the "
        "[ros.amcl.message_notifier] rosconsole logger to DEBUG for more information."
    )
    assert output.has('scans in frame "nowhere" are dropped: no transform to "odom"')
    assert output.text.count('scans in frame "nowhere"') == 1  # once per frame
    robot.step(pose, pose)  # the laser's own frame: amcl goes on
    assert amcl.wait_idle()
    assert amcl.processed == 1 and amcl.map_to_odom() is not None


def test_nan_and_inf_readings_are_skipped(bus):
    robot = robot_with_map(bus)
    truth = tour()[:200]
    odom = noisy_odometry(truth)
    amcl = start(bus, {"max_particles": 2000, **initial_guess(truth[0])})
    assert wait_until(lambda: amcl.localizer is not None)
    rng = np.random.default_rng(3)
    for k in range(len(truth)):
        msg = robot.scan_msg(truth[k], 0.0)
        ranges = np.asarray(msg.ranges).copy()
        ranges[rng.choice(len(ranges), 60, replace=False)] = np.nan
        ranges[rng.choice(len(ranges), 20, replace=False)] = np.inf
        ranges[:5] = 0.01  # below range_min: read as range_max, so skipped
        msg.ranges = ranges.astype(np.float32)
        robot.step(truth[k], odom[k], msg)
        assert amcl.wait_idle()
    assert amcl.processed == len(truth)
    pf = amcl.localizer.pf
    assert np.isfinite(pf.weights).all() and np.isfinite(pf.poses).all()
    estimate = amcl.last_estimate
    pose = pf.best_cluster().mean
    assert estimate is not None
    assert np.hypot(*(pose[:2] - truth[-1][:2])) < 0.15


def test_scans_before_the_map_are_ignored_and_the_map_is_requested_again(bus, capsys):
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    amcl = start(bus)
    output = Output(capsys)
    assert output.has("Requesting the map...")
    assert output.has("Request for map failed; trying again...")
    pose = tour()[0]
    robot.step(pose, pose)
    assert amcl.wait_idle()
    assert amcl.received == 1 and amcl.processed == 0 and amcl.localizer is None
    serve_map(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    assert output.has("Received a 203 X 163 map @ 0.050 m/pix")
    robot.step(pose, pose)
    assert amcl.wait_idle()
    assert amcl.processed == 1


def test_a_base_frame_outside_the_tree_is_reported(bus, capsys):
    robot = robot_with_map(bus)
    amcl = start(bus, {"base_frame_id": "base_footprint"})
    assert wait_until(lambda: amcl.localizer is not None)
    pose = tour()[0]
    robot.step(pose, pose)
    assert amcl.wait_idle()
    assert Output(capsys).has(
        "Couldn't transform from laser to base_footprint, even though the message notifier is in use"
    )
    assert amcl.processed == 0 and amcl._worker.is_alive()


def test_a_negative_range_is_refused_with_amcls_error(bus, capsys):
    robot = robot_with_map(bus)
    amcl = start(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    pose = tour()[0]
    msg = robot.scan_msg(pose, 0.0)
    msg.range_min = -1.0
    robot.step(pose, pose, msg)
    assert amcl.wait_idle()
    assert Output(capsys).has("range_max or range_min from laser is negative! ignore this message.")
    robot.step(pose, pose)
    assert amcl.wait_idle()
    assert amcl.processed == 1


def test_a_map_in_another_frame_warns(bus, capsys):
    node = Node("map_server", bus=bus, disable_rosout=True)
    node.set_param("~frame_id", "world")
    MapServer(node, loaded_map())
    amcl = start(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    assert Output(capsys).has(
        "Frame_id of map received:'world' doesn't match global_frame_id:'map'. This could "
        "cause issues with reading published topics"
    )


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("min_particles", "many", "parameter ~min_particles must be an integer, got 'many'"),
        ("kld_err", "small", "parameter ~kld_err must be a number, got 'small'"),
        ("use_map_topic", 3, "parameter ~use_map_topic must be a boolean, got 3"),
        ("resample_interval", 0, "parameter ~resample_interval must be at least 1, got 0"),
    ],
)
def test_a_parameter_of_the_wrong_type_is_one_line_naming_it(bus, name, value, message):
    node = Node("amcl", bus=bus, disable_rosout=True)
    node.set_param("~" + name, value)
    with pytest.raises(AmclError) as caught:
        read_params(node)
    assert str(caught.value).splitlines()[0] == message


def test_amcls_warnings_for_odd_parameters(bus):
    node = Node("amcl", bus=bus, disable_rosout=True)
    for key, value in {
        "laser_model_type": "sonar",
        "odom_model_type": "tracks",
        "min_particles": 600,
        "max_particles": 500,
        "initial_pose_x": float("nan"),
    }.items():
        node.set_param("~" + key, value)
    said: list[str] = []
    p = read_params(node, said.append)
    assert said == [
        "ignoring NAN in initial pose X position",
        'Unknown laser model type "sonar"; defaulting to likelihood_field model',
        'Unknown odom model type "tracks"; defaulting to diff model',
        "You've set min_particles to be greater than max particles, this isn't allowed so "
        "they'll be set to be equal.",
    ]
    assert (p.laser_model_type, p.odom_model_type) == ("likelihood_field", "diff")
    assert p.max_particles == p.min_particles == 600 and p.initial_pose_x == 0.0
