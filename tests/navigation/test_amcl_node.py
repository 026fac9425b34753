"""The ``amcl`` node on an in-process bus: map_server serves ``static_map``, a robot drives
through the demo rooms publishing ``/clock``, ``/tf`` and ``/scan``; amcl publishes the latched
``amcl_pose``, ``particlecloud`` and a ``map -> odom`` transform that puts the robot where it
truly is (texts and behaviour of amcl_node.cpp, Noetic)."""

from __future__ import annotations

import numpy as np
import pytest
from amcl_feed import (
    Output,
    Robot,
    amcl_map,
    bus,
    initial_guess,
    noisy_odometry,
    pose_of,
    serve_map,
    start,
    tour,
    wait_until,
)

from workbench.bus import Node
from workbench.mapping.geometry import compose
from workbench.msgs.geometry_msgs import PoseArray, PoseWithCovarianceStamped
from workbench.msgs.std_srvs import Empty
from workbench.tf import Buffer, TransformListener


def test_the_node_localises_the_robot_and_publishes_map_to_odom(bus, capsys):
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    truth = tour()[:260]
    odom = noisy_odometry(truth)
    amcl = start(bus, {"max_particles": 2000, **initial_guess(truth[0])})
    assert wait_until(lambda: amcl.localizer is not None)
    watcher = Node("watcher", bus=bus, disable_rosout=True)
    poses: list = []
    clouds: list = []
    watcher.create_subscription("/amcl_pose", PoseWithCovarianceStamped, poses.append, 100)
    watcher.create_subscription("/particlecloud", PoseArray, clouds.append, 100)
    buffer = Buffer()
    TransformListener(buffer, watcher)
    errors = []
    for k in range(len(truth)):
        stamp = robot.step(truth[k], odom[k])
        assert amcl.wait_idle()
        # amcl sends map -> odom with every scan, stamped transform_tolerance after it
        assert wait_until(
            lambda s=stamp: (
                buffer.can_transform("map", "odom", 0)
                and buffer.get_latest_common_time("map", "odom") >= (s + 0.1) * 1e9 - 1e3
            )
        )
        estimate = compose(pose_of(buffer.lookup_transform("map", "odom", 0)), odom[k])
        errors.append(np.hypot(*(estimate[:2] - truth[k][:2])))
    assert amcl.processed == len(truth) and amcl.dropped == 0
    assert errors[0] > 0.5  # the wrong guess
    assert max(errors[120:]) <= 0.1, max(errors[120:])

    output = Output(capsys)
    assert output.has("Requesting the map...")
    assert output.has("Received a 203 X 163 map @ 0.050 m/pix")
    assert wait_until(lambda: len(poses) > 10 and clouds)
    last = poses[-1]
    assert last.header.frame_id == "map"
    position = np.array([last.pose.pose.position.x, last.pose.pose.position.y])
    stamp_index = int(round((last.header.stamp.to_sec() - 100.0) / robot.dt)) - 1
    assert np.hypot(*(position - truth[stamp_index][:2])) <= 0.1
    cov = np.asarray(last.pose.covariance).reshape(6, 6)
    assert 0 < cov[0, 0] < 0.05 and 0 < cov[1, 1] < 0.05 and 0 < cov[5, 5] < 0.05
    assert cov[2, 2] == 0 and cov[3, 3] == 0
    assert clouds[-1].header.frame_id == "map"
    assert 100 <= len(clouds[-1].poses) <= 2000

    # map -> odom is post-dated by transform_tolerance (0.1 s) after the scan
    tf_stamp = buffer.get_latest_common_time("map", "odom")
    assert tf_stamp / 1e9 == pytest.approx(robot.t + 0.1)
    mid = robot.t - robot.dt / 2  # between two scans tf interpolates map -> base_link
    assert buffer.can_transform("map", "base_link", mid)
    # the pose is saved into ~initial_pose_* every 2 s (save_pose_rate 0.5), as savePoseToServer
    saved = np.array([bus.params.get(f"/amcl/initial_pose_{c}") for c in "xya"])
    assert np.hypot(*(saved[:2] - truth[-1][:2])) < 0.15
    assert bus.params.get("/amcl/initial_cov_xx") == pytest.approx(cov[0, 0])
    # latched: a late subscriber gets the last pose at once
    late: list = []
    Node("late", bus=bus, disable_rosout=True).create_subscription(
        "/amcl_pose", PoseWithCovarianceStamped, late.append, 1
    )
    assert wait_until(lambda: late)
    assert late[-1].header.stamp == last.header.stamp


def test_an_initial_pose_resets_the_filter_and_one_in_another_frame_is_ignored(bus, capsys):
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    amcl = start(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    user = Node("rviz", bus=bus, disable_rosout=True)
    pub = user.create_publisher("/initialpose", PoseWithCovarianceStamped, 2)
    msg = PoseWithCovarianceStamped()
    msg.header.frame_id = "map"
    msg.pose.pose.position.x, msg.pose.pose.position.y = 5.0, 3.0
    msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = np.sin(0.5), np.cos(0.5)
    cov = np.zeros(36)
    cov[0] = cov[7] = 0.04
    cov[35] = 0.01
    msg.pose.covariance = cov
    pub.publish(msg)
    output = Output(capsys)
    assert output.has("Setting pose")
    assert amcl.wait_idle()
    pf = amcl.localizer.pf
    assert pf.count == 5000
    assert pf.mean[:2] == pytest.approx([5.0, 3.0], abs=0.02)
    assert pf.mean[2] == pytest.approx(1.0, abs=0.02)
    assert pf.poses[:, 0].std() == pytest.approx(0.2, rel=0.1)

    other = PoseWithCovarianceStamped()
    other.header.frame_id = "odom"
    other.pose.pose.position.x = 1.0
    other.pose.pose.orientation.w = 1.0
    pub.publish(other)
    assert amcl.wait_idle()
    assert amcl.localizer.pf.mean[:2] == pytest.approx([5.0, 3.0], abs=0.02)
    assert output.has(
        'Ignoring initial pose in frame "odom"; initial poses must be in the global frame, "map"'
    )


def test_setting_pose_logs_amcls_line(bus, capsys):
    serve_map(bus)
    amcl = start(bus)
    Node("clock", bus=bus, disable_rosout=True)
    assert wait_until(lambda: amcl.localizer is not None)
    msg = PoseWithCovarianceStamped()
    msg.header.frame_id = "/map"  # a leading slash is stripped, as amcl does
    msg.pose.pose.position.x, msg.pose.pose.position.y = 1.25, -0.5
    msg.pose.pose.orientation.w = 1.0
    amcl.handle_initial_pose(msg)
    assert Output(capsys).has("Setting pose (0.000000): 1.250 -0.500 0.000")


def test_global_localization_and_nomotion_update_services(bus):
    m = amcl_map()
    robot = Robot(bus, m)
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    amcl = start(bus, {"max_particles": 3000})
    assert wait_until(lambda: amcl.localizer is not None)
    caller = Node("caller", bus=bus, disable_rosout=True)
    caller.create_client("/global_localization", Empty).call(Empty.Request(), timeout=5)
    pf = amcl.localizer.pf
    assert pf.count == 3000
    assert (pf.poses[:, :2].std(axis=0) > 1.5).all()
    i, j, valid = m.cells_of(pf.poses[:, 0], pf.poses[:, 1])
    assert valid.all() and (m.states[j[valid], i[valid]] == -1).all()  # all in free space

    pose = tour()[0]
    robot.step(pose, pose)  # the first scan after a reset only records the odometry
    assert amcl.wait_idle()
    updates = amcl.localizer.updates
    robot.step(pose, pose)  # no motion: no update
    assert amcl.wait_idle()
    assert amcl.localizer.updates == updates
    caller.create_client("/request_nomotion_update", Empty).call(Empty.Request(), timeout=5)
    robot.step(pose, pose)
    assert amcl.wait_idle()
    assert amcl.localizer.updates == updates + 1


def test_set_map_takes_the_map_and_the_initial_pose(bus, capsys):
    from workbench.msgs.nav_msgs import GetMap, SetMap

    serve_map(bus)
    amcl = start(bus)
    assert wait_until(lambda: amcl.localizer is not None)
    caller = Node("caller", bus=bus, disable_rosout=True)
    grid = caller.create_client("/static_map", GetMap).call(GetMap.Request(), timeout=5).map
    request = SetMap.Request(map=grid)
    request.initial_pose.header.frame_id = "map"
    request.initial_pose.pose.pose.position.x = 6.0
    request.initial_pose.pose.pose.position.y = 2.0
    request.initial_pose.pose.pose.orientation.w = 1.0
    request.initial_pose.pose.covariance[0] = request.initial_pose.pose.covariance[7] = 0.01
    response = caller.create_client("/set_map", SetMap).call(request, timeout=10)
    assert response.success
    assert amcl.localizer.pf.mean[:2] == pytest.approx([6.0, 2.0], abs=0.02)
    output = Output(capsys)
    assert output.has("Setting pose")
    assert output.text.count("Received a 203 X 163 map @ 0.050 m/pix") == 2


def test_the_map_topic_is_used_with_use_map_topic(bus, capsys):
    serve_map(bus)
    amcl = start(bus, {"use_map_topic": True})
    assert wait_until(lambda: amcl.localizer is not None)
    output = Output(capsys)
    assert output.has("Subscribed to map topic.")
    assert "Requesting the map..." not in output.text
    assert amcl.localizer.map.size_x == 203


__all__ = ["bus"]  # the fixture
