"""Errors of the bag tools: missing, unreadable, damaged and unwritable bags."""

from __future__ import annotations

from workbench.errors import BagError


class BagNotFoundError(BagError):
    """The bag file does not exist."""


class BagFormatError(BagError):
    """The file is not a ROS 1 bag v2.0 (wrong magic, version or encryption)."""


class BagDamagedError(BagError):
    """The bag is truncated or corrupt; the readable part is in :attr:`recovered`.

    Attributes:
        recovered: Messages that could be read before the damage.
    """

    def __init__(self, message: str, *, path=None, hint=None, recovered: int = 0) -> None:
        super().__init__(message, path=path, hint=hint)
        self.recovered = recovered


class BagWriteError(BagError):
    """The bag cannot be written (directory missing, permission, disk full)."""
