"""amcl when it falls behind: a filter update that does not return while the robot drives on
(what a starved CPU does to it), then load drops. ROS's amcl catches up because its tf
message filter drops the scans that grew older than the tf cache at once and its subscriber
queues drop the oldest; workbench's amcl must likewise publish ``map -> odom`` from fresh
scans again within a few scans, and a 2D Pose Estimate sent while it was stuck must take
effect at once, not after the backlog."""

from __future__ import annotations

import threading

import numpy as np
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
from workbench.msgs import Time
from workbench.msgs.geometry_msgs import PoseWithCovarianceStamped
from workbench.tf import Buffer, TransformListener

__all__ = ["bus"]  # the fixture

#: Scans published while amcl is stuck: 30 s at 5 Hz, more than the 100 scans its filter
#: queue holds and three times the 10 s its tf buffer keeps.
STARVED = 150
#: Scans after the load dropped within which amcl must be current again.
RECOVERY = 10
#: Scans after that.
AFTER = 40


class Watcher:
    """The ``map -> odom`` transform amcl broadcasts, as any node on the bus sees it."""

    def __init__(self, bus) -> None:
        self.node = Node("watcher", bus=bus, disable_rosout=True)
        self.buffer = Buffer()
        TransformListener(self.buffer, self.node)

    def current(self, stamp: float) -> bool:
        """Whether ``map -> odom`` was sent for the scan of ``stamp`` (or a later one)."""
        if not self.buffer.can_transform("map", "odom", 0):
            return False
        # amcl stamps it transform_tolerance (0.1 s) after the scan
        return self.buffer.get_latest_common_time("map", "odom") >= (stamp + 0.1) * 1e9 - 1e3

    def error(self, truth: np.ndarray, odom: np.ndarray) -> float:
        estimate = compose(pose_of(self.buffer.lookup_transform("map", "odom", 0)), odom)
        return float(np.hypot(*(estimate[:2] - truth[:2])))


def pose_estimate(pose: np.ndarray, stamp: float) -> PoseWithCovarianceStamped:
    """RViz's 2D Pose Estimate at ``pose`` (x, y, yaw in the map frame)."""
    msg = PoseWithCovarianceStamped()
    msg.header.frame_id = "map"
    msg.header.stamp = Time.from_sec(stamp)
    msg.pose.pose.position.x, msg.pose.pose.position.y = float(pose[0]), float(pose[1])
    msg.pose.pose.orientation.z = float(np.sin(pose[2] / 2))
    msg.pose.pose.orientation.w = float(np.cos(pose[2] / 2))
    cov = np.zeros(36)
    cov[0] = cov[7] = 0.0025
    cov[35] = 0.003
    msg.pose.covariance = cov
    return msg


def test_amcl_catches_up_after_falling_behind_and_takes_a_pose_estimate_at_once(bus, capsys):
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    truth = tour()[: 6 + STARVED + RECOVERY + AFTER]
    odom = noisy_odometry(truth)
    # amcl starts 1.2 m from the robot: a few scans cannot bring it there
    guess = initial_guess(truth[0], offset=(1.0, -0.7, 0.3))
    amcl = start(bus, {"max_particles": 2000, **guess})
    assert wait_until(lambda: amcl.localizer is not None)
    watcher = Watcher(bus)
    rviz = Node("rviz", bus=bus, disable_rosout=True)
    estimates = rviz.create_publisher("/initialpose", PoseWithCovarianceStamped, 2)
    k = 0
    for k in range(5):
        stamp = robot.step(truth[k], odom[k])
        assert amcl.wait_idle()
        assert wait_until(lambda s=stamp: watcher.current(s))
    assert watcher.error(truth[k], odom[k]) > 0.8  # where amcl wrongly thinks it is

    # the next filter update does not return until the load drops
    localizer = amcl.localizer
    update = localizer.process
    stuck, load_dropped = threading.Event(), threading.Event()

    def starved(*args):
        stuck.set()
        load_dropped.wait(120.0)
        return update(*args)

    localizer.process = starved
    k += 1
    robot.step(truth[k], odom[k])
    assert wait_until(stuck.is_set)
    for _ in range(STARVED):
        k += 1
        robot.step(truth[k], odom[k])
    # the student sees the robot in the wrong place and gives amcl its pose
    estimates.publish(pose_estimate(truth[k], robot.t))
    output = Output(capsys)
    localizer.process = update
    load_dropped.set()

    # the load dropped: within a few scans amcl is current again, at the estimated pose
    recovered = None
    for n in range(RECOVERY):
        k += 1
        dropped = amcl.dropped
        stamp = robot.step(truth[k], odom[k])
        # the next scan comes once amcl sent map -> odom for this one or dropped one
        wait_until(lambda s=stamp, d=dropped: watcher.current(s) or amcl.dropped > d)
        if watcher.current(stamp):
            recovered = n
            break
    assert recovered is not None, (
        f"amcl sent no map -> odom for any of the {RECOVERY} scans after the load dropped "
        f"(received {amcl.received}, processed {amcl.processed}, dropped {amcl.dropped})"
    )
    assert output.has("Setting pose")
    assert watcher.error(truth[k], odom[k]) < 0.3

    # while it was stuck, amcl's watchdog saw no scan pass its filter (as amcl's, on bus time)
    assert output.has("No laser scan received (and thus no pose updates have been published)")
    # and it goes on localising from every scan
    for _ in range(AFTER):
        k += 1
        stamp = robot.step(truth[k], odom[k])
        assert amcl.wait_idle()
        assert wait_until(lambda s=stamp: watcher.current(s))
    assert watcher.error(truth[k], odom[k]) < 0.15


def test_a_scan_older_than_the_tf_cache_is_dropped_at_once_with_tf2s_lines(bus, capsys):
    robot = Robot(bus, amcl_map())
    robot.tick(robot.t)
    robot.mount()
    serve_map(bus)
    truth = tour()[:60]
    odom = noisy_odometry(truth)
    amcl = start(bus, {"max_particles": 500, **initial_guess(truth[0], offset=(0, 0, 0))})
    assert wait_until(lambda: amcl.localizer is not None)
    for k in range(60):  # 12 s of odometry
        robot.step(truth[k], odom[k])
        assert amcl.wait_idle()
    processed = amcl.processed
    # a scan 11 s old (a bag replayed without its clock, say): tf forgot its odometry
    old = robot.scan_msg(truth[0], robot.t - 11.0)
    player = Node("player", bus=bus, disable_rosout=True)
    player.create_publisher("/scan", type(old), 1).publish(old)
    assert amcl.wait_idle()
    assert amcl.dropped == 1 and amcl.processed == processed
    output = Output(capsys)
    assert output.has(
        "  The majority of dropped messages were due to messages growing older than the TF "
        f"cache time.  The last message's timestamp was: {robot.t - 11.0:f}, and the last "
        "frame_id was: laser"
    )
    assert 'scans in frame "laser" are dropped' not in output.text  # the frame is fine
