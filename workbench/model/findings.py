"""One problem found in a robot description, as ``check`` reports it."""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class Finding:
    """An error or warning about one element of a description.

    Attributes:
        severity: ``"error"`` (the model is wrong) or ``"warning"`` (it works, but ...).
        code: A stable short name, e.g. ``inertia-not-positive-definite``.
        element: The element concerned, e.g. ``link 'base_link'``.
        message: What is wrong.
        hint: What to do about it.
        line: Line in the file, if known.
    """

    severity: str
    code: str
    element: str
    message: str
    hint: str = ""
    line: int | None = None

    def format(self, path: str | None = None) -> str:
        """``path:line: error: element: message (hint)`` on one line."""
        where = ""
        if path:
            where = f"{path}:{self.line}: " if self.line else f"{path}: "
        text = f"{where}{self.severity}: {self.element}: {self.message}"
        if self.hint:
            text += f" ({self.hint})"
        return text

    def to_dict(self) -> dict:
        return asdict(self)
