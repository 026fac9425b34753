"""Find a robot description by name or path and read it as URDF or SDF text."""

from __future__ import annotations

import contextlib
import io
import os
from dataclasses import dataclass
from pathlib import Path

from workbench.errors import ModelError
from workbench.model.robot_library import INSTALL_HINT, library_robot, library_robots, library_root
from workbench.paths import is_dir, is_file, urdf_dir

#: Suffixes tried, in order, for a bare name such as ``robot_arm``.
NAME_SUFFIXES = (".urdf", ".urdf.xacro", ".xacro", ".sdf")


class XacroError(ModelError):
    """Expanding a xacro file failed."""


@dataclass
class DescriptionText:
    """The text of a description, ready for a parser.

    Attributes:
        path: The file it was read from.
        text: URDF or SDF XML (xacro already expanded).
        format: ``"urdf"`` or ``"sdf"``.
        expanded: True when ``text`` came out of xacro.
    """

    path: Path
    text: str
    format: str
    expanded: bool = False


def is_xacro(path: Path) -> bool:
    return path.name.endswith(".xacro")


def resolve_robot_path(source: str | os.PathLike[str]) -> Path:
    """Turn a name from ``urdf/`` or a file path into the path of a description.

    ``robot_arm`` becomes ``urdf/robot_arm.urdf`` (then ``.urdf.xacro``,
    ``.xacro``, ``.sdf``); anything that exists as a file is returned as is.

    Raises:
        ModelError: Nothing was found; the message lists what was tried.
    """
    text = os.fspath(source)
    path = Path(text).expanduser()
    if is_file(path):
        return path.resolve()
    if is_dir(path):
        raise ModelError(
            "is a directory, not a robot description",
            path=path,
            hint="give a .urdf, .sdf or .xacro file",
        )
    tried = [path]
    looks_like_name = os.sep not in text and "/" not in text and not path.suffix
    if looks_like_name:
        directory = urdf_dir()
        for suffix in NAME_SUFFIXES:
            candidate = directory / f"{text}{suffix}"
            tried.append(candidate)
            if is_file(candidate):
                return candidate.resolve()
        described = library_robot(text)
        if described is not None:
            return described
    else:
        raise ModelError(
            "no such file", path=path, hint="check the path, or give a name from urdf/"
        )
    names = available_robots()
    hint = "give a path to a .urdf, .sdf or .xacro file"
    if names:
        hint += " or one of: " + ", ".join(names)
    if library_root() is None:
        hint += f"; well-known robots (panda, ur5, ...) come with {INSTALL_HINT}"
    else:
        hint += " or a robot of example-robot-data (" + ", ".join(library_robots()) + ")"
    raise ModelError(
        f"no robot description '{text}' (tried {', '.join(str(t) for t in tried)})", hint=hint
    )


def available_robots() -> list[str]:
    """Names of the descriptions in ``urdf/`` (:func:`resolve_robot_path` also takes the
    robots of an installed description package, :func:`library_robots`)."""
    directory = urdf_dir()
    if not directory.is_dir():
        return []
    names = set()
    for child in directory.iterdir():
        for suffix in NAME_SUFFIXES:
            if child.name.endswith(suffix) and child.is_file():
                names.add(child.name[: -len(suffix)])
                break
    return sorted(names)


def expand_xacro(path: Path, mappings: dict[str, str] | None = None) -> str:
    """Run xacro on ``path`` and return the URDF text.

    Expressions, includes, ``load_yaml`` and substitutions run in workbench's
    sandbox (:mod:`workbench.model.xacro_sandbox`): the file can compute, read files
    of its own package, and nothing else, within the bounds of
    :mod:`workbench.model.limits`.

    Raises:
        XacroError: xacro failed or the file reached past the sandbox; the message
            carries the reason and names the (included) file it happened in.
    """
    try:
        from workbench.model import xacro_sandbox
    except ImportError as error:  # pragma: no cover - xacro is a dependency
        raise XacroError(
            f"xacro is not installed ({error})", path=path, hint="pip install xacro"
        ) from None
    captured = io.StringIO()
    try:
        with contextlib.redirect_stderr(captured), contextlib.redirect_stdout(captured):
            return xacro_sandbox.expand(path, mappings)
    except Exception as error:  # xacro raises XacroException, NameError, ExpatError ...
        where = getattr(error, "workbench_file", None) or path
        message, hint = _xacro_reason(error)
        raise XacroError(f"xacro failed: {message}", path=where, hint=hint) from None


def _xacro_reason(error: Exception) -> tuple[str, str]:
    """One line saying why xacro failed, and what to do."""
    hint = "fix the xacro source and run it again"
    cause = getattr(error, "exc", None)
    if isinstance(error, ModelError):
        return error.message, error.hint or hint
    if isinstance(cause, ModelError):
        suffix = _shortened(" ".join(str(getattr(error, "suffix", "") or "").split()))
        return " ".join(f"{cause.message} {suffix}".split()), cause.hint or hint
    if isinstance(error, RecursionError) or isinstance(cause, RecursionError):
        return "the XML or its macros are nested too deeply (a macro that calls itself?)", hint
    if isinstance(error, MemoryError) or isinstance(cause, MemoryError):
        return "out of memory", hint
    return _shortened(" ".join(str(error).split())) or type(error).__name__, hint


def _shortened(text: str, length: int = 400) -> str:
    """xacro repeats the whole expression in its messages; keep a readable start of it."""
    return text if len(text) <= length else text[: length - 5] + " ...'"


def read_description(path: Path, mappings: dict[str, str] | None = None) -> DescriptionText:
    """Read a description file, expanding xacro, and tell URDF from SDF.

    Raises:
        ModelError: The file cannot be read; :class:`XacroError` when xacro fails.
    """
    if is_xacro(path):
        text = expand_xacro(path, mappings)
        return DescriptionText(path, text, "urdf", expanded=True)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ModelError(
            "the file is not UTF-8 text", path=path, hint="is it really a URDF/SDF file?"
        ) from None
    except OSError as error:
        raise ModelError(f"cannot read the file: {error.strerror}", path=path) from None
    head = text.lstrip()[:2000]
    fmt = "sdf" if path.suffix.lower() == ".sdf" or "<sdf" in head.split("<robot")[0] else "urdf"
    return DescriptionText(path, text, fmt)
