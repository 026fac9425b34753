"""actionlib's ``SimpleActionServer``: one goal at a time, a newer goal preempts.

As ``actionlib/simple_action_server.py`` (1.14): a new goal stamped no earlier than the
current and the waiting goal becomes the *next* goal (a waiting goal it displaces is
canceled with "This goal was canceled because another goal was received by the simple
action server"); while a goal is active this requests its preemption. An older goal is
canceled at once. :meth:`accept_new_goal` makes the next goal current ("This goal has been
accepted by the simple action server"). With an ``execute_cb`` a worker thread accepts
each new goal and runs the callback; a callback that returns with its goal still active
gets the goal aborted with actionlib's warning ("No terminal state was set."), one that
raises gets it aborted with the error. Without one, the owner polls
:meth:`is_new_goal_available` / :meth:`is_preempt_requested` (``goal_cb``/``preempt_cb``
tell it when), as move_base's and most C++ servers' loops do.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from workbench.actionlib.server import ActionServer, ServerGoalHandle
from workbench.actionlib.types import ACTIVE, PREEMPTING, ActionError

_DISPLACED = "This goal was canceled because another goal was received by the simple action server"


class SimpleActionServer:
    """One-goal-at-a-time server under ``ns``.

    Args:
        node: The node that owns the topics.
        ns: The action namespace.
        action_type: ``"pkg/NameAction"`` or its class.
        execute_cb: ``execute_cb(goal)`` run on a worker thread per goal (optional).
        auto_start: Start at once.
        goal_cb: Called (no arguments) when a new goal is available.
        preempt_cb: Called (no arguments) when the current goal's preemption is requested.
    """

    def __init__(
        self,
        node: Any,
        ns: str,
        action_type: Any,
        execute_cb: Callable[[Any], Any] | None = None,
        auto_start: bool = True,
        goal_cb: Callable[[], Any] | None = None,
        preempt_cb: Callable[[], Any] | None = None,
    ) -> None:
        self.node = node
        self.execute_cb = execute_cb
        self.goal_cb = goal_cb
        self.preempt_cb = preempt_cb
        self.current: ServerGoalHandle | None = None
        self.next: ServerGoalHandle | None = None
        self.new_goal = False
        self.preempt_request = False
        self.new_goal_preempt_request = False
        self._stop = False
        self._thread: threading.Thread | None = None
        self.server = ActionServer(node, ns, action_type, self._on_goal, self._on_cancel, False)
        # One lock with the action server (actionlib takes the server's lock first): goal
        # arrival and accepting a goal take the two in opposite orders otherwise.
        self.lock = self.server.lock
        self.wake = threading.Condition(self.lock)
        node.on_shutdown(self.shutdown)
        if auto_start:
            self.start()

    def start(self) -> None:
        """Begin taking goals (and start the execute thread if there is a callback)."""
        if self.execute_cb is not None and self._thread is None:
            self._thread = threading.Thread(
                target=self._execute_loop, name=f"actionlib:{self.server.ns}", daemon=True
            )
            self._thread.start()
        self.server.start()

    def shutdown(self) -> None:
        with self.lock:
            self._stop = True
            self.wake.notify_all()
        self.server.shutdown()

    # --- queries ------------------------------------------------------------------------

    def is_new_goal_available(self) -> bool:
        return self.new_goal

    def is_preempt_requested(self) -> bool:
        return self.preempt_request

    def is_active(self) -> bool:
        """Whether the current goal is ACTIVE or PREEMPTING."""
        with self.lock:
            return self.current is not None and self.current.status in (ACTIVE, PREEMPTING)

    def current_goal(self) -> Any:
        """The current goal's message (None before the first)."""
        return None if self.current is None else self.current.get_goal()

    # --- goal lifecycle -----------------------------------------------------------------

    def accept_new_goal(self) -> Any:
        """Make the next goal current and ACTIVE; returns its goal message.

        Raises:
            ActionError: No new goal is available.
        """
        with self.lock:
            if not self.new_goal or self.next is None:
                raise ActionError(
                    "Attempting to accept the next goal when a new goal is not available"
                )
            if self.is_active() and self.current != self.next:
                self.current.set_canceled(None, _DISPLACED)  # type: ignore[union-attr]
            self.current = self.next
            self.new_goal = False
            self.preempt_request = self.new_goal_preempt_request
            self.new_goal_preempt_request = False
            self.current.set_accepted("This goal has been accepted by the simple action server")
            return self.current.get_goal()

    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        with self.lock:
            if self.current is not None:
                self.current.set_succeeded(result, text)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        with self.lock:
            if self.current is not None:
                self.current.set_aborted(result, text)

    def set_preempted(self, result: Any = None, text: str = "") -> None:
        with self.lock:
            if self.current is not None:
                self.current.set_canceled(result, text)

    def publish_feedback(self, feedback: Any) -> None:
        with self.lock:
            if self.current is not None:
                self.current.publish_feedback(feedback)

    # --- callbacks of the action server ---------------------------------------------------

    def _on_goal(self, handle: ServerGoalHandle) -> None:
        with self.lock:
            stamp = handle.goal_id.stamp.to_nsec()
            newer_than_current = (
                self.current is None or stamp >= self.current.goal_id.stamp.to_nsec()
            )
            newer_than_next = self.next is None or stamp >= self.next.goal_id.stamp.to_nsec()
            if not (newer_than_current and newer_than_next):
                handle.set_canceled(None, _DISPLACED)
                return
            if self.next is not None and (self.current is None or self.next != self.current):
                self.next.set_canceled(None, _DISPLACED)
            self.next = handle
            self.new_goal = True
            self.new_goal_preempt_request = False
            if self.is_active():
                self.preempt_request = True
                if self.preempt_cb is not None:
                    self.preempt_cb()
            if self.goal_cb is not None:
                self.goal_cb()
            self.wake.notify_all()

    def _on_cancel(self, handle: ServerGoalHandle) -> None:
        with self.lock:
            if handle == self.current:
                self.preempt_request = True
                if self.preempt_cb is not None:
                    self.preempt_cb()
            elif handle == self.next:
                self.new_goal_preempt_request = True

    def _execute_loop(self) -> None:
        assert self.execute_cb is not None
        while True:
            with self.lock:
                while not self._stop and not self.new_goal:
                    self.wake.wait(0.1)
                if self._stop:
                    return
                goal = self.accept_new_goal()
            try:
                self.execute_cb(goal)
            except Exception as error:  # a user's callback: report it, keep serving
                self.node.get_logger().error(f"Exception in your execute callback: {error}")
                self.set_aborted(None, f"Exception in execute callback: {error}")
                continue
            with self.lock:
                if self.is_active():
                    self.node.get_logger().warn(
                        "Your executeCallback did not set the goal to a terminal status.  This is a "
                        "bug in your ActionServer implementation. Fix your code!  For now, the "
                        "ActionServer will set this goal to aborted"
                    )
                    self.set_aborted(None, "No terminal state was set.")
