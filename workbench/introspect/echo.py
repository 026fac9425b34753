"""``rostopic echo`` text: YAML documents separated by ``---``, field paths, ``--noarr``."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterable
from typing import Any

import numpy as np

from workbench.errors import BusError

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


def _scalar(value: Any) -> str:
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    return str(value)


def _is_message(value: Any) -> bool:
    return hasattr(type(value), "_specs") and hasattr(type(value), "__slots__")


def _lines(msg: Any, indent: int, noarr: bool) -> list[str]:
    pad = "  " * indent
    out: list[str] = []
    specs = {s.name: s for s in getattr(type(msg), "_specs", ())}
    for name in type(msg).__slots__:
        value = getattr(msg, name)
        spec = specs.get(name)
        is_array = spec is not None and spec.kind in ("array", "seq")
        if is_array and noarr:
            elem = spec.ros_type.split("[")[0]
            out.append(f'{pad}{name}: "<array type: {elem}, length: {len(value)}>"')
        elif (
            hasattr(value, "secs")
            and hasattr(value, "nsecs")
            and not _is_message_with_fields(value)
        ):
            out += [f"{pad}{name}: ", f"{pad}  secs: {value.secs}", f"{pad}  nsecs: {value.nsecs}"]
        elif _is_message(value):
            out.append(f"{pad}{name}: ")
            out += _lines(value, indent + 1, noarr)
        elif isinstance(value, (list, np.ndarray)):
            items = list(value)
            if items and _is_message(items[0]):
                out.append(f"{pad}{name}: ")
                for item in items:
                    out.append(f"{pad}  - ")
                    out += _lines(item, indent + 2, noarr)
            else:
                out.append(f"{pad}{name}: [{', '.join(_scalar(v) for v in items)}]")
        else:
            out.append(f"{pad}{name}: {_scalar(value)}")
    return out


def _is_message_with_fields(value: Any) -> bool:
    return _is_message(value) and set(type(value).__slots__) - {"secs", "nsecs", "sec", "nanosec"}


def format_value(value: Any, *, noarr: bool = False) -> str:
    """One echoed value as ``rostopic echo`` prints it (without the ``---``)."""
    if hasattr(value, "secs") and hasattr(value, "nsecs") and not _is_message_with_fields(value):
        return f"secs: {value.secs}\nnsecs: {value.nsecs}"
    if _is_message(value):
        return "\n".join(_lines(value, 0, noarr))
    if isinstance(value, (list, np.ndarray)):
        items = list(value)
        if items and _is_message(items[0]):
            return "\n".join(["-"] + [line for item in items for line in _lines(item, 1, noarr)])
        if noarr:
            return f'"<array type: {type(items[0]).__name__ if items else "unknown"}, length: {len(items)}>"'
        return f"[{', '.join(_scalar(v) for v in items)}]"
    return _scalar(value)


def format_echo(value: Any, *, noarr: bool = False) -> str:
    """A YAML document and its ``---`` separator line."""
    return f"{format_value(value, noarr=noarr)}\n---"
