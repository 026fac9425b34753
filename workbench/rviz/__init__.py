"""RViz in the browser: displays that draw the bus's topics in Drake's Meshcat.

``from workbench.rviz import RViz``; see :mod:`workbench.rviz.rviz`. The
displays are in :mod:`workbench.rviz.displays` and
:mod:`workbench.rviz.marker_display`; RViz's marker checks in
:mod:`workbench.rviz.marker_check`.
"""

from __future__ import annotations

from typing import Any

__all__ = ["RViz"]


def __getattr__(name: str) -> Any:
    if name == "RViz":
        from workbench.rviz.rviz import RViz

        return RViz
    raise AttributeError(f"module 'workbench.rviz' has no attribute '{name}'")
