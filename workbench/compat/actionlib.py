"""actionlib for the lab's rospy scripts: ``from workbench.compat import actionlib``.

``actionlib.SimpleActionClient("move_base", MoveBaseAction)`` and
``actionlib.SimpleActionServer(name, Action, execute_cb=..., auto_start=False)`` work as in
rospy, on the node of :func:`workbench.compat.rospy.init_node`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from workbench import actionlib as _actionlib
from workbench.actionlib import ActionServer, GoalIDGenerator, ServerGoalHandle
from workbench.compat import rospy

__all__ = [
    "ActionServer",
    "GoalIDGenerator",
    "GoalStatus",
    "ServerGoalHandle",
    "SimpleActionClient",
    "SimpleActionServer",
    "SimpleGoalState",
]


class GoalStatus:
    """``actionlib_msgs/GoalStatus``'s constants (``actionlib.GoalStatus.SUCCEEDED``)."""

    PENDING = _actionlib.PENDING
    ACTIVE = _actionlib.ACTIVE
    PREEMPTED = _actionlib.PREEMPTED
    SUCCEEDED = _actionlib.SUCCEEDED
    ABORTED = _actionlib.ABORTED
    REJECTED = _actionlib.REJECTED
    PREEMPTING = _actionlib.PREEMPTING
    RECALLING = _actionlib.RECALLING
    RECALLED = _actionlib.RECALLED
    LOST = _actionlib.LOST


class SimpleGoalState:
    """The simple client's own goal states."""

    PENDING = 0
    ACTIVE = 1
    DONE = 2


class SimpleActionClient(_actionlib.SimpleActionClient):
    """``SimpleActionClient(ns, ActionSpec)`` on the script's node."""

    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803 (rospy's name)
        super().__init__(ns, ActionSpec, rospy.context().node(required=True))


class SimpleActionServer(_actionlib.SimpleActionServer):
    """``SimpleActionServer(name, ActionSpec, execute_cb=None, auto_start=True)`` on the script's node."""

    def __init__(
        self,
        name: str,
        ActionSpec: Any,  # noqa: N803 (rospy's name)
        execute_cb: Callable[[Any], Any] | None = None,
        auto_start: bool = True,
    ) -> None:
        super().__init__(
            rospy.context().node(required=True), name, ActionSpec, execute_cb, auto_start
        )

    def register_goal_callback(self, callback: Callable[[], Any]) -> None:
        self.goal_cb = callback

    def register_preempt_callback(self, callback: Callable[[], Any]) -> None:
        self.preempt_cb = callback
