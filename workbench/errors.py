"""One exception hierarchy for the whole workbench.

Every error a user can cause derives from :class:`WorkbenchError`. It carries
*where* the problem is (file, line, or the name of a frame, topic, joint ...)
and *what to do* about it, so the command line can print a single line
without a traceback.

Capabilities derive their own, more specific errors from the category
classes below (for example ``planning`` raises subclasses of
:class:`PlanningError`).
"""

from __future__ import annotations

import os

#: Characters that would break an error's single line, and how they are shown instead.
_ONE_LINE = str.maketrans({"\n": "\\n", "\r": "\\r", "\t": "\\t", "\v": "\\v", "\f": "\\f"})


class WorkbenchError(Exception):
    """Base class of every error workbench raises on bad input or bad state.

    Args:
        message: What is wrong, in one sentence.
        path: The file concerned, if any.
        line: The 1-based line in ``path``, if known.
        hint: What the user should do about it.
    """

    exit_code: int = 1

    def __init__(
        self,
        message: str,
        *,
        path: str | os.PathLike[str] | None = None,
        line: int | None = None,
        hint: str | None = None,
    ) -> None:
        self.message = message
        self.path = os.fspath(path) if path is not None else None
        self.line = line
        self.hint = hint
        super().__init__(self.one_line())

    def one_line(self) -> str:
        """The error as one line: ``path:line: message (hint)``."""
        where = ""
        if self.path is not None:
            where = self.path if self.line is None else f"{self.path}:{self.line}"
            where += ": "
        text = f"{where}{self.message}"
        if self.hint:
            text += f" ({self.hint})"
        return text


class MissingDependencyError(WorkbenchError, ImportError):
    """An optional Python package (an extra) or a system program is missing."""


# --- categories, one per layer -------------------------------------------------


class MessageError(WorkbenchError):
    """Unknown message type, wrong field name or value, bad serialized bytes."""


class BusError(WorkbenchError):
    """Names, topics, services, parameters, transports and the core."""


class BagError(WorkbenchError):
    """Missing, truncated, corrupt or unwritable bag files."""


class TransformError(WorkbenchError):
    """Base of tf's exceptions (tf2's LookupException and friends derive from it)."""


class ModelError(WorkbenchError):
    """A robot description (URDF, SDF, xacro) cannot be read or loaded.

    Names in its message come from the file and may hold line breaks or tabs; they are
    shown as ``\\n`` and ``\\t``, so the error stays one line whatever the file held.
    """

    def one_line(self) -> str:
        """The error as one line: ``path:line: message (hint)``, line breaks escaped."""
        return super().one_line().translate(_ONE_LINE)


class ViewerError(WorkbenchError):
    """Meshcat, snapshots and rendering."""


class SimulationError(WorkbenchError):
    """Building or running a ``sim.World``."""


class PlanningError(WorkbenchError):
    """Setup, goals, collision, IK, planning, timing and execution."""


class MappingError(WorkbenchError):
    """Logs, occupancy grids, SLAM and map files."""


class SerialError(WorkbenchError):
    """rosserial links and serial ports."""
