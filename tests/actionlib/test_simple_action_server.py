"""SimpleActionServer's one-goal policy and the execute-callback mode, against actionlib 1.14.

From ``actionlib/src/actionlib/simple_action_server.py``: a newer goal becomes the next
goal and requests preemption of the active one; accepting it cancels the old one with
"This goal was canceled because another goal was received by the simple action server";
an older goal is canceled at once; a waiting goal displaced by a newer one is canceled;
an execute callback that returns without a terminal state gets the goal aborted with
"No terminal state was set.".
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from stepping import SteppedBus

from workbench.actionlib import (
    ABORTED,
    ACTIVE,
    PREEMPTED,
    RECALLED,
    SUCCEEDED,
    ActionError,
    SimpleActionClient,
    SimpleActionServer,
)
from workbench.bus import Bus, Node
from workbench.msgs import Time
from workbench.msgs.actionlib_msgs import GoalID
from workbench.msgs.move_base_msgs import MoveBaseActionGoal, MoveBaseGoal

ACTION = "move_base_msgs/MoveBaseAction"
DISPLACED = "This goal was canceled because another goal was received by the simple action server"
REPO = Path(__file__).resolve().parents[2]


class Harness:
    def __init__(self) -> None:
        self.sb = SteppedBus()
        node = Node("server", bus=self.sb.bus)
        self.events: list[str] = []
        self.server = SimpleActionServer(
            node,
            "move_base",
            ACTION,
            goal_cb=lambda: self.events.append("goal"),
            preempt_cb=lambda: self.events.append("preempt"),
        )
        client_node = Node("client", bus=self.sb.bus)
        self.pub = client_node.create_publisher(
            "move_base/goal", "move_base_msgs/MoveBaseActionGoal"
        )
        self.results = []
        client_node.create_subscription(
            "move_base/result", "move_base_msgs/MoveBaseActionResult", self.results.append, 0
        )
        self.sb.drain()

    def goal(self, goal_id: str, stamp: float, x: float = 0.0) -> None:
        msg = MoveBaseActionGoal(goal_id=GoalID(id=goal_id, stamp=Time(0, round(stamp * 1e9))))
        msg.goal.target_pose.pose.position.x = x
        self.pub.publish(msg)
        self.sb.drain()

    def result_of(self, goal_id: str):
        return next(r.status for r in self.results if r.status.goal_id.id == goal_id)


def test_newer_goal_preempts_the_active_one() -> None:
    h = Harness()
    h.goal("a", 1.0, x=1.0)
    assert h.server.is_new_goal_available() and h.events == ["goal"]
    assert h.server.accept_new_goal().target_pose.pose.position.x == 1.0
    assert h.server.is_active() and not h.server.is_preempt_requested()
    h.goal("b", 2.0, x=2.0)
    assert h.server.is_preempt_requested() and h.events == ["goal", "preempt", "goal"]
    assert h.server.accept_new_goal().target_pose.pose.position.x == 2.0
    h.sb.drain()
    status = h.result_of("a")
    assert status.status == PREEMPTED and status.text == DISPLACED
    assert h.server.current.status == ACTIVE and not h.server.is_preempt_requested()


def test_older_goal_is_canceled_at_once() -> None:
    h = Harness()
    h.goal("new", 5.0)
    h.server.accept_new_goal()
    h.goal("old", 4.0)
    assert not h.server.is_new_goal_available()
    status = h.result_of("old")
    assert status.status == RECALLED and status.text == DISPLACED


def test_waiting_goal_displaced_by_newer() -> None:
    h = Harness()
    h.goal("a", 1.0)
    h.goal("b", 2.0)
    assert h.result_of("a").status == RECALLED
    assert h.server.accept_new_goal() is not None and h.server.current.goal_id.id == "b"


def test_cancel_of_the_next_goal_carries_into_accept() -> None:
    h = Harness()
    h.goal("a", 1.0)
    cancel = Node("c2", bus=h.sb.bus).create_publisher("move_base/cancel", "actionlib_msgs/GoalID")
    cancel.publish(GoalID(id="a"))
    h.sb.drain()
    h.server.accept_new_goal()
    assert h.server.is_preempt_requested()  # accepted goal is PREEMPTING already
    h.server.set_preempted()
    h.sb.drain()
    assert h.result_of("a").status == PREEMPTED


def test_accept_without_a_goal_is_an_error() -> None:
    h = Harness()
    with pytest.raises(ActionError, match="new goal is not available"):
        h.server.accept_new_goal()


def test_execute_callback_on_a_threaded_bus() -> None:
    bus = Bus(threaded=True, workers=2)
    try:
        node = Node("fib", bus=bus)

        def execute(goal):
            if goal.target_pose.pose.position.x > 0:
                server.set_succeeded(None, "done")
            # else: returns without a terminal state

        server = SimpleActionServer(node, "move_base", ACTION, execute_cb=execute)
        client = SimpleActionClient("move_base", ACTION, Node("user", bus=bus))
        assert client.wait_for_server(5.0)
        goal = MoveBaseGoal()
        goal.target_pose.pose.position.x = 1.0
        feedback = []
        done = []
        client.send_goal(goal, done_cb=lambda s, r: done.append(s), feedback_cb=feedback.append)
        assert client.wait_for_result(5.0)
        assert client.get_state() == SUCCEEDED and done == [SUCCEEDED]
        goal.target_pose.pose.position.x = -1.0
        assert client.send_goal_and_wait(goal, 5.0) == ABORTED
        assert client.get_goal_status_text() == "No terminal state was set."
    finally:
        bus.shutdown()


def test_compat_actionlib_in_a_rospy_script() -> None:
    code = """
        from workbench.compat import actionlib, rospy
        from workbench.msgs.move_base_msgs import MoveBaseAction, MoveBaseGoal, MoveBaseFeedback

        rospy.init_node("nav_script")

        def execute(goal):
            fb = MoveBaseFeedback()
            fb.base_position.pose.position.x = goal.target_pose.pose.position.x / 2
            server.publish_feedback(fb)
            rospy.sleep(0.2)
            server.set_succeeded()

        server = actionlib.SimpleActionServer("move_base", MoveBaseAction, execute, auto_start=False)
        server.start()
        client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
        print("server", client.wait_for_server(rospy.Duration(5)))
        goal = MoveBaseGoal()
        goal.target_pose.pose.position.x = 3.0
        seen = []
        client.send_goal(goal, feedback_cb=lambda f: seen.append(f.base_position.pose.position.x))
        print("done", client.wait_for_result(rospy.Duration(5)))
        print("state", client.get_state() == actionlib.GoalStatus.SUCCEEDED, seen)
        rospy.signal_shutdown("done")
    """
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc", PYTHONUNBUFFERED="1")
    result = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        cwd=REPO,
    )
    assert result.returncode == 0, result.stderr
    assert "server True" in result.stdout and "done True" in result.stdout
    assert "state True [1.5]" in result.stdout
