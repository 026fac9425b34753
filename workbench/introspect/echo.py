"""``rostopic echo`` text: YAML documents separated by ``---``, field paths, ``--noarr``.

The text is what ROS 1's ``rostopic echo`` (ros_comm 1.15, genpy 0.6) prints, character
for character:

* strings are double-quoted YAML with non-ASCII escaped (``"h\\xE9llo"``), the empty
  string is ``''``; a ``string[]`` is a YAML block list (``- a``, quoted only where YAML
  needs it);
* numbers are Python's ``str`` (``float32`` values as the 32-bit value read back, so
  ``0.1`` shows as ``0.10000000149011612``), ``nan``/``inf``, bools ``True``/``False``;
* numeric arrays (``uint8[]`` too) are ``[1, 2, 3]``, an empty array ``[]``; a ``char[]``
  is Python's text of bytes (``b'hi'``), as rostopic on Python 3 shows it;
* ``nsecs`` is padded to nine characters (``nsecs:  47642753``), a time at the top
  (``/topic/header/stamp``) and a list of messages start with an empty line;
* a nested message's key and each ``-`` item keep their trailing space (``header: ``);
* ``--noarr`` and ``--nostr`` replace arrays and strings with
  ``"<array type: T, length: N>"`` / ``"<string length: N>"`` in the message and its
  nested messages, not inside arrays of messages;
* ``-w WIDTH`` pads numbers to a fixed width; ``-p`` prints CSV rows (see :func:`format_plot`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np
import yaml

from workbench.errors import BusError
from workbench.msgs._classes import Message
from workbench.msgs._time import _TimeBase

_INDEX = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[([^\]]*)\])?$")


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
    if "/".join(parts) in known:
        return "/".join(parts), []
    for cut in range(len(parts) - 1, 0, -1):
        topic = "/".join(parts[:cut]) or "/"
        if topic in known:
            return topic, [part for part in parts[cut:] if part]
    raise BusError(
        f"topic {path} does not appear to be published yet",
        hint="'workbench topic list' shows the topics",
    )


def _index(text: str, part: str) -> int | slice:
    """``2``, ``-1``, ``1:3``, ``::2`` -> an index or a slice (as rostopic's field paths)."""
    try:
        if ":" not in text:
            return int(text)
        pieces = text.split(":")
        if len(pieces) > 3:
            raise ValueError(text)
        numbers = [int(p) if p.strip() else None for p in pieces]
        return slice(*numbers)
    except ValueError:
        raise BusError(
            f"bad index in field '{part}'", hint="use field[i], field[a:b] or field[a:b:step]"
        ) from None


def get_field(msg: Any, fields: list[str], *, topic: str = "") -> Any:
    """Follow a field path (``["pose", "position", "x"]``, ``["ranges[3]"]``) into a message.

    An index may be a slice (``ranges[0:3]``, ``transforms[1:]``); after a slice of a list
    of messages, the rest of the path applies to each of them (a list comes back), as
    rostopic's ``/tf/transforms[0:2]/child_frame_id``.

    Raises:
        BusError: a field does not exist (names it and the fields there are).
    """
    value = msg
    for at, part in enumerate(fields):
        match = _INDEX.match(part)
        name, index = (match.group(1), match.group(2)) if match else (part, None)
        slots = ("secs", "nsecs") if isinstance(value, _TimeBase) else ()
        slots += getattr(type(value), "__slots__", ())
        if name not in slots:
            where = f" of {topic}" if topic else ""
            kind = getattr(value, "_type", type(value).__name__)
            raise BusError(
                f"no field '{name}' in {kind}{where}",
                hint=f"its fields are: {', '.join(slots) or 'none'}",
            )
        value = getattr(value, name)
        if index is None:
            continue
        position = _index(index, part)
        try:
            value = value[position]
        except (IndexError, TypeError):
            raise BusError(f"field '{part}' is out of range") from None
        if isinstance(position, slice) and isinstance(value, list) and at + 1 < len(fields):
            return [get_field(item, fields[at + 1 :], topic=topic) for item in value]
    return value


def field_type(cls: Any, fields: list[str]) -> str | None:
    """The declared ROS type of the last field of a path (``float32[]`` for ``ranges[2]``).

    This is the type rostopic hands its formatting when echoing a field of a live topic.
    None when the path does not name a declared field.
    """
    kind: str | None = None
    for part in fields:
        name = part.split("[", 1)[0]
        specs = getattr(cls, "_specs", None)
        if specs is None:
            return None
        spec = next((s for s in specs if s.name == name), None)
        if spec is None:
            return None
        kind = spec.ros_type
        if spec.elem_is_msg:
            from workbench.msgs._store import store

            cls = store().classes.get(spec.elem)
        else:
            cls = None
    return kind


# --- YAML text --------------------------------------------------------------------------


def _string(text: str) -> str:
    if not text:
        return "''"
    # PyYAML's double-quoted style, exactly as genpy asks for it.
    return str(yaml.dump(text, default_style='"')).rstrip("\n")


def _number(value: int | float, width: int | None) -> str:
    if width is None:
        return str(value)
    if isinstance(value, float):
        text = f"{value:.{width}f}"
        return text[: max(text.find("."), width)]
    return f"{value:{width}d}"


def _time(value: _TimeBase, indent: str, width: int | None) -> str:
    if width is None:
        return f"\n{indent}secs: {value.secs}\n{indent}nsecs: {value.nsecs:9d}"
    return f"\n{indent}secs: {value.secs:{width}d}\n{indent}nsecs: {value.nsecs:{width}d}"


def _plain(value: Any) -> Any:
    """numpy scalars to Python's."""
    return value.item() if isinstance(value, np.generic) else value


def _float32(value: float) -> float:
    """The value a float32 field carries on the wire."""
    with np.errstate(over="ignore"):
        return float(np.float32(value))


def _sequence(items: list[Any], indent: str, width: int | None) -> str:
    if not items:
        return "[]"
    first = items[0]
    if width is not None and type(first) in (int, float):
        return "[" + ", ".join(_number(v, width) for v in items) + "]"
    if isinstance(first, str):
        block = str(yaml.dump(items)).rstrip("\n")
        if block.startswith("["):
            return block
        return "\n" + "\n".join(indent + line for line in block.splitlines())
    if type(first) in (int, float, bool):
        return str(items)
    return "\n" + "\n".join(
        f"{indent}- {_text(item, indent + '  ', width, None)}" for item in items
    )


def _text(value: Any, indent: str, width: int | None, options: tuple[bool, bool] | None) -> str:
    """One value; ``options`` (noarr, nostr) when the value is a message to transform."""
    value = _plain(value)
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, (int, float)):
        return _number(value, width)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, _TimeBase):
        return _time(value, indent, width)
    if isinstance(value, Message):
        return _message(value, indent, width, options)
    if isinstance(value, np.ndarray):
        return _sequence(value.tolist(), indent, width)
    if isinstance(value, (list, tuple)):
        return _sequence([_plain(item) for item in value], indent, width)
    if isinstance(value, (bytes, bytearray)):
        return _sequence(list(value), indent, width)
    return str(value)


def _hidden(value: Any, ros_type: str, noarr: bool, nostr: bool) -> str | None:
    """rostopic's replacement text for an array (``--noarr``) or a string (``--nostr``)."""
    if noarr and "[" in ros_type:
        return f"<array type: {ros_type.rstrip('[]')}, length: {len(value)}>"
    if nostr and ros_type == "string":
        return f"<string length: {len(value)}>"
    if nostr and ros_type == "string[]":
        return f"<array type: string, length: {len(value)}>"
    return None


def _equals_itself(msg: Any) -> bool:
    """False for a message with a NaN float field, there or in a nested message.

    (Arrays compare their items by identity first, so a NaN inside an array does not count.)
    """
    if isinstance(msg, _TimeBase) or not isinstance(msg, Message):
        return True
    for spec in type(msg)._specs:
        if spec.kind == "base" and spec.elem in ("float32", "float64"):
            value = getattr(msg, spec.name)
            if value != value:
                return False
        elif spec.kind == "msg" and not _equals_itself(getattr(msg, spec.name)):
            return False
    return True


def _chars(value: Any, ros_type: str | None) -> str | None:
    """A ``char[]`` array arrives as bytes, which rostopic prints as Python does (``b'hi'``)."""
    if ros_type and ros_type.startswith("char[") and isinstance(value, np.ndarray):
        return str(value.astype(np.uint8).tobytes())
    return None


def _message(
    msg: Message, indent: str, width: int | None, options: tuple[bool, bool] | None
) -> str:
    inner = indent + "  "
    lines = []
    for spec in type(msg)._specs:
        value = getattr(msg, spec.name)
        if spec.kind == "base" and spec.elem == "float32":
            value = _float32(value)
        hidden = _hidden(value, spec.ros_type, *options) if options else None
        if hidden is not None:
            text = _string(hidden)
        else:
            # The replacement reaches nested messages, not messages inside arrays, and not
            # a nested message with a NaN field: rostopic recurses only into a message that
            # compares equal to itself.
            nested = options if spec.kind == "msg" and _equals_itself(value) else None
            text = _chars(value, spec.ros_type) or _text(value, inner, width, nested)
        lines.append(f"{indent}{spec.name}: {text}")
    body = "\n".join(lines)
    return "\n" + body if indent else body


def format_value(
    value: Any,
    *,
    noarr: bool = False,
    nostr: bool = False,
    width: int | None = None,
    ros_type: str | None = None,
    typed: bool = True,
) -> str:
    """One echoed value as ``rostopic echo`` prints it (without the ``---``).

    Args:
        value: A message, or a field of one.
        noarr: Print arrays as ``"<array type: T, length: N>"`` (``--noarr``).
        nostr: Print strings as ``"<string length: N>"`` (``--nostr``).
        width: Pad numbers to this width (``-w``).
        ros_type: The declared type of the field ``value`` is (see :func:`field_type`).
        typed: Whether rostopic would know ``ros_type``: it applies ``--noarr`` and
            ``--nostr`` to an echoed field of a live topic, not to one of a bag.
    """
    options = (noarr, nostr)
    if isinstance(value, Message) and not isinstance(value, _TimeBase):
        return _message(value, "", width, options)
    # rostopic measures a string or an array with the field's declared type; an element of
    # an array (a number, say) has no length, where rostopic fails, and is printed instead.
    if typed and ros_type is not None and isinstance(value, (str, list, tuple, np.ndarray)):
        hidden = _hidden(value, ros_type, noarr, nostr)
        if hidden is not None:
            return _string(hidden)
    return _chars(value, ros_type) or _text(value, "", width, None)


def format_echo(
    value: Any,
    *,
    noarr: bool = False,
    nostr: bool = False,
    width: int | None = None,
    ros_type: str | None = None,
    typed: bool = True,
) -> str:
    """A YAML document and its ``---`` separator line (see :func:`format_value`)."""
    text = format_value(
        value, noarr=noarr, nostr=nostr, width=width, ros_type=ros_type, typed=typed
    )
    return f"{text}\n---"


# --- rostopic echo -p: CSV ---------------------------------------------------------------


def _fields_shown(msg: Message, noarr: bool, nostr: bool) -> Iterable[Any]:
    for spec in type(msg)._specs:
        if noarr and "[" in spec.ros_type:
            continue
        if nostr and "string" in spec.ros_type:
            continue
        yield spec


def _csv_walk(
    value: Any, label: str, noarr: bool, nostr: bool, leaf: Callable[[Any, str], str]
) -> str | None:
    """Visit the scalars of ``value`` in rostopic's CSV order; None when there are none."""
    value = _plain(value)
    if isinstance(value, (bool, int, float, _TimeBase, str)):
        return leaf(value, label)
    if isinstance(value, np.ndarray) and value.dtype == np.uint8:
        return None  # uint8[] arrives as bytes in rostopic, which its CSV leaves out
    if isinstance(value, Message):
        parts = []
        for spec in _fields_shown(value, noarr, nostr):
            item = getattr(value, spec.name)
            if spec.kind == "base" and spec.elem == "float32":
                item = _float32(item)
            part = _csv_walk(item, f"{label}.{spec.name}", noarr, nostr, leaf)
            if part is not None:
                parts.append(part)
        return ",".join(parts) if parts else None
    if isinstance(value, (bytes, bytearray)):
        return None
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)) and value:
        if not isinstance(_plain(value[0]), (bool, int, float, _TimeBase, str, Message)):
            return None  # an array of arrays (a sliced field path) has no CSV columns
        parts = []
        for i, item in enumerate(value):
            part = _csv_walk(item, f"{label}{i}", noarr, nostr, leaf)
            if part is not None:
                parts.append(part)
        return ",".join(parts) if parts else None
    return None


def _csv_label(value: Any, label: str) -> str:
    return label


def _csv_value(value: Any, label: str) -> str:
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, _TimeBase):
        return str(value.to_nsec())
    return str(value)


def format_plot_header(value: Any, *, noarr: bool = False, nostr: bool = False) -> str:
    """The ``%time,field.a,...`` line ``rostopic echo -p`` prints before the first row."""
    labels = _csv_walk(value, "field", noarr, nostr, _csv_label)
    return "%time," + (labels or "")


def format_plot(
    value: Any, stamp_ns: int | None, *, noarr: bool = False, nostr: bool = False
) -> str:
    """One ``rostopic echo -p`` row: the time in nanoseconds, then every scalar.

    Args:
        value: The message or field.
        stamp_ns: The bag's record time of the message; None for a live message (its
            ``header.stamp`` then, or the current time, as rostopic).
        noarr: Leave arrays out.
        nostr: Leave strings out.
    """
    if stamp_ns is None:
        if isinstance(value, Message) and type(value)._has_header:
            stamp_ns = value.header.stamp.to_nsec()  # type: ignore[attr-defined]
        else:
            import time

            stamp_ns = time.time_ns()
    return f"{stamp_ns},{_csv_walk(value, '', noarr, nostr, _csv_value) or ''}"
