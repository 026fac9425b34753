"""Errors of the costmaps and the global planner (all are :class:`~workbench.errors.MappingError`)."""

from __future__ import annotations

from workbench.errors import MappingError


class CostmapError(MappingError):
    """A costmap or planner parameter has the wrong type or value (the message names it)."""


__all__ = ["CostmapError"]
