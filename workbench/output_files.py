"""Before workbench writes a file the user named: the folder must exist, the target must be ours.

Commands write where they are told (``--json traj.json``, ``-o robot.pdf``), and
nowhere else: a missing folder is an error (it is never created), a directory,
pipe or device is refused (``/dev/full`` would swallow a plot and report success),
and an existing file is replaced only when it is the kind of file workbench writes
there (:data:`KINDS`): a trajectory JSON by a trajectory JSON, a Meshcat snapshot by a
snapshot, a PNG by a PNG. Anything else (``--json package.json``, ``--csv notes.txt``)
is someone's file and stays untouched. Writing goes through a temporary file in the
same folder, so a failed write leaves the old file as it was.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Callable
from pathlib import Path

from workbench.errors import WorkbenchError

_HEAD_BYTES = 65536


def _starts(*prefixes: bytes) -> Callable[[bytes], bool]:
    return lambda head: head.lstrip().startswith(prefixes)


def _contains(prefix: bytes, marker: bytes) -> Callable[[bytes], bool]:
    return lambda head: head.startswith(prefix) and marker in head


#: Kind of output -> (what it is, test of a file's first bytes that says it is one).
KINDS: dict[str, tuple[str, Callable[[bytes], bool]]] = {
    "trajectory-json": ("a trajectory JSON", _starts(b'{"joint_names"')),
    "trajectory-csv": ("a trajectory CSV", _starts(b"t,", b"t\r\n", b"t\n")),
    "png": ("a PNG image", _starts(b"\x89PNG\r\n\x1a\n")),
    "pdf": ("a PDF", _starts(b"%PDF-")),
    "svg": ("an SVG drawing", lambda head: b"<svg" in head),
    "html-snapshot": ("a Meshcat snapshot", lambda head: b"meshcat" in head.lower()),
    "graphviz": ("a graphviz graph", _starts(b"digraph")),
    "planning-yaml": (
        "a planning.yaml written by workbench setup",
        _contains(b"#", b"workbench setup"),
    ),
    "srdf": (
        "an SRDF written by workbench setup",
        lambda head: b"Semantic description of the robot for planning" in head,
    ),
    "building-sdf": (
        "an SDF file written by workbench world build",
        lambda head: b"<sdf" in head and b"Written by 'workbench world build'" in head,
    ),
    "building-model-config": (
        "a model.config written by workbench world build",
        lambda head: b"<model" in head and b"Written by 'workbench world build'" in head,
    ),
}


def _short(text: str) -> str:
    """A path for a message: a 5,000-character one is cut to 100."""
    return text if len(text) <= 100 else text[:97] + "..."


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except (OSError, ValueError):  # a name too long to look up: no such folder
        return False


def _refuse(message: str, hint: str, error: type[WorkbenchError]) -> WorkbenchError:
    return error(message, hint=hint)


def check_output(
    path: str | os.PathLike[str],
    kind: str,
    *,
    option: str | None = None,
    error: type[WorkbenchError] = WorkbenchError,
) -> Path:
    """Check that ``path`` may be written as ``kind`` (see :data:`KINDS`), before any work.

    Args:
        path: Where the user asked for the output.
        kind: A key of :data:`KINDS`.
        option: The option that named it (``--json``), for the message.
        error: The error class to raise (a capability's own).

    Returns:
        ``path`` as a :class:`Path`.

    Raises:
        WorkbenchError: (of class ``error``) the folder is missing or not writable, the
            target is a directory, pipe or device, or an existing file of another kind.
    """
    path = Path(path)
    what, looks_ours = KINDS[kind]
    label = f"{option} {_short(str(path))}" if option else _short(str(path))
    folder = path.parent if str(path.parent) else Path(".")
    if not _is_dir(folder):
        raise _refuse(
            f"cannot write {label}: the folder {_short(str(folder))} does not exist",
            "create it first; workbench does not create folders",
            error,
        )
    try:
        info = path.stat()
    except FileNotFoundError:
        _probe(path, label, error)
        return path
    except OSError as problem:
        raise _refuse(
            f"cannot write {label}: {problem.strerror}", "choose another name", error
        ) from None
    if not stat.S_ISREG(info.st_mode):
        kind_text = "a directory" if stat.S_ISDIR(info.st_mode) else "not a regular file"
        raise _refuse(
            f"cannot write {label}: it is {kind_text}", f"give a file name for {what}", error
        )
    try:
        with path.open("rb") as handle:
            head = handle.read(_HEAD_BYTES)
    except OSError as problem:
        raise _refuse(
            f"cannot write {label}: {problem.strerror}", "choose another name", error
        ) from None
    if head.strip() and not looks_ours(head):
        raise _refuse(
            f"will not overwrite {label}: it is not {what}",
            "choose another name, or remove the file first",
            error,
        )
    return path


def _probe(path: Path, label: str, error: type[WorkbenchError]) -> None:
    """Create and remove the new file once, so a folder that takes no files fails now.

    ``os.access`` says yes to root everywhere, also in ``/proc``; only trying tells.
    """
    try:
        handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except FileExistsError:
        return  # appeared meanwhile: checked again when it is written
    except OSError as problem:
        raise _refuse(
            f"cannot write {label}: {problem.strerror}", "choose a folder you can write to", error
        ) from None
    os.close(handle)
    with contextlib.suppress(OSError):
        os.unlink(path)


def write_output(
    path: str | os.PathLike[str],
    data: str | bytes,
    *,
    error: type[WorkbenchError] = WorkbenchError,
) -> Path:
    """Write ``data`` to ``path`` through a temporary file in the same folder.

    Call :func:`check_output` first. A full disk or a vanished folder leaves the old
    file untouched and raises.

    Raises:
        WorkbenchError: (of class ``error``) the write failed.
    """
    path = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    folder = path.parent if str(path.parent) else Path(".")
    temporary = None
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
        with os.fdopen(handle, "wb") as stream:
            stream.write(payload)
            stream.flush()
            os.fsync(stream.fileno())
        if path.exists():
            os.chmod(temporary, stat.S_IMODE(path.stat().st_mode))
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
        temporary = None
    except OSError as problem:
        raise error(f"cannot write {path}: {problem.strerror}") from None
    finally:
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
    return path
