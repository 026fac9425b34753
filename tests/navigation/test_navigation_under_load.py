"""The navigation stack after amcl fell behind: the kinematic robot (tests/navigation/
kinematic_robot.py) in its room, amcl localising it on the room's map and sending
``map -> odom``, move_base with its costmaps on the same stepped bus. amcl's filter update
stalls for 30 s of simulated time while the robot's scans keep coming (a starved CPU);
once the load drops, the global costmap must get the robot's pose again within a few
scans, and move_base must take the robot around the box to a goal."""

from __future__ import annotations

import math
import threading

from kinematic_robot import KinematicRobot, SimClock
from move_base_setup import PARAMS
from process_helpers import wait_for as poll

from workbench.actionlib import SUCCEEDED, SimpleActionClient
from workbench.actionlib.client import SIMPLE_DONE
from workbench.bus import Bus, Node
from workbench.navigation.amcl_node import Amcl
from workbench.navigation.move_base import MoveBase
from workbench.tf import Buffer, TransformListener
from workbench.tf.timeconv import to_ns

START = (0.8, 2.0, 0.0)
GOAL = (5.0, 2.0, math.pi / 2)
#: Simulated seconds per step; the laser scans at 5 Hz.
DT, SCAN_PERIOD = 0.05, 0.2
#: Simulated seconds amcl is stuck: its filter queue (100 scans, 20 s) fills and the
#: oldest scans fall out of the tf cache (10 s).
STARVED = 30.0
#: Steps after the load dropped within which the global costmap must have the pose again.
RECOVERY = 20
AMCL = {
    "use_map_topic": True,
    "base_frame_id": "base_footprint",
    "initial_pose_x": START[0],
    "initial_pose_y": START[1],
    "initial_pose_a": START[2],
    "initial_cov_xx": 0.01,
    "initial_cov_yy": 0.01,
    "initial_cov_aa": 0.01,
    "max_particles": 1000,
}


def wait_for(predicate, timeout: float = 30.0) -> bool:
    """:func:`process_helpers.wait_for` polling every 2 ms."""
    return poll(predicate, timeout, poll=0.002)


class Stack:
    """Robot, amcl and move_base on a stepped bus on simulated time."""

    def __init__(self) -> None:
        self.bus = Bus(threaded=False)
        self.clock = SimClock(self.bus)
        for key, value in PARAMS.items():
            self.bus.params.set(f"/move_base/{key}", value)
        for key, value in AMCL.items():
            self.bus.params.set(f"/amcl/{key}", value)
        self.robot = KinematicRobot(self.bus, START, map_to_odom=False)
        self.amcl = Amcl(Node("amcl", bus=self.bus))
        assert wait_for(lambda: self.amcl.localizer is not None)
        self.node = Node("move_base", bus=self.bus)
        self.lines: list[str] = []
        self.node.create_subscription("/rosout", "rosgraph_msgs/Log", self._on_log, 0)
        self.buffer = Buffer(cache_time=10.0)
        TransformListener(self.buffer, self.node)
        self.clock.drain()
        self.move_base = MoveBase(self.node, self.buffer)
        self.user = Node("user", bus=self.bus)
        self.client = SimpleActionClient("move_base", "move_base_msgs/MoveBaseAction", self.user)

    def _on_log(self, msg) -> None:
        if msg.name in ("/move_base", "/amcl"):
            self.lines.append(f"{msg.name}: {msg.msg}")

    def step(self, wait: bool = True) -> None:
        """Advance DT; with ``wait``, until amcl handled what came (or dropped a scan)."""
        robot, clock = self.robot, self.clock
        robot.step(DT)
        clock.t += DT
        self.bus.clock.set_time(round(clock.t * 1e9))
        robot.publish_state(SCAN_PERIOD)
        clock.drain()  # amcl's tf listener gets the odometry of the scan
        if wait:
            dropped = self.amcl.dropped
            wait_for(lambda: self.amcl.wait_idle(0.0) or self.amcl.dropped > dropped)
            clock.drain()  # move_base gets amcl's map -> odom

    def localised(self) -> bool:
        """Whether move_base's tf has ``map -> odom`` for the robot's latest scan."""
        if not self.buffer.can_transform("map", "odom", 0):
            return False
        latest = self.buffer.get_latest_common_time("map", "odom")
        return latest >= to_ns(self.robot.last_scan) + to_ns(0.1) - 1000

    def goal(self, x: float, y: float, yaw: float):
        from workbench.msgs.move_base_msgs import MoveBaseGoal

        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = "map"
        goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
        goal.target_pose.pose.orientation.z = math.sin(yaw / 2)
        goal.target_pose.pose.orientation.w = math.cos(yaw / 2)
        return goal

    def close(self) -> None:
        self.move_base.shutdown()
        self.amcl.close()
        self.bus.shutdown()


def test_move_base_reaches_a_goal_after_amcl_fell_behind() -> None:
    stack = Stack()
    try:
        for _ in range(20):
            stack.step()
        assert stack.localised(), stack.lines
        assert stack.move_base.global_costmap.robot_pose() is not None

        # amcl's next filter update does not return for STARVED simulated seconds
        localizer = stack.amcl.localizer
        update = localizer.process
        stuck, load_dropped = threading.Event(), threading.Event()

        def starved(*args):
            stuck.set()
            load_dropped.wait(120.0)
            return update(*args)

        localizer.process = starved
        for _ in range(round(SCAN_PERIOD / DT) + 1):
            stack.step(wait=False)
        assert wait_for(stuck.is_set)
        for _ in range(round(STARVED / DT)):
            stack.step(wait=False)
        assert not stack.localised()
        assert stack.move_base.global_costmap.robot_pose() is None  # map -> odom is stale
        localizer.process = update
        load_dropped.set()

        # the load dropped: a few scans later the global costmap has the robot again
        for _ in range(RECOVERY):
            stack.step()
            if stack.localised():
                break
        assert stack.localised(), (stack.amcl.received, stack.amcl.processed, stack.lines[-5:])
        pose = stack.move_base.global_costmap.robot_pose()
        assert pose is not None
        assert math.dist(pose[:2], stack.robot.pose[:2]) < 0.15

        # and move_base takes the robot around the box to a goal
        stack.client.send_goal(stack.goal(*GOAL))
        for _ in range(round(90.0 / DT)):
            stack.step()
            if stack.client.simple_state == SIMPLE_DONE:
                break
        assert stack.client.get_state() == SUCCEEDED, stack.lines[-10:]
        x, y, _ = stack.robot.pose
        assert math.hypot(x - GOAL[0], y - GOAL[1]) <= 0.15 + 0.1  # xy tolerance + amcl's error
        assert stack.robot.closest > stack.robot.radius
    finally:
        stack.close()
