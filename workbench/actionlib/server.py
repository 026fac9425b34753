"""actionlib's ``ActionServer`` on the bus: goals, cancels, status, feedback and results.

Under the action namespace ``ns`` the server subscribes to ``ns/goal`` (``NameActionGoal``)
and ``ns/cancel`` (``actionlib_msgs/GoalID``) and publishes ``ns/status``
(``actionlib_msgs/GoalStatusArray``, every 1/``actionlib_status_frequency`` s, 5 Hz unless
set), ``ns/feedback`` and ``ns/result``, as ``actionlib/action_server.py`` (1.14) does:

* a new goal gets a tracker in PENDING (an empty id is replaced by a generated one, a
  zero stamp by now) and goes to the goal callback, unless its stamp is at or before the
  last cancel's stamp: then it is RECALLED at once;
* a cancel with an empty id and a zero stamp cancels every goal, one with an id cancels
  that goal, one with a stamp every goal stamped at or before it; PENDING goals go to
  RECALLING and ACTIVE ones to PREEMPTING, and the cancel callback sees them; a cancel
  for an id the server has not seen is kept (RECALLING) and recalls the goal when it
  arrives;
* a goal that reached a terminal state stays in the status list for
  ``ns/status_list_timeout`` s (5.0).

A :class:`ServerGoalHandle` moves its goal through the states; a transition actionlib does
not allow is logged with actionlib's error text and ignored.
"""

from __future__ import annotations

import copy
import threading
from collections.abc import Callable
from typing import Any

from workbench.actionlib.types import (
    ABORTED,
    ACTIVE,
    PENDING,
    PREEMPTED,
    PREEMPTING,
    RECALLED,
    RECALLING,
    REJECTED,
    SUCCEEDED,
    TERMINAL,
    ActionSpec,
    GoalIDGenerator,
)

_ZERO = 0


class _Tracker:
    """A goal's status (and its goal message once it arrived)."""

    def __init__(self, status: Any, goal: Any = None) -> None:
        self.status = status
        self.goal = goal
        self.released_ns = _ZERO  # when the goal reached a terminal state (0: still held)


class ServerGoalHandle:
    """One goal on the server: read it, move it through the states, send feedback."""

    def __init__(self, tracker: _Tracker, server: ActionServer) -> None:
        self._tracker = tracker
        self._server = server

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ServerGoalHandle) and self.goal_id.id == other.goal_id.id

    def __hash__(self) -> int:
        return hash(self.goal_id.id)

    @property
    def goal_id(self) -> Any:
        """The goal's ``actionlib_msgs/GoalID``."""
        return self._tracker.status.goal_id

    def get_goal(self) -> Any:
        """The user's goal message (``NameGoal``), or None for a cancel-only tracker."""
        return None if self._tracker.goal is None else self._tracker.goal.goal

    def get_goal_id(self) -> Any:
        return self.goal_id

    def get_goal_status(self) -> Any:
        """The goal's ``actionlib_msgs/GoalStatus`` (a live reference)."""
        return self._tracker.status

    @property
    def status(self) -> int:
        return int(self._tracker.status.status)

    def set_accepted(self, text: str = "") -> None:
        """PENDING -> ACTIVE, RECALLING -> PREEMPTING."""
        self._move(
            {PENDING: ACTIVE, RECALLING: PREEMPTING}, text, "an active", "a pending or recalling"
        )

    def set_rejected(self, result: Any = None, text: str = "") -> None:
        """PENDING or RECALLING -> REJECTED."""
        self._move(
            {PENDING: REJECTED, RECALLING: REJECTED},
            text,
            "a rejected",
            "a pending or recalling",
            result,
        )

    def set_canceled(self, result: Any = None, text: str = "") -> None:
        """PENDING/RECALLING -> RECALLED, ACTIVE/PREEMPTING -> PREEMPTED."""
        moves = {PENDING: RECALLED, RECALLING: RECALLED, ACTIVE: PREEMPTED, PREEMPTING: PREEMPTED}
        self._move(
            moves, text, "a cancelled", "a pending, recalling, active, or preempting", result
        )

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """ACTIVE or PREEMPTING -> ABORTED."""
        self._move(
            {ACTIVE: ABORTED, PREEMPTING: ABORTED},
            text,
            "an aborted",
            "a preempting or active",
            result,
        )

    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """ACTIVE or PREEMPTING -> SUCCEEDED."""
        moves = {ACTIVE: SUCCEEDED, PREEMPTING: SUCCEEDED}
        self._move(moves, text, "a succeeded", "a preempting or active", result)

    def set_cancel_requested(self) -> bool:
        """PENDING -> RECALLING, ACTIVE -> PREEMPTING; whether the user should hear of it."""
        with self._server.lock:
            moves = {PENDING: RECALLING, ACTIVE: PREEMPTING}
            new = moves.get(self.status)
            if new is None:
                return False
            self._tracker.status.status = new
            self._server.publish_status()
            return True

    def publish_feedback(self, feedback: Any) -> None:
        """Publish ``feedback`` (``NameFeedback``) with this goal's status."""
        self._server.publish_feedback(self._tracker.status, feedback)

    def _move(
        self, moves: dict[int, int], text: str, target: str, sources: str, result: Any = None
    ) -> None:
        server = self._server
        with server.lock:
            new = moves.get(self.status)
            if new is None:
                server.node.get_logger().error(
                    f"To transition to {target} state, the goal must be in {sources} state, "
                    f"it is currently in state: {self.status}"
                )
                return
            status = self._tracker.status
            status.status = new
            status.text = text
            if new in TERMINAL:
                self._tracker.released_ns = server.node.bus.clock.now_ns()
                server.publish_result(
                    status, result if result is not None else server.spec.result()
                )
            else:
                server.publish_status()


class ActionServer:
    """The action protocol's server side under ``ns``.

    Args:
        node: The node that owns the topics.
        ns: The action namespace (``move_base`` -> ``move_base/goal`` ...).
        action_type: ``"pkg/NameAction"`` or its class.
        goal_cb: ``goal_cb(handle)`` for every new goal (accept or reject it there or later).
        cancel_cb: ``cancel_cb(handle)`` when a goal's cancel is requested.
        auto_start: Start at once (else :meth:`start`).
    """

    def __init__(
        self,
        node: Any,
        ns: str,
        action_type: Any,
        goal_cb: Callable[[ServerGoalHandle], Any],
        cancel_cb: Callable[[ServerGoalHandle], Any] | None = None,
        auto_start: bool = True,
    ) -> None:
        self.node = node
        self.ns = node.resolve_name(ns, "action namespace")
        self.spec = ActionSpec.of(action_type)
        self.goal_cb = goal_cb
        self.cancel_cb = cancel_cb or (lambda handle: None)
        self.lock = threading.RLock()
        self.trackers: list[_Tracker] = []
        self.last_cancel_ns = _ZERO
        self.started = False
        self.ids = GoalIDGenerator(node.name)
        self.status_frequency = _status_frequency(node, self.ns)
        self.status_list_timeout = float(node.get_param(self.ns + "/status_list_timeout", 5.0))
        self.status_pub = node.create_publisher(
            self.ns + "/status", "actionlib_msgs/GoalStatusArray", 50
        )
        self.result_pub = node.create_publisher(self.ns + "/result", self.spec.action_result, 50)
        self.feedback_pub = node.create_publisher(
            self.ns + "/feedback", self.spec.action_feedback, 50
        )
        node.create_subscription(self.ns + "/goal", self.spec.action_goal, self._on_goal, 50)
        node.create_subscription(self.ns + "/cancel", "actionlib_msgs/GoalID", self._on_cancel, 50)
        self._timer = None
        if self.status_frequency > 0:
            self._timer = node.create_timer(1.0 / self.status_frequency, self._on_timer)
        if auto_start:
            self.start()

    def start(self) -> None:
        """Begin taking goals and publishing status."""
        with self.lock:
            self.started = True
            self.publish_status()

    def handles(self) -> list[ServerGoalHandle]:
        """Handles of every goal in the status list."""
        with self.lock:
            return [ServerGoalHandle(t, self) for t in self.trackers]

    # --- incoming ---------------------------------------------------------------------

    def _on_goal(self, msg: Any) -> None:
        with self.lock:
            if not self.started:
                return
            for tracker in self.trackers:
                if tracker.status.goal_id.id == msg.goal_id.id:
                    if tracker.status.status == RECALLING:  # its cancel came first
                        tracker.status.status = RECALLED
                        tracker.released_ns = self.node.bus.clock.now_ns()
                        self.publish_result(tracker.status, self.spec.result())
                    return
            from workbench.msgs.actionlib_msgs import GoalStatus

            status = GoalStatus(status=PENDING)
            status.goal_id = msg.goal_id
            if status.goal_id.id == "":
                status.goal_id = self.ids.generate(self.node.now())
            if status.goal_id.stamp.to_nsec() == 0:
                status.goal_id.stamp = self.node.now()
            tracker = _Tracker(status, msg)
            self.trackers.append(tracker)
            handle = ServerGoalHandle(tracker, self)
            stamp = msg.goal_id.stamp.to_nsec()
            if stamp != 0 and stamp <= self.last_cancel_ns:
                handle.set_canceled(
                    None,
                    "This goal handle was canceled by the action server because its timestamp "
                    "is before the timestamp of the last cancel request",
                )
            else:
                self.goal_cb(handle)

    def _on_cancel(self, msg: Any) -> None:
        with self.lock:
            if not self.started:
                return
            stamp = msg.stamp.to_nsec()
            cancel_id = msg.id
            found = False
            for tracker in list(self.trackers):
                goal_id = tracker.status.goal_id
                everything = cancel_id == "" and stamp == 0
                by_stamp = stamp != 0 and goal_id.stamp.to_nsec() <= stamp
                if everything or cancel_id == goal_id.id or by_stamp:
                    found = found or cancel_id == goal_id.id
                    handle = ServerGoalHandle(tracker, self)
                    if handle.set_cancel_requested():
                        self.cancel_cb(handle)
            if cancel_id != "" and not found:
                from workbench.msgs.actionlib_msgs import GoalStatus

                tracker = _Tracker(GoalStatus(goal_id=msg, status=RECALLING))
                tracker.released_ns = self.node.bus.clock.now_ns()
                self.trackers.append(tracker)
            self.last_cancel_ns = max(self.last_cancel_ns, stamp)

    def _on_timer(self, _event: Any) -> None:
        with self.lock:
            if self.started:
                self.publish_status()

    # --- outgoing ---------------------------------------------------------------------

    def publish_status(self) -> None:
        """Publish the status list now (dropping goals released over the timeout ago)."""
        from workbench.msgs.actionlib_msgs import GoalStatusArray

        with self.lock:
            now = self.node.bus.clock.now_ns()
            timeout = int(self.status_list_timeout * 1e9)
            self.trackers = [
                t for t in self.trackers if t.released_ns == _ZERO or t.released_ns + timeout >= now
            ]
            array = GoalStatusArray(status_list=[copy.deepcopy(t.status) for t in self.trackers])
            array.header.stamp = self.node.now()
            self.status_pub.publish(array)

    def publish_result(self, status: Any, result: Any) -> None:
        with self.lock:
            msg = self.spec.action_result(status=copy.deepcopy(status), result=result)
            msg.header.stamp = self.node.now()
            self.result_pub.publish(msg)
            self.publish_status()

    def publish_feedback(self, status: Any, feedback: Any) -> None:
        with self.lock:
            msg = self.spec.action_feedback(status=copy.deepcopy(status), feedback=feedback)
            msg.header.stamp = self.node.now()
            self.feedback_pub.publish(msg)

    def shutdown(self) -> None:
        """Stop publishing status (the node's endpoints close with the node)."""
        with self.lock:
            self.started = False
            if self._timer is not None:
                self._timer.shutdown()


def _status_frequency(node: Any, ns: str) -> float:
    """``ns/status_frequency`` (deprecated) or the nearest ``actionlib_status_frequency``."""
    if node.has_param(ns + "/status_frequency"):
        node.get_logger().warn(
            "You're using the deprecated status_frequency parameter, please switch to "
            "actionlib_status_frequency."
        )
        return float(node.get_param(ns + "/status_frequency"))
    found = node.search_param("actionlib_status_frequency")
    return 5.0 if found is None else float(node.get_param(found, 5.0))
