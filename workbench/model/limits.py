"""Bounds on what a model file may ask of workbench, and the checks that apply them.

A model from the internet is input like any other: it may not make workbench
read forever, allocate without end or hand Drake something it aborts on. The
bounds are far above any real robot (the lab's largest has 16 links) and are
listed in the README under "Limits on input".
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path

from workbench.errors import ModelError

#: Largest model file (URDF, SDF, xacro and its includes, YAML it loads), and largest
#: expanded xacro output, bytes.
MAX_MODEL_BYTES = 64 * 1024 * 1024
#: Largest mesh file, bytes (a mesh is read whole by Drake and by trimesh).
MAX_MESH_BYTES = 256 * 1024 * 1024
#: Longest name of a robot, link, joint, material or model, characters.
MAX_NAME_LENGTH = 256
#: Most links (and, separately, most joints) in one model.
MAX_LINKS = 10_000
#: Largest size of a shape (box edge, radius, length), m: a thousand kilometres. Drake's
#: collision code overflows on sizes near the largest float (a 1e308 m box crashes it).
MAX_SHAPE_SIZE = 1e6
#: Most XML elements xacro may process for one file, macros expanded.
MAX_XACRO_ELEMENTS = 200_000


def _size_text(size: int) -> str:
    return f"{size / (1024 * 1024):.0f} MiB" if size >= 1024 * 1024 else f"{size} bytes"


def check_input_file(
    path: str | os.PathLike[str],
    what: str = "model file",
    limit: int = MAX_MODEL_BYTES,
    *,
    where: str | os.PathLike[str] | None = None,
    line: int | None = None,
) -> Path:
    """Check that ``path`` is a regular file of at most ``limit`` bytes before it is read.

    A FIFO or device would block or never end; a huge (or sparse) file would fill memory.

    Args:
        path: The file.
        what: What it is, for the message (``mesh``, ``model file``).
        limit: Largest size, bytes.
        where: The file that refers to it (the error names that file and ``line``);
            None names ``path`` itself.
        line: The line in ``where``.

    Returns:
        ``path`` as a :class:`Path`.

    Raises:
        ModelError: Missing, not a regular file, or too big.
    """
    path = Path(path)
    named = path if where is None else where
    subject = "" if where is None else f"{what} {path}: "
    try:
        info = path.stat()
    except OSError as error:
        raise ModelError(
            f"{subject}cannot read the {what}: {error.strerror}", path=named, line=line
        ) from None
    if not stat.S_ISREG(info.st_mode):
        kind = "a directory" if stat.S_ISDIR(info.st_mode) else "not a regular file"
        raise ModelError(
            f"{subject}the {what} is {kind}; a pipe or device would never end",
            path=named,
            line=line,
            hint=f"give a {what} that is a regular file",
        )
    if info.st_size > limit:
        raise ModelError(
            f"{subject}the {what} has {_size_text(info.st_size)}; workbench reads at most "
            f"{_size_text(limit)}",
            path=named,
            line=line,
            hint=f"is it really a {what}? See 'Limits on input' in the README",
        )
    return path


def name_problem(name: str) -> str | None:
    """Why ``name`` cannot name a robot, link, joint or material, or None when it can.

    A name has 1 to :data:`MAX_NAME_LENGTH` characters, none of them a control
    character (line breaks, tabs, NUL): Drake crashes on very long names, and a
    line break would split every one-line message about the element.
    """
    if not name.strip():
        return "is empty"
    if not name.replace("::", "").strip():
        return "is only Drake's scope separator '::'"
    if len(name) > MAX_NAME_LENGTH:
        return f"has {len(name):,} characters; at most {MAX_NAME_LENGTH}"
    bad = next((c for c in name if ord(c) < 32 or 127 <= ord(c) < 160), None)
    if bad is not None:
        return f"contains the control character {bad!r}"
    return None


#: Longest ``<uri>`` of an ``<include>`` or mesh, and longest part of it between slashes,
#: characters (what a file system takes: PATH_MAX and NAME_MAX on Linux).
MAX_URI_LENGTH, MAX_URI_PART = 4096, 255


def uri_problem(uri: str) -> str | None:
    """Why ``uri`` cannot name a model or file, or None (a name no file system holds)."""
    if len(uri) > MAX_URI_LENGTH:
        return f"has {len(uri):,} characters; at most {MAX_URI_LENGTH:,}"
    longest = max((len(part) for part in uri.split("/")), default=0)
    if longest > MAX_URI_PART:
        return f"has a name of {longest:,} characters; a file name has at most {MAX_URI_PART}"
    if any(ord(c) < 32 for c in uri):
        return "contains a control character"
    return None


def shown_name(name: str, length: int = 40) -> str:
    """``name`` cut to ``length`` characters with control characters escaped, for messages."""
    text = name.encode("unicode_escape").decode("ascii") if name_problem(name) else name
    return text if len(text) <= length else text[: length - 3] + "..."


def file_stem_problem(name: str) -> str | None:
    """Why a robot name cannot be used as a file name (``NAME.gv``), or None."""
    problem = name_problem(name)
    if problem is not None:
        return problem
    if "/" in name or "\\" in name or name in (".", ".."):
        return "contains a path separator"
    return None


_DEPTH = re.compile(r"Excessive depth in document: (\d+).*")


def xml_error_text(message: str) -> str:
    """lxml's complaint about a file as one line, without its position or libxml2's advice.

    ``Excessive depth in document: 2048, use XML_PARSE_HUGE option`` becomes
    ``elements are nested more than 2048 deep``: an option of libxml2 is no advice
    for whoever wrote the model.
    """
    text = " ".join(re.sub(r",? line \d+, column \d+", "", message).split())
    return _DEPTH.sub(lambda match: f"elements are nested more than {match.group(1)} deep", text)
