"""Errors of the bag tools: missing, unreadable, damaged and unwritable bags; damage warnings."""

from __future__ import annotations

import contextlib
import sys
import warnings
from collections.abc import Iterator
from typing import Any

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


class BagWarning(UserWarning):
    """Part of a bag could not be read and was skipped (the text names the byte offset)."""


@contextlib.contextmanager
def warnings_as_lines(stream: Any = None) -> Iterator[None]:
    """Print every :class:`BagWarning` of the block as one ``[WARN] ...`` line (command line)."""

    def show(message: Any, category: Any, *args: Any, **kwargs: Any) -> None:
        if issubclass(category, BagWarning):
            print(f"[WARN] {message}", file=stream or sys.stderr, flush=True)
        else:
            previous(message, category, *args, **kwargs)

    with warnings.catch_warnings():
        warnings.simplefilter("always", BagWarning)
        previous = warnings.showwarning
        warnings.showwarning = show
        yield
