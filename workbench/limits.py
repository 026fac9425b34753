"""Bounds on what workbench reads: files, YAML documents and nested values.

Every input a user (or a file from the internet) can hand to workbench is
read within a bound, and going past it is a one-line error naming the input
and the bound, never a hang, a ``MemoryError`` or a ``RecursionError``:

* files: only regular files are read (a FIFO would block forever and
  ``/dev/zero`` never ends), up to a size given per kind of file;
* YAML: the text is checked event by event (libyaml's parser does not
  recurse) before anything is built, so nesting depth and the size *after
  alias expansion* are known first: a 244-byte "billion laughs" document is
  refused instead of growing into gigabytes wherever it is copied or sent;
* values (parameters, messages built from YAML): depth, number of elements
  and bytes of text, counted without recursion.

The numbers are in README's "Limits on data" section. Callers pass their own
error class (a :class:`~workbench.errors.WorkbenchError` subclass), so a
launch file's limit is a ``LaunchError`` and a map's a ``MapFileError``.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from workbench.errors import WorkbenchError

MiB = 1024 * 1024

#: Largest text file read as a whole (YAML, launch files, textfile= parameters), bytes.
MAX_TEXT_FILE_BYTES = 16 * MiB

#: Longest duration or timeout a command-line option takes, s (about 116 days): ``inf``
#: would never end and ``1e308`` overflows a clock's deadline.
MAX_OPTION_SECONDS = 10_000_000.0

#: Largest ``--seed`` an option takes (numpy's and OMPL's seeds are unsigned 32-bit).
MAX_SEED = 2**32 - 1


@dataclass(frozen=True)
class TreeLimits:
    """Bounds on a nested value (YAML after alias expansion, or a parameter).

    Attributes:
        max_depth: Nesting levels of lists and dicts (a scalar at the top is depth 0).
        max_nodes: Lists, dicts and scalars, counted once per appearance.
        max_bytes: Characters of all strings and keys together (numbers count 8).
    """

    max_depth: int = 64
    max_nodes: int = 1_000_000
    max_bytes: int = 64 * MiB


#: The bounds of a YAML document read from a file or the command line.
YAML_LIMITS = TreeLimits()


def human_bytes(size: int) -> str:
    """``1536`` -> ``1.5 KiB``; for messages about sizes."""
    value = float(size)
    for unit in ("bytes", "KiB", "MiB", "GiB"):
        if value < 1024 or unit == "GiB":
            return f"{int(value)} bytes" if unit == "bytes" else f"{value:.1f} {unit}"
        value /= 1024
    return f"{value:.1f} GiB"  # pragma: no cover - the loop returns


# --- files --------------------------------------------------------------------------------


def check_regular_file(
    path: str | os.PathLike[str], what: str, error: type[WorkbenchError] = WorkbenchError
) -> int:
    """Check ``path`` is a regular file that can be read; returns its size in bytes.

    Raises:
        error: No such file, a directory, a FIFO, socket or device, or no permission.
    """
    try:
        info = os.stat(path)
    except FileNotFoundError:
        raise error(f"cannot read {what}: no such file", path=path) from None
    except OSError as exc:
        raise error(f"cannot read {what}: {exc.strerror or exc}", path=path) from None
    if stat.S_ISDIR(info.st_mode):
        raise error(f"is a directory, not a {what}", path=path)
    if not stat.S_ISREG(info.st_mode):
        kind = (
            "a FIFO (named pipe)"
            if stat.S_ISFIFO(info.st_mode)
            else "a device"
            if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode)
            else "not a regular file"
        )
        raise error(
            f"is {kind}; a {what} must be a regular file",
            path=path,
            hint="copy the data into a regular file first",
        )
    return info.st_size


def read_bytes_bounded(
    path: str | os.PathLike[str],
    what: str,
    max_bytes: int,
    error: type[WorkbenchError] = WorkbenchError,
) -> bytes:
    """The bytes of a regular file of at most ``max_bytes``.

    Raises:
        error: Not a readable regular file, or larger than ``max_bytes``.
    """
    check_regular_file(path, what, error)
    try:
        with open(path, "rb") as stream:
            data = stream.read(max_bytes + 1)
    except OSError as exc:
        raise error(f"cannot read {what}: {exc.strerror or exc}", path=path) from None
    if len(data) > max_bytes:
        raise error(
            f"{what} is larger than {human_bytes(max_bytes)}, the limit for such files",
            path=path,
            hint="is it the right file?",
        )
    return data


def read_text_bounded(
    path: str | os.PathLike[str],
    what: str,
    error: type[WorkbenchError] = WorkbenchError,
    max_bytes: int = MAX_TEXT_FILE_BYTES,
) -> str:
    """The UTF-8 text of a regular file of at most ``max_bytes``.

    Raises:
        error: Not a readable regular file, too large, or not UTF-8 text.
    """
    data = read_bytes_bounded(path, what, max_bytes, error)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise error(
            f"{what} is not UTF-8 text (byte 0x{data[exc.start]:02x} at offset {exc.start})",
            path=path,
            line=line,
            hint="is it a binary file?",
        ) from None


# --- nested values --------------------------------------------------------------------------


def _children(value: Any) -> Iterator[Any]:
    if isinstance(value, dict):
        for key, child in value.items():
            yield key
            yield child
    else:
        yield from value


def tree_size(value: Any) -> tuple[int, int]:
    """``(nodes, bytes)`` of a nested value (already within bounds), counted without recursion.

    Lists, tuples and dicts are containers; everything else is a leaf: strings
    and bytes weigh their length, other leaves 8.
    """
    nodes = size = 0
    stack = [value]
    while stack:
        item = stack.pop()
        nodes += 1
        if isinstance(item, (list, tuple, dict)):
            stack.extend(_children(item))
        else:
            size += len(item) if isinstance(item, (str, bytes)) else 8
    return nodes, size


def check_tree(
    value: Any,
    what: str,
    limits: TreeLimits,
    error: type[WorkbenchError] = WorkbenchError,
    path: str | os.PathLike[str] | None = None,
) -> None:
    """Refuse a value deeper, larger or longer than ``limits``.

    The walk stops as soon as a bound is passed, so even a value of millions of
    elements costs only up to the bound.

    Raises:
        error: A bound is passed; the message names ``what`` and the bound.
    """
    nodes = size = 0
    stack: list[tuple[Any, int]] = [(value, 0)]
    while stack:
        item, level = stack.pop()
        nodes += 1
        if nodes > limits.max_nodes:
            raise error(
                f"{what} has more than {limits.max_nodes:,} elements",
                path=path,
                hint="split it, or load the data from a file of its own",
            )
        if isinstance(item, (list, tuple, dict)):
            if level + 1 > limits.max_depth:
                raise error(
                    f"{what} is nested more than {limits.max_depth} levels deep",
                    path=path,
                    hint="flatten it",
                )
            stack.extend((child, level + 1) for child in _children(item))
        else:
            size += len(item) if isinstance(item, (str, bytes)) else 8
            if size > limits.max_bytes:
                raise error(
                    f"{what} holds more than {human_bytes(limits.max_bytes)} of text",
                    path=path,
                    hint="keep large data in files, not in one value",
                )


# --- YAML ---------------------------------------------------------------------------------


def _yaml_module() -> Any:
    import yaml

    return yaml


def _loader() -> Any:
    yaml = _yaml_module()
    return getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def _yaml_error_line(exc: Exception) -> int | None:
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    return mark.line + 1 if mark is not None else None


def check_yaml(
    text: str,
    what: str,
    limits: TreeLimits = YAML_LIMITS,
    error: type[WorkbenchError] = WorkbenchError,
    path: str | os.PathLike[str] | None = None,
) -> None:
    """Walk the YAML events of ``text`` and refuse it past ``limits`` (aliases expanded).

    An anchored node's expanded size is remembered when it ends, so ``*alias``
    adds what it stands for; an alias to a node still being read (a recursive
    structure) is refused.

    Raises:
        error: Invalid YAML (with the line) or a bound passed.
    """
    yaml = _yaml_module()
    events = yaml.events
    # per open collection: [nodes, bytes, anchor]; per anchor: (nodes, bytes, depth below)
    stack: list[list[Any]] = [[0, 0, None, 0]]
    anchors: dict[str, tuple[int, int, int]] = {}

    def add(nodes: int, size: int, below: int) -> None:
        top = stack[-1]
        top[0] += nodes
        top[1] += size
        top[3] = max(top[3], below)
        total_nodes = sum(frame[0] for frame in stack)
        total_size = sum(frame[1] for frame in stack)
        if total_nodes > limits.max_nodes:
            raise error(
                f"{what} has more than {limits.max_nodes:,} elements once its aliases are expanded",
                path=path,
                line=line,
                hint="is it a YAML 'billion laughs' bomb?",
            )
        if total_size > limits.max_bytes:
            raise error(
                f"{what} holds more than {human_bytes(limits.max_bytes)} of text once its "
                "aliases are expanded",
                path=path,
                line=line,
            )
        if len(stack) - 1 + below > limits.max_depth:
            raise error(
                f"{what} is nested more than {limits.max_depth} levels deep",
                path=path,
                line=line,
                hint="flatten it",
            )

    line: int | None = None
    try:
        for event in yaml.parse(text, Loader=_loader()):
            mark = getattr(event, "start_mark", None)
            line = mark.line + 1 if mark is not None else line
            if isinstance(event, (events.SequenceStartEvent, events.MappingStartEvent)):
                stack.append([1, 0, event.anchor, 0])
                if len(stack) - 1 > limits.max_depth:
                    add(0, 0, 0)
            elif isinstance(event, (events.SequenceEndEvent, events.MappingEndEvent)):
                nodes, size, anchor, below = stack.pop()
                if anchor is not None:
                    anchors[anchor] = (nodes, size, below + 1)
                add(nodes, size, below + 1)
            elif isinstance(event, events.ScalarEvent):
                if event.anchor is not None:
                    anchors[event.anchor] = (1, len(event.value), 0)
                add(1, len(event.value), 0)
            elif isinstance(event, events.AliasEvent):
                if event.anchor not in anchors:
                    raise error(
                        f"{what}: alias *{event.anchor} refers to a node that is not complete "
                        "(a recursive structure) or not defined",
                        path=path,
                        line=line,
                    )
                add(*anchors[event.anchor])
    except yaml.YAMLError as exc:
        raise _yaml_error(exc, what, limits, error, path) from None


def _yaml_error(
    exc: Exception,
    what: str,
    limits: TreeLimits,
    error: type[WorkbenchError],
    path: str | os.PathLike[str] | None,
) -> WorkbenchError:
    problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
    context = getattr(exc, "context", None)
    if context and problem.startswith("but "):  # "expected a single document ... but found"
        problem = f"{context} {problem}"
    if "nesting depth" in problem:  # libyaml's own bound (1000 levels)
        return error(
            f"{what} is nested more than {limits.max_depth} levels deep",
            path=path,
            line=_yaml_error_line(exc),
            hint="flatten it",
        )
    return error(f"{what} is not valid YAML: {problem}", path=path, line=_yaml_error_line(exc))


def load_yaml(
    text: str,
    what: str = "YAML",
    limits: TreeLimits = YAML_LIMITS,
    error: type[WorkbenchError] = WorkbenchError,
    path: str | os.PathLike[str] | None = None,
    loader: Any = None,
) -> Any:
    """``yaml.safe_load(text)`` within ``limits``: a one-line error instead of a bomb.

    Args:
        text: The YAML text (one document).
        what: What it is, for messages ("parameter file", "map YAML" ...).
        limits: Depth, elements and bytes after alias expansion.
        error: The error class to raise.
        path: The file it came from, for messages.
        loader: A safe loader class with extra tags (default: PyYAML's safe loader).

    Raises:
        error: Invalid YAML, a ``!!python`` tag, a value YAML cannot build (a
            5000-digit integer) or a bound passed.
    """
    if len(text) > MAX_TEXT_FILE_BYTES:
        raise error(
            f"{what} is longer than {human_bytes(MAX_TEXT_FILE_BYTES)}", path=path, hint=None
        )
    check_yaml(text, what, limits, error, path)
    yaml = _yaml_module()
    try:
        return yaml.load(text, Loader=loader or _loader())  # noqa: S506 - a safe loader
    except yaml.YAMLError as exc:
        raise _yaml_error(exc, what, limits, error, path) from None
    except (ValueError, TypeError, OverflowError) as exc:
        reason = str(exc).split(";")[0]  # not Python's advice on raising its digit limit
        raise error(f"{what} holds a value YAML cannot build: {reason}", path=path) from None


def load_yaml_file(
    path: str | os.PathLike[str],
    what: str,
    error: type[WorkbenchError] = WorkbenchError,
    limits: TreeLimits = YAML_LIMITS,
) -> Any:
    """Read a YAML file within the file and YAML bounds.

    Raises:
        error: Not a readable regular UTF-8 file, too large, invalid YAML, or a bound passed.
    """
    text = read_text_bounded(path, what, error)
    return load_yaml(text, what, limits, error, Path(path))
