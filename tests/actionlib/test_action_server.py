"""actionlib's protocol on the bus: server state machine, cancels, status list and the client.

Each expectation is actionlib 1.14's (``actionlib/src/actionlib/action_server.py``,
``server_goal_handle.py``, ``simple_action_client.py``, ``goal_id_generator.py``, read via
the ros/actionlib sources): the transitions a ``ServerGoalHandle`` allows, cancel by id /
everything (empty id, zero stamp) / by stamp, a cancel arriving before its goal, a goal
stamped at or before the last cancel, the 5 Hz status and the 5 s status-list timeout,
and the simple client's RECALLING->PENDING, PREEMPTING->ACTIVE reading.
"""

from __future__ import annotations

import re

import pytest
from stepping import SteppedBus

from workbench.actionlib import (
    ABORTED,
    ACTIVE,
    PENDING,
    PREEMPTED,
    PREEMPTING,
    RECALLED,
    RECALLING,
    REJECTED,
    SUCCEEDED,
    ActionError,
    ActionServer,
    SimpleActionClient,
)
from workbench.bus import Node
from workbench.msgs import Time
from workbench.msgs.actionlib_msgs import GoalID
from workbench.msgs.move_base_msgs import MoveBaseGoal

ACTION = "move_base_msgs/MoveBaseAction"


class Harness:
    def __init__(self) -> None:
        self.sb = SteppedBus()
        self.node = Node("server", bus=self.sb.bus)
        self.cnode = Node("client", bus=self.sb.bus)
        self.handles = []
        self.cancels = []
        self.server = ActionServer(
            self.node, "move_base", ACTION, self.handles.append, self.cancels.append
        )
        self.client = SimpleActionClient("move_base", ACTION, self.cnode)
        self.statuses = []
        self.results = []
        self.cnode.create_subscription(
            "move_base/status", "actionlib_msgs/GoalStatusArray", self.statuses.append, 0
        )
        self.cnode.create_subscription(
            "move_base/result", "move_base_msgs/MoveBaseActionResult", self.results.append, 0
        )
        self.cancel_pub = self.cnode.create_publisher("move_base/cancel", "actionlib_msgs/GoalID")
        self.goal_pub = self.cnode.create_publisher(
            "move_base/goal", "move_base_msgs/MoveBaseActionGoal"
        )
        self.sb.drain()

    def send(self) -> None:
        self.client.send_goal(MoveBaseGoal())
        self.sb.drain()

    def raw_goal(self, goal_id: str, stamp: float) -> None:
        from workbench.msgs.move_base_msgs import MoveBaseActionGoal

        msg = MoveBaseActionGoal(goal_id=GoalID(id=goal_id, stamp=Time(0, round(stamp * 1e9))))
        self.goal_pub.publish(msg)
        self.sb.drain()

    def status_of(self, goal_id: str) -> int:
        last = self.statuses[-1]
        return next(int(s.status) for s in last.status_list if s.goal_id.id == goal_id)


@pytest.fixture
def h() -> Harness:
    return Harness()


def test_goal_id_is_node_count_seconds(h: Harness) -> None:
    h.send()
    assert re.fullmatch(r"/client-\d+-100\.000", h.client.goal_id.id)
    assert h.handles[0].goal_id.id == h.client.goal_id.id
    assert h.client.goal_id.stamp == Time(100, 0)


def test_accept_then_succeed(h: Harness) -> None:
    h.send()
    handle = h.handles[0]
    assert handle.status == PENDING and h.client.get_state() == PENDING
    active = []
    h.client.active_cb = lambda: active.append(True)
    handle.set_accepted("go")
    h.sb.drain()
    assert h.client.get_state() == ACTIVE and active == [True]
    handle.set_succeeded(None, "Goal reached.")
    h.sb.drain()
    assert h.client.get_state() == SUCCEEDED
    assert h.client.get_goal_status_text() == "Goal reached."
    assert h.client.wait_for_result(1.0)
    assert h.results[-1].status.status == SUCCEEDED


def test_terminal_goal_leaves_the_status_list_after_five_seconds(h: Harness) -> None:
    h.send()
    h.handles[0].set_rejected(None, "no")
    h.sb.drain()
    gid = h.handles[0].goal_id.id
    h.sb.advance(4.9)
    assert h.status_of(gid) == REJECTED
    h.sb.advance(0.4)
    assert all(s.goal_id.id != gid for s in h.statuses[-1].status_list)


def test_status_is_published_at_five_hertz(h: Harness) -> None:
    h.statuses.clear()
    h.sb.advance(2.0)
    assert len(h.statuses) in (10, 11)  # 5 Hz, the boundary tick may fall either side


def test_status_frequency_parameter(h: Harness) -> None:
    h.sb.bus.params.set("/actionlib_status_frequency", 20.0)
    node = Node("fast", bus=h.sb.bus)
    got = []
    ActionServer(node, "fast_action", ACTION, lambda handle: None)
    node.create_subscription("fast_action/status", "actionlib_msgs/GoalStatusArray", got.append, 0)
    h.sb.drain()
    got.clear()
    h.sb.advance(1.0)
    assert len(got) in (20, 21)


def test_invalid_transition_is_ignored(h: Harness) -> None:
    h.send()
    handle = h.handles[0]
    handle.set_succeeded()  # PENDING cannot succeed
    h.sb.drain()
    assert handle.status == PENDING
    handle.set_aborted()
    assert handle.status == PENDING


def test_cancel_pending_goal_recalls_it(h: Harness) -> None:
    h.send()
    h.client.cancel_goal()
    h.sb.drain()
    handle = h.handles[0]
    assert handle.status == RECALLING and h.cancels == [handle]
    assert h.client.get_state() == PENDING  # the simple client reads RECALLING as PENDING
    handle.set_canceled()
    h.sb.drain()
    assert h.client.get_state() == RECALLED


def test_cancel_active_goal_preempts_it(h: Harness) -> None:
    h.send()
    handle = h.handles[0]
    handle.set_accepted()
    h.client.cancel_goal()
    h.sb.drain()
    assert handle.status == PREEMPTING
    assert h.client.get_state() == ACTIVE  # PREEMPTING reads ACTIVE
    handle.set_aborted(None, "failed while stopping")  # a preempting goal may still abort
    h.sb.drain()
    assert h.client.get_state() == ABORTED


def test_accepting_a_recalling_goal_makes_it_preempting(h: Harness) -> None:
    h.send()
    h.client.cancel_goal()
    h.sb.drain()
    h.handles[0].set_accepted()
    assert h.handles[0].status == PREEMPTING
    h.handles[0].set_canceled()
    h.sb.drain()
    assert h.client.get_state() == PREEMPTED


def test_cancel_everything_and_by_stamp(h: Harness) -> None:
    h.raw_goal("a", 10.0)
    h.raw_goal("b", 20.0)
    h.raw_goal("c", 30.0)
    h.cancel_pub.publish(GoalID(stamp=Time(20, 0)))  # at and before 20 s
    h.sb.drain()
    assert [x.status for x in h.handles] == [RECALLING, RECALLING, PENDING]
    h.cancel_pub.publish(GoalID())  # empty id and zero stamp: everything
    h.sb.drain()
    assert [x.status for x in h.handles] == [RECALLING, RECALLING, RECALLING]
    h.raw_goal("d", 15.0)  # stamped before the last cancel: recalled on arrival
    assert h.handles[-1].goal_id.id == "c" and h.results[-1].status.goal_id.id == "d"
    assert h.results[-1].status.status == RECALLED
    assert "before the timestamp of the last cancel request" in h.results[-1].status.text


def test_cancel_before_goal_recalls_the_goal_on_arrival(h: Harness) -> None:
    h.cancel_pub.publish(GoalID(id="early"))
    h.sb.drain()
    h.sb.advance(0.3)
    assert h.status_of("early") == RECALLING
    h.raw_goal("early", 0.0)
    assert h.handles == []  # the user never hears of it
    assert h.results[-1].status.goal_id.id == "early"
    assert h.results[-1].status.status == RECALLED


def test_empty_goal_id_and_stamp_are_filled_in(h: Harness) -> None:
    h.raw_goal("", 0.0)
    gid = h.handles[0].goal_id
    assert gid.id.startswith("/server-") and gid.stamp == Time(100, 0)


def test_not_an_action_type() -> None:
    sb = SteppedBus()
    with pytest.raises(ActionError, match="not an action type"):
        ActionServer(Node("x", bus=sb.bus), "a", "move_base_msgs/MoveBaseGoal", lambda g: None)


def test_lost_when_goal_vanishes(h: Harness) -> None:
    h.send()
    h.sb.advance(0.3)
    h.server.trackers.clear()  # the server forgets it (restarted) before any result
    h.sb.advance(0.3)
    assert h.client.get_state() == 9  # LOST
    assert h.client.wait_for_result(0.1)
