"""How many subscribers a plugin's topic has, asked of the bus at most five times a wall second.

Plugins skip the work of a step nobody listens to; asking the graph every physics step
would cost more than the work saved.
"""

from __future__ import annotations

import time
from typing import Any

#: Seconds a count is reused before the bus is asked again.
RECOUNT_AFTER = 0.2


class ListenerCount:
    """Subscriber counts of publishers' topics, each refreshed after :data:`RECOUNT_AFTER` s."""

    def __init__(self) -> None:
        self._counts: dict[str, tuple[float, int]] = {}

    def __call__(self, publisher: Any) -> int:
        """Subscribers of ``publisher``'s topic (0 for None)."""
        if publisher is None:
            return 0
        now = time.monotonic()
        checked, count = self._counts.get(publisher.topic, (-1e9, 0))
        if now - checked >= RECOUNT_AFTER:
            count = publisher.get_num_connections()
            self._counts[publisher.topic] = (now, count)
        return count

    def forget(self) -> None:
        """Ask the bus again on the next call (a subscriber was just added)."""
        self._counts.clear()
