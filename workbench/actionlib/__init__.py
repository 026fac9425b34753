"""actionlib on the bus: goals, cancels, status, feedback and results (ROS 1's action protocol).

``ActionServer``/``SimpleActionServer`` serve an action under a namespace, ``SimpleActionClient``
sends goals to one; the topics, goal ids and the goal state machine are actionlib's.
``from workbench.compat import actionlib`` gives rospy scripts the same classes bound to
their ``init_node`` node.
"""

from __future__ import annotations

from workbench.actionlib.client import SimpleActionClient
from workbench.actionlib.server import ActionServer, ServerGoalHandle
from workbench.actionlib.simple_server import SimpleActionServer
from workbench.actionlib.types import (
    ABORTED,
    ACTIVE,
    LOST,
    PENDING,
    PREEMPTED,
    PREEMPTING,
    RECALLED,
    RECALLING,
    REJECTED,
    SUCCEEDED,
    ActionError,
    ActionSpec,
    GoalIDGenerator,
    state_name,
)

__all__ = [
    "ABORTED",
    "ACTIVE",
    "LOST",
    "PENDING",
    "PREEMPTED",
    "PREEMPTING",
    "RECALLED",
    "RECALLING",
    "REJECTED",
    "SUCCEEDED",
    "ActionError",
    "ActionServer",
    "ActionSpec",
    "GoalIDGenerator",
    "ServerGoalHandle",
    "SimpleActionClient",
    "SimpleActionServer",
    "state_name",
]
