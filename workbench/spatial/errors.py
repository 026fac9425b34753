"""The error raised for malformed poses and shapes."""

from __future__ import annotations

from workbench.errors import WorkbenchError


class SpatialError(WorkbenchError, ValueError):
    """A pose, rotation or shape given with the wrong number, kind or range of values."""
