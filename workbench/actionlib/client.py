"""actionlib's ``SimpleActionClient`` on the bus: send a goal, follow it, wait, cancel.

As ``actionlib/simple_action_client.py`` and ``action_client.py`` (1.14): a goal goes out on
``ns/goal`` with a fresh id (``<node>-<count>-<secs>``) stamped now; the client follows the
goal's status in ``ns/status`` and its ``ns/feedback`` and ``ns/result``. The goal is done
when its result arrives; a goal that vanishes from the server's status list before its
result came is LOST. :meth:`get_state` reports RECALLING as PENDING and PREEMPTING as
ACTIVE, as the simple client does. Cancels go to ``ns/cancel``: by id
(:meth:`cancel_goal`), everything (:meth:`cancel_all_goals`: empty id, zero stamp) or by
stamp (:meth:`cancel_goals_at_and_before_time`).

Waiting works on both kinds of bus: a threaded bus runs the callbacks by itself; on a
stepped bus (``Bus(threaded=False)``) the waits spin it.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

from workbench.actionlib.types import (
    ACTIVE,
    LOST,
    PENDING,
    PREEMPTING,
    RECALLING,
    TERMINAL,
    ActionSpec,
    GoalIDGenerator,
)

#: ``SimpleGoalState`` of the simple client.
SIMPLE_PENDING, SIMPLE_ACTIVE, SIMPLE_DONE = 0, 1, 2


def _seconds(timeout: Any) -> float:
    """A timeout as float seconds (``Duration`` or number; 0 or None: forever)."""
    if timeout is None:
        return 0.0
    return float(timeout.to_sec() if hasattr(timeout, "to_sec") else timeout)


class SimpleActionClient:
    """Client of the action under ``ns``.

    Args:
        ns: The action namespace (``move_base``), resolved in ``node``'s namespace.
        action_type: ``"pkg/NameAction"`` or its class.
        node: The node that owns the topics (``workbench.compat.actionlib`` uses rospy's).
    """

    def __init__(self, ns: str, action_type: Any, node: Any) -> None:
        self.node = node
        self.ns = node.resolve_name(ns, "action namespace")
        self.spec = ActionSpec.of(action_type)
        self.ids = GoalIDGenerator(node.name)
        self.cond = threading.Condition(threading.RLock())
        self.goal_id: Any = None
        self.status: Any = None  # latest actionlib_msgs/GoalStatus of our goal
        self.result: Any = None
        self.simple_state = SIMPLE_DONE
        self.seen_status = False
        self.seen_in_list = False
        self.done_cb: Callable[..., Any] | None = None
        self.active_cb: Callable[[], Any] | None = None
        self.feedback_cb: Callable[[Any], Any] | None = None
        self.goal_pub = node.create_publisher(self.ns + "/goal", self.spec.action_goal, 10)
        self.cancel_pub = node.create_publisher(self.ns + "/cancel", "actionlib_msgs/GoalID", 10)
        node.create_subscription(
            self.ns + "/status", "actionlib_msgs/GoalStatusArray", self._on_status, 1
        )
        node.create_subscription(
            self.ns + "/feedback", self.spec.action_feedback, self._on_feedback, 10
        )
        node.create_subscription(self.ns + "/result", self.spec.action_result, self._on_result, 10)

    # --- waiting ----------------------------------------------------------------------

    def _wait(self, done: Callable[[], bool], timeout: Any) -> bool:
        seconds = _seconds(timeout)
        bus = self.node.bus
        if not bus.threaded:
            return bus.spin_until(done, seconds if seconds > 0 else None)
        clock = bus.clock
        deadline = clock.now_ns() + int(seconds * 1e9) if seconds > 0 else None
        wall = time.monotonic()
        with self.cond:
            while not done():
                if bus.is_shutdown:
                    return False
                if deadline is not None and clock.now_ns() >= deadline:
                    break
                if (
                    deadline is not None
                    and not clock.is_simulated
                    and time.monotonic() - wall > seconds
                ):
                    break
                self.cond.wait(0.1)
            return done()

    def _server_ready(self) -> bool:
        return (
            self.seen_status
            and self.goal_pub.get_num_connections() > 0
            and self.cancel_pub.get_num_connections() > 0
        )

    def wait_for_server(self, timeout: Any = 0.0) -> bool:
        """Wait until the server's status arrived and it listens for goals (0: forever)."""
        return self._wait(self._server_ready, timeout)

    def wait_for_result(self, timeout: Any = 0.0) -> bool:
        """Wait until the goal is done (0: forever); whether it is."""
        if self.goal_id is None:
            self.node.get_logger().error("Called wait_for_result when no goal exists")
            return False
        return self._wait(lambda: self.simple_state == SIMPLE_DONE, timeout)

    # --- goals ------------------------------------------------------------------------

    def send_goal(
        self,
        goal: Any,
        done_cb: Callable[[int, Any], Any] | None = None,
        active_cb: Callable[[], Any] | None = None,
        feedback_cb: Callable[[Any], Any] | None = None,
    ) -> None:
        """Send ``goal`` (a ``NameGoal``); it replaces the goal this client followed."""
        from workbench.msgs.actionlib_msgs import GoalStatus

        now = self.node.now()
        with self.cond:
            self.goal_id = self.ids.generate(now)
            self.status = GoalStatus(goal_id=self.goal_id, status=PENDING)
            self.result = None
            self.seen_in_list = False
            self.simple_state = SIMPLE_PENDING
            self.done_cb, self.active_cb, self.feedback_cb = done_cb, active_cb, feedback_cb
            msg = self.spec.action_goal(goal_id=self.goal_id, goal=goal)
            msg.header.stamp = now
        self.goal_pub.publish(msg)

    def send_goal_and_wait(
        self, goal: Any, execute_timeout: Any = 0.0, preempt_timeout: Any = 0.0
    ) -> int:
        """Send, wait; cancel and wait again if it did not finish; returns the state."""
        self.send_goal(goal)
        if not self.wait_for_result(execute_timeout):
            self.cancel_goal()
            self.wait_for_result(preempt_timeout)
        return self.get_state()

    def cancel_goal(self) -> None:
        """Cancel the goal this client follows."""
        if self.goal_id is not None:
            from workbench.msgs.actionlib_msgs import GoalID

            self.cancel_pub.publish(GoalID(id=self.goal_id.id))

    def cancel_all_goals(self) -> None:
        """Cancel every goal of the server (empty id, zero stamp)."""
        from workbench.msgs.actionlib_msgs import GoalID

        self.cancel_pub.publish(GoalID())

    def cancel_goals_at_and_before_time(self, stamp: Any) -> None:
        """Cancel every goal stamped at or before ``stamp`` (a ``Time``)."""
        from workbench.msgs.actionlib_msgs import GoalID

        self.cancel_pub.publish(GoalID(stamp=stamp))

    def stop_tracking_goal(self) -> None:
        with self.cond:
            self.goal_id = None

    # --- state ------------------------------------------------------------------------

    def get_state(self) -> int:
        """The goal's ``GoalStatus`` (RECALLING reads PENDING, PREEMPTING reads ACTIVE)."""
        with self.cond:
            if self.goal_id is None or self.status is None:
                return LOST
            status = int(self.status.status)
            return {RECALLING: PENDING, PREEMPTING: ACTIVE}.get(status, status)

    def get_result(self) -> Any:
        """The goal's result message (None until done)."""
        with self.cond:
            return self.result

    def get_goal_status_text(self) -> str:
        with self.cond:
            return "" if self.status is None else str(self.status.text)

    # --- callbacks --------------------------------------------------------------------

    def _mine(self, goal_id: Any) -> bool:
        return self.goal_id is not None and goal_id.id == self.goal_id.id

    def _on_status(self, msg: Any) -> None:
        fire_active = False
        with self.cond:
            self.seen_status = True
            if self.goal_id is not None and self.simple_state != SIMPLE_DONE:
                mine = [s for s in msg.status_list if self._mine(s.goal_id)]
                if mine:
                    self.seen_in_list = True
                    fire_active = self._update(mine[0])
                elif self.seen_in_list and self.status.status not in TERMINAL:
                    self.status.status = LOST  # gone from the server before its result
                    self._finish()
            self.cond.notify_all()
        if fire_active and self.active_cb is not None:
            self.active_cb()

    def _update(self, status: Any) -> bool:
        """Take a newer status; whether the goal just left PENDING."""
        self.status = status
        if self.simple_state == SIMPLE_PENDING and int(status.status) not in (PENDING, RECALLING):
            self.simple_state = SIMPLE_ACTIVE
            return True
        return False

    def _on_feedback(self, msg: Any) -> None:
        with self.cond:
            if not self._mine(msg.status.goal_id) or self.simple_state == SIMPLE_DONE:
                return
            callback = self.feedback_cb
        if callback is not None:
            callback(msg.feedback)

    def _on_result(self, msg: Any) -> None:
        with self.cond:
            if not self._mine(msg.status.goal_id) or self.simple_state == SIMPLE_DONE:
                return
            self.status = msg.status
            self.result = msg.result
            done = self._finish()
            self.cond.notify_all()
        if done is not None:
            done(self.get_state(), msg.result)

    def _finish(self) -> Callable[..., Any] | None:
        self.simple_state = SIMPLE_DONE
        return self.done_cb
