"""Action types, goal ids and goal states shared by the action servers and clients.

An action ``pkg/NameAction`` comes with six messages, as actionlib's generator makes them:
``NameActionGoal`` (header, goal_id, goal), ``NameActionResult`` and ``NameActionFeedback``
(header, status, result/feedback) and the user's ``NameGoal``, ``NameResult``,
``NameFeedback``. Goal ids are ``<node>-<count>-<seconds>`` with the seconds to three
decimals, as actionlib's ``GoalIDGenerator`` (``actionlib/goal_id_generator.py``) writes them.
"""

from __future__ import annotations

import itertools
import threading
from dataclasses import dataclass
from typing import Any

from workbench.bus.errors import BusError
from workbench.msgs import get_type, type_name

#: actionlib_msgs/GoalStatus values (``GoalStatus.msg``).
PENDING, ACTIVE, PREEMPTED, SUCCEEDED, ABORTED = 0, 1, 2, 3, 4
REJECTED, PREEMPTING, RECALLING, RECALLED, LOST = 5, 6, 7, 8, 9
STATE_NAMES = (
    "PENDING",
    "ACTIVE",
    "PREEMPTED",
    "SUCCEEDED",
    "ABORTED",
    "REJECTED",
    "PREEMPTING",
    "RECALLING",
    "RECALLED",
    "LOST",
)
#: States after which a goal never changes again.
TERMINAL = frozenset({PREEMPTED, SUCCEEDED, ABORTED, REJECTED, RECALLED, LOST})


class ActionError(BusError):
    """An action name, type or call that cannot work (one line: what and what to do)."""


def state_name(state: int) -> str:
    """``GoalStatus`` value -> its name (``3`` -> ``SUCCEEDED``)."""
    return STATE_NAMES[state] if 0 <= state < len(STATE_NAMES) else f"UNKNOWN({state})"


@dataclass(frozen=True)
class ActionSpec:
    """The message classes of one action type."""

    action: str
    action_goal: Any
    action_result: Any
    action_feedback: Any
    goal: Any
    result: Any
    feedback: Any

    @classmethod
    def of(cls, action_type: Any) -> ActionSpec:
        """The spec of ``"pkg/NameAction"`` or of its class.

        Raises:
            ActionError: The name does not end in ``Action`` or a message is missing.
        """
        name = action_type if isinstance(action_type, str) else type_name(action_type)
        if not name.endswith("Action"):
            raise ActionError(
                f"'{name}' is not an action type",
                hint="give the action's type, e.g. move_base_msgs/MoveBaseAction",
            )
        base = name[: -len("Action")]
        try:
            return cls(
                name,
                *(get_type(base + suffix) for suffix in _SUFFIXES),
            )
        except KeyError as error:
            raise ActionError(f"action type '{name}' is incomplete: {error}") from None


_SUFFIXES = ("ActionGoal", "ActionResult", "ActionFeedback", "Goal", "Result", "Feedback")


class GoalIDGenerator:
    """Unique goal ids ``<name>-<count>-<secs.3f>``, the count shared by the process."""

    _counter = itertools.count(1)
    _lock = threading.Lock()

    def __init__(self, name: str) -> None:
        self.name = name

    def generate(self, now: Any) -> Any:
        """A new ``actionlib_msgs/GoalID`` stamped ``now`` (a ``Time``)."""
        from workbench.msgs.actionlib_msgs import GoalID

        with self._lock:
            count = next(self._counter)
        return GoalID(id=f"{self.name}-{count}-{now.to_sec():.3f}", stamp=now)
