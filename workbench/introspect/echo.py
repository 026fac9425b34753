"""``rostopic echo`` text: YAML documents separated by ``---``, field paths, ``--noarr``."""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

import numpy as np

from workbench.errors import BusError
from workbench.msgs._classes import Message
from workbench.msgs._convert import format_scalar, to_yaml, yaml_lines
from workbench.msgs._time import _TimeBase

_INDEX = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[(-?\d+)\])?$")


def split_topic_field(path: str, topics: Iterable[str]) -> tuple[str, list[str]]:
    """Split ``/turtle1/pose/x`` into the longest known topic and its field path.

    Args:
        path: A topic name, optionally followed by ``/field/sub[2]``.
        topics: The topics that exist.

    Returns:
        ``(topic, ["x"])``; the field list is empty for a bare topic.

    Raises:
        BusError: no known topic is a prefix of ``path``.
    """
    known = set(topics)
    if path in known:
        return path, []
    parts = path.rstrip("/").split("/")
    for cut in range(len(parts) - 1, 0, -1):
        topic = "/".join(parts[:cut]) or "/"
        if topic in known:
            return topic, parts[cut:]
    raise BusError(
        f"topic {path} does not appear to be published yet",
        hint="'workbench topic list' shows the topics",
    )


def get_field(msg: Any, fields: list[str], *, topic: str = "") -> Any:
    """Follow a field path (``["pose", "position", "x"]``, ``["ranges[3]"]``) into a message.

    Raises:
        BusError: a field does not exist (names it and the fields there are).
    """
    value = msg
    for part in fields:
        match = _INDEX.match(part)
        name, index = (match.group(1), match.group(2)) if match else (part, None)
        slots = getattr(type(value), "__slots__", ())
        if name not in slots:
            where = f" of {topic}" if topic else ""
            kind = getattr(value, "_type", type(value).__name__)
            raise BusError(
                f"no field '{name}' in {kind}{where}",
                hint=f"its fields are: {', '.join(slots) or 'none'}",
            )
        value = getattr(value, name)
        if index is not None:
            try:
                value = value[int(index)]
            except (IndexError, TypeError):
                raise BusError(f"field '{part}' is out of range") from None
    return value


def format_value(value: Any, *, noarr: bool = False) -> str:
    """One echoed value as ``rostopic echo`` prints it (without the ``---``)."""
    if isinstance(value, _TimeBase):
        return f"secs: {value.secs}\nnsecs: {value.nsecs}"
    if isinstance(value, Message):
        return to_yaml(value, noarr=noarr)
    if isinstance(value, (list, np.ndarray)):
        items = list(value)
        if items and isinstance(items[0], Message):
            return "\n".join(
                ["-"] + [line for item in items for line in yaml_lines(item, 1, noarr=noarr)]
            )
        if noarr:
            return f'"<array type: {type(items[0]).__name__ if items else "unknown"}, length: {len(items)}>"'
        return f"[{', '.join(format_scalar(v) for v in items)}]"
    return format_scalar(value)


def format_echo(value: Any, *, noarr: bool = False) -> str:
    """A YAML document and its ``---`` separator line."""
    return f"{format_value(value, noarr=noarr)}\n---"
