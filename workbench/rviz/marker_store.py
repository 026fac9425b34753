"""Which markers are shown: RViz's marker display bookkeeping, without any drawing.

Semantics of rviz's ``MarkerDisplay`` (noetic): markers are keyed by
``(ns, id)``; ADD (= MODIFY) replaces the marker with that key; DELETE removes
it; DELETEALL (action 3) removes every marker of the display; a marker whose
``lifetime`` is above zero disappears that long after it arrived; a
``frame_locked`` marker is re-posed through tf on every update, the others keep
the pose tf gave them when they arrived. A marker that fails RViz's checks
(:mod:`workbench.rviz.marker_check`) is not shown and its status says why.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from workbench.rviz.marker_check import ADD, DELETE, DELETEALL, MarkerStatus, check_marker

MarkerKey = tuple[str, int]


@dataclass
class ShownMarker:
    """A marker being shown: the message, when it arrived and when it expires (s)."""

    message: Any
    received: float
    expires: float | None
    pose: Any = None  # X_FM in the fixed frame, set by the display


@dataclass
class MarkerStore:
    """The markers of one display and their statuses (``"ns/id" -> MarkerStatus``)."""

    markers: dict[MarkerKey, ShownMarker] = field(default_factory=dict)
    statuses: dict[str, MarkerStatus] = field(default_factory=dict)

    def process(self, marker: Any, now: float) -> tuple[list[MarkerKey], list[MarkerKey]]:
        """Apply one message; returns ``(keys to draw, keys to erase)``."""
        key: MarkerKey = (marker.ns, int(marker.id))
        label = f"{marker.ns}/{marker.id}"
        if marker.action == DELETEALL:
            gone = list(self.markers)
            self.markers.clear()
            self.statuses.clear()
            return [], gone
        if marker.action == DELETE:
            self.statuses.pop(label, None)
            return ([], [key]) if self.markers.pop(key, None) is not None else ([], [])
        if marker.action != ADD:
            self.statuses[label] = MarkerStatus("error", f"Unknown marker action: {marker.action}")
            return [], []
        status = check_marker(marker)
        if status is not None:
            self.statuses[label] = status
            if status.fatal:
                return ([], [key]) if self.markers.pop(key, None) is not None else ([], [])
        else:
            self.statuses.pop(label, None)
        lifetime = _seconds(marker.lifetime)
        expires = now + lifetime if lifetime > 0.0001 else None
        self.markers[key] = ShownMarker(marker, now, expires)
        return [key], []

    def expire(self, now: float) -> list[MarkerKey]:
        """Drop the markers whose lifetime is over; returns their keys."""
        gone = [k for k, m in self.markers.items() if m.expires is not None and now >= m.expires]
        for key in gone:
            del self.markers[key]
            self.statuses.pop(f"{key[0]}/{key[1]}", None)
        return gone

    def frame_locked(self) -> list[MarkerKey]:
        """Keys of the markers to re-pose on every update."""
        return [k for k, m in self.markers.items() if m.message.frame_locked]


def _seconds(duration: Any) -> float:
    for sec, nsec in (("sec", "nanosec"), ("secs", "nsecs")):
        if hasattr(duration, sec):
            return float(getattr(duration, sec)) + float(getattr(duration, nsec)) * 1e-9
    return float(duration)
