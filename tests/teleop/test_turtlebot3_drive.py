"""turtlebot3_drive's decisions on synthetic scans, and the node on a bus.

The original (turtlebot3_gazebo/src/turtlebot3_drive.cpp, noetic): readings at
0, 30 and 330 deg (inf -> range_max); ahead > 0.7 m: left < 0.6 m -> turn right,
else right < 0.6 m -> turn left, else forward at 0.3 m/s; ahead < 0.7 m -> turn
right; turns at 1.5 rad/s until odometry's heading changed by 30 deg.
"""

from __future__ import annotations

import math
import threading

import numpy as np
import pytest
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist
from workbench.msgs.nav_msgs import Odometry
from workbench.msgs.sensor_msgs import LaserScan
from workbench.teleop.keys import Velocity
from workbench.teleop.turtlebot3_drive import (
    DriveState,
    Turtlebot3Drive,
    drive,
    sector_min,
)

FORWARD = Velocity(x=0.3)
RIGHT = Velocity(yaw=-1.5)
LEFT = Velocity(yaw=1.5)


def lds_scan(ahead: float = 3.5, left: float = 3.5, right: float = 3.5, rest: float = 3.5):
    """A TurtleBot3 LDS-01 scan (360 readings over a full turn from 0 rad), 60 deg sectors set."""
    degrees = np.arange(360)
    ranges = np.full(360, rest, dtype=np.float32)
    ranges[(degrees <= 10) | (degrees >= 350)] = ahead
    ranges[(degrees >= 20) & (degrees <= 40)] = left
    ranges[(degrees >= 320) & (degrees <= 340)] = right
    return LaserScan(
        angle_min=0.0,
        angle_max=6.28319,
        angle_increment=6.28319 / 359,
        range_min=0.12,
        range_max=3.5,
        ranges=ranges,
    )


def odom(yaw: float) -> Odometry:
    msg = Odometry()
    msg.pose.pose.orientation.z = math.sin(yaw / 2)
    msg.pose.pose.orientation.w = math.cos(yaw / 2)
    return msg


def test_readings_are_the_nearest_in_each_sector_by_angle():
    scan = lds_scan()
    scan.ranges = np.arange(360, dtype=np.float32) + 1.0
    assert sector_min(scan, math.radians(-15), math.radians(15)) == 1.0
    assert sector_min(scan, math.radians(15), math.radians(60)) == 16.0
    assert sector_min(scan, math.radians(-60), math.radians(-15)) == 301.0  # 1.0028 deg apart
    # the lab's custom_bot laser: 720 readings from -1.578 to 1.578 rad (front half only)
    front = LaserScan(angle_min=-1.578, angle_max=1.578, angle_increment=3.156 / 719)
    front.ranges = np.linspace(-1.578, 1.578, 720).astype(np.float32)
    assert sector_min(front, math.radians(15), math.radians(60)) == pytest.approx(
        math.radians(15), abs=5e-3
    )
    assert sector_min(front, math.radians(150), math.radians(210)) is None  # behind: unseen


def _steps(wander: Turtlebot3Drive, n: int) -> list[Velocity | None]:
    return [wander.step() for _ in range(n)]


def test_nothing_moves_before_the_first_scan():
    wander = Turtlebot3Drive()
    assert _steps(wander, 5) == [None] * 5


def test_clear_all_around_drives_forward_every_other_step():
    wander = Turtlebot3Drive()
    wander.on_scan(lds_scan())
    assert _steps(wander, 4) == [None, FORWARD, None, FORWARD]


def test_an_obstacle_ahead_turns_right_until_the_heading_changed_30_degrees():
    wander = Turtlebot3Drive()
    wander.on_odom(odom(1.0))
    wander.on_scan(lds_scan(ahead=0.5))
    assert wander.step() is None and wander.state == DriveState.RIGHT_TURN
    assert _steps(wander, 3) == [RIGHT] * 3
    wander.on_odom(odom(1.0 - math.radians(29)))
    assert wander.step() == RIGHT
    wander.on_odom(odom(1.0 - math.radians(31)))
    wander.on_scan(lds_scan())  # turned away from it
    assert _steps(wander, 3) == [None, None, FORWARD]
    assert wander.state == DriveState.GET_DIRECTION


@pytest.mark.parametrize(
    ("scan", "turn"),
    [
        (lds_scan(left=0.4), RIGHT),  # near on the left: away to the right
        (lds_scan(right=0.4), LEFT),
        (lds_scan(left=0.4, right=0.4), RIGHT),  # the left is checked first
        (lds_scan(ahead=0.69, left=0.4, right=3.0), RIGHT),
    ],
)
def test_a_near_side_turns_away_from_it(scan, turn):
    wander = Turtlebot3Drive()
    wander.on_scan(scan)
    assert _steps(wander, 3) == [None, turn, turn]


def test_infinite_readings_are_range_max_and_minus_inf_is_too_close():
    wander = Turtlebot3Drive()
    wander.on_scan(lds_scan(ahead=math.inf, left=math.inf, right=math.inf, rest=math.inf))
    assert wander.readings == (3.5, 3.5, 3.5)
    assert _steps(wander, 2) == [None, FORWARD]
    wander.on_scan(lds_scan(ahead=-math.inf))
    assert wander.readings == (0.0, 3.5, 3.5)
    assert _steps(wander, 2) == [None, RIGHT]


def test_nan_readings_keep_the_previous_reading():
    wander = Turtlebot3Drive()
    wander.on_scan(lds_scan(ahead=math.nan, left=math.nan, right=math.nan))
    assert wander.readings == (3.5, 3.5, 3.5)  # nothing known yet: range_max
    wander.on_scan(lds_scan(ahead=0.5))
    wander.on_scan(lds_scan(ahead=math.nan, rest=math.nan))  # no valid return ahead at all
    assert wander.readings == (0.5, 3.5, 3.5)
    assert _steps(wander, 2) == [None, RIGHT]


def test_a_thin_leg_between_the_originals_three_beams_is_seen():
    """The original reads 0, 30 and 330 deg only; a 5 cm table leg at 15-18 deg and 0.5 m
    slips between them until the robot touches it (it did, three times in ten minutes in
    the house). The nearest reading of each sector sees it."""
    wander = Turtlebot3Drive()
    scan = lds_scan()
    scan.ranges[16:19] = 0.5
    wander.on_scan(scan)
    assert wander.readings is not None and wander.readings[1] == pytest.approx(0.5)
    assert _steps(wander, 2) == [None, RIGHT]


def test_a_turn_across_plus_minus_pi_is_measured_the_short_way():
    wander = Turtlebot3Drive()
    wander.on_odom(odom(3.0))
    wander.on_scan(lds_scan(ahead=0.3))
    wander.step()
    wander.on_odom(odom(-3.1))  # 10 deg further, across the +-pi seam
    assert wander.step() == RIGHT
    wander.on_odom(odom(-2.6))  # 39 deg
    assert wander.step() is None and wander.state == DriveState.GET_DIRECTION


def test_the_node_wanders_on_a_bus_and_stops_with_a_zero_twist():
    bus = Bus()
    node = Node("turtlebot3_drive", bus=bus, disable_rosout=True)
    node.set_param("cmd_vel_topic_name", "/cmd_vel")
    robot = Node("robot", bus=bus, disable_rosout=True)
    twists: list[Twist] = []
    robot.create_subscription("/cmd_vel", Twist, twists.append, queue_size=0)
    scans = robot.create_publisher("/scan", LaserScan)
    odometry = robot.create_publisher("/odom", Odometry)
    stop = threading.Event()
    thread = threading.Thread(target=drive, args=(node, stop), daemon=True)
    thread.start()
    try:
        odometry.publish(odom(0.0))
        scans.publish(lds_scan(ahead=0.4))
        assert wait_for(lambda: len(twists) >= 3)
        assert {(t.linear.x, t.angular.z) for t in list(twists)} == {(0.0, -1.5)}
        odometry.publish(odom(-0.6))
        scans.publish(lds_scan())
        assert wait_for(lambda: twists[-1].linear.x == 0.3)
    finally:
        stop.set()
        thread.join(timeout=10)
    assert not thread.is_alive()
    assert wait_for(lambda: (twists[-1].linear.x, twists[-1].angular.z) == (0.0, 0.0))
    bus.shutdown()


def test_workbench_run_turtlebot3_drive_stops_on_sigterm_with_a_zero_twist(
    teleop_process, core_uri
):
    import signal

    import pexpect

    wanderer = teleop_process("turtlebot3_gazebo", "turtlebot3_drive")
    wanderer.child.expect_exact("TurtleBot3 Simulation Node Init")
    bus = Bus.connect(core_uri)
    try:
        robot = Node("robot", bus=bus)
        scans = robot.create_publisher("/scan", LaserScan)
        assert wait_for(lambda: scans.get_num_connections() > 0)
        scans.publish(lds_scan())
        assert wait_for(lambda: (0.3, 0.0) in wanderer.pairs()), wanderer.pairs()
        wanderer.child.kill(signal.SIGTERM)
        wanderer.child.expect(pexpect.EOF)
        wanderer.child.close()
        assert wanderer.child.exitstatus == 128 + signal.SIGTERM
        assert "Traceback" not in wanderer.child.before
        assert wait_for(lambda: wanderer.pairs()[-1] == (0.0, 0.0)), wanderer.pairs()[-3:]
    finally:
        bus.shutdown()
