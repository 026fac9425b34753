"""The bus's errors (all :class:`~workbench.errors.BusError`)."""

from __future__ import annotations

from workbench.bus.clock import ShutdownInterrupt
from workbench.bus.names import InvalidNameError
from workbench.bus.params import ParameterError
from workbench.errors import BusError


class TopicTypeError(BusError):
    """Two ends of a topic (or service) disagree on its type (md5sum)."""


class ServiceError(BusError):
    """A service call failed: nobody offers it, the handler raised, or it timed out."""


class ServiceTimeout(ServiceError, TimeoutError):
    """``wait_for_service`` or a call with a timeout ran out of time."""


class CoreError(BusError):
    """The core cannot be reached, or cannot be started (port in use)."""


class ShutdownError(BusError):
    """The node or bus has been shut down."""


__all__ = [
    "BusError",
    "CoreError",
    "InvalidNameError",
    "ParameterError",
    "ServiceError",
    "ServiceTimeout",
    "ShutdownError",
    "ShutdownInterrupt",
    "TopicTypeError",
]
