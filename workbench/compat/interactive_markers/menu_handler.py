"""``interactive_markers.menu_handler``: context menus for interactive markers.

:class:`MenuHandler` as in ROS 1: ``insert`` entries (nested under a parent),
``setVisible``, ``setCheckState``/``getCheckState`` (a checked entry's title is
shown as ``[x] title``, an unchecked one as ``[ ] title``), ``apply`` the menu
to a marker of a server (then ``server.applyChanges()``), ``reApply`` after
changes. A MENU_SELECT feedback calls the chosen entry's callback.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from workbench.msgs.visualization_msgs import InteractiveMarkerFeedback, MenuEntry

__all__ = ["MenuHandler"]


@dataclass
class _Entry:
    title: str
    command: str
    command_type: int
    feedback_cb: Callable[[Any], Any] | None
    visible: bool = True
    check_state: int = 0
    sub_entries: list[int] = field(default_factory=list)


class MenuHandler:
    """A menu of entries, applied to interactive markers."""

    NO_CHECKBOX = 0
    CHECKED = 1
    UNCHECKED = 2

    def __init__(self) -> None:
        self.top_level_handles: list[int] = []
        self.entry_contexts: dict[int, _Entry] = {}
        self.current_handle = 1
        self.managed_markers: set[str] = set()

    def insert(
        self,
        title: str,
        parent: int | None = None,
        command_type: int = MenuEntry.FEEDBACK,
        command: str = "",
        callback: Callable[[Any], Any] | None = None,
    ) -> int:
        """Add an entry (under ``parent`` if given); returns its handle (1, 2, ...)."""
        handle = self.current_handle
        self.current_handle += 1
        if parent is not None:
            parent_context = self.entry_contexts.get(parent)
            if parent_context is None:
                raise KeyError(f"menu parent handle {parent} does not exist")
            parent_context.sub_entries.append(handle)
        else:
            self.top_level_handles.append(handle)
        self.entry_contexts[handle] = _Entry(title, command, command_type, callback)
        return handle

    def setVisible(self, handle: int, visible: bool) -> bool:  # noqa: N802 - ROS's name
        context = self.entry_contexts.get(handle)
        if context is None:
            return False
        context.visible = visible
        return True

    def setCheckState(self, handle: int, check_state: int) -> bool:  # noqa: N802 - ROS's name
        context = self.entry_contexts.get(handle)
        if context is None:
            return False
        context.check_state = check_state
        return True

    def getCheckState(self, handle: int) -> int | None:  # noqa: N802 - ROS's name
        context = self.entry_contexts.get(handle)
        return context.check_state if context is not None else None

    def getTitle(self, handle: int) -> str | None:  # noqa: N802 - ROS's name
        context = self.entry_contexts.get(handle)
        return context.title if context is not None else None

    def apply(self, server: Any, marker_name: str) -> bool:
        """Put the menu on ``marker_name`` of ``server`` (send with ``server.applyChanges()``)."""
        marker = server.get(marker_name)
        if marker is None:
            self.managed_markers.discard(marker_name)
            return False
        marker.menu_entries = []
        self._push(self.top_level_handles, marker.menu_entries, 0)
        server.insert(marker, self.processFeedback, InteractiveMarkerFeedback.MENU_SELECT)
        self.managed_markers.add(marker_name)
        return True

    def reApply(self, server: Any) -> bool:  # noqa: N802 - ROS's name
        success = True
        for name in list(self.managed_markers):
            success = self.apply(server, name) and success
        return success

    def processFeedback(self, feedback: Any) -> None:  # noqa: N802 - ROS's name
        context = self.entry_contexts.get(feedback.menu_entry_id)
        if context is not None and context.feedback_cb is not None:
            context.feedback_cb(feedback)

    def _push(self, handles: list[int], entries: list[Any], parent: int) -> None:
        for handle in handles:
            context = self.entry_contexts[handle]
            if not context.visible:
                continue
            entries.append(self._entry(handle, context, parent))
            self._push(context.sub_entries, entries, handle)

    def _entry(self, handle: int, context: _Entry, parent: int) -> Any:
        title = context.title
        if context.check_state == self.CHECKED:
            title = "[x] " + title
        elif context.check_state == self.UNCHECKED:
            title = "[ ] " + title
        return MenuEntry(
            id=handle,
            parent_id=parent,
            title=title,
            command=context.command,
            command_type=context.command_type,
        )
