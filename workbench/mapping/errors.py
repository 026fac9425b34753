"""Errors raised by :mod:`workbench.mapping` (all are :class:`~workbench.errors.MappingError`)."""

from __future__ import annotations

from workbench.errors import MappingError


class LogError(MappingError):
    """A laser log (CARMEN or ROS bag) is missing, unreadable or holds no laser scans."""


class MapFileError(MappingError):
    """A map_server map (YAML + image) is missing, incomplete or cannot be written."""
