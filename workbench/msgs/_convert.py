"""Messages to and from plain Python data, and the YAML text ``rostopic echo`` prints."""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from workbench.errors import MessageError
from workbench.msgs._classes import Message
from workbench.msgs._time import _TimeBase


def to_dict(msg: Message) -> dict[str, Any]:
    """A message as nested dicts/lists of plain Python values.

    Time and duration fields become ``{"secs": s, "nsecs": ns}``; numeric
    arrays become lists.
    """
    if not isinstance(msg, Message):
        raise MessageError(f"to_dict needs a message, not {type(msg).__name__}")
    return _plain(msg)


def _plain(value: Any) -> Any:
    if isinstance(value, _TimeBase):
        return {"secs": value.secs, "nsecs": value.nsecs}
    if isinstance(value, Message):
        return {name: _plain(getattr(value, name)) for name in value.__slots__}
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, list):
        return [_plain(item) for item in value]
    return value


def from_dict(cls: type[Message], data: Any, path: str = "") -> Message:
    """Build a message of class ``cls`` from a dict (by field) or list (by position).

    Nested messages may again be dicts or lists, as ``rostopic pub`` accepts
    them. Missing fields keep their zero defaults.

    Raises:
        MessageError: A field is unknown or a value does not fit; the message names the
            field's path (``linear.x``).
    """
    if isinstance(data, Message) and data.__msgtype__ == cls.__msgtype__:
        return data
    where = f" (at '{path}')" if path else ""
    if data is None:
        return cls()
    if isinstance(data, (list, tuple)):
        if len(data) > len(cls.__slots__):
            raise MessageError(
                f"{cls._type} has {len(cls.__slots__)} fields "
                f"({', '.join(cls.__slots__) or 'none'}) but {len(data)} values were given{where}"
            )
        data = dict(zip(cls.__slots__, data, strict=False))
    elif not isinstance(data, dict):
        if len(cls.__slots__) == 1:  # a bare value for a one-field message: String "hi"
            data = {cls.__slots__[0]: data}
        else:
            raise MessageError(
                f"{cls._type} needs a dict of fields or a list of values, "
                f"not {type(data).__name__}{where}"
            )
    if issubclass(cls, _TimeBase):
        try:
            return cls(**data)
        except TypeError as error:
            raise MessageError(f"{cls._type}: {error}{where}") from None
    from workbench.msgs._store import store

    classes = store().classes
    values: dict[str, Any] = {}
    for name, value in data.items():
        spec = next((s for s in cls._specs if s.name == name), None)
        if spec is None:
            # Let the class produce its "no field ... did you mean" error.
            cls(**{name: value})
        assert spec is not None
        sub = f"{path}.{name}" if path else name
        if spec.elem_is_msg and spec.kind == "msg":
            value = from_dict(classes[spec.elem], value, sub)
        elif spec.elem_is_msg and isinstance(value, (list, tuple)):
            value = [
                from_dict(classes[spec.elem], item, f"{sub}[{i}]") for i, item in enumerate(value)
            ]
        values[name] = value
    try:
        return cls(**values)
    except MessageError as error:
        if path:
            raise MessageError(f"{error.message} (at '{path}')", hint=error.hint) from None
        raise


def to_yaml(msg: Message, indent: int = 0, *, noarr: bool = False) -> str:
    """The message as ``rostopic echo`` prints it (without the trailing ``---``).

    ``noarr`` prints arrays as ``"<array type: T, length: N>"``, as ``rostopic echo --noarr``.
    """
    return "\n".join(yaml_lines(msg, indent, noarr=noarr))


def format_scalar(value: Any) -> str:
    """One field value (not a message or array) as ``rostopic echo`` prints it."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    return str(value)


def yaml_lines(msg: Message, indent: int = 0, *, noarr: bool = False) -> list[str]:
    """:func:`to_yaml`'s lines."""
    pad = "  " * indent
    lines: list[str] = []
    arrays = {s.name: s for s in type(msg)._specs if s.kind in ("array", "seq")} if noarr else {}
    for name in msg.__slots__:
        value = getattr(msg, name)
        if name in arrays:
            element = arrays[name].ros_type.split("[")[0]
            lines.append(f'{pad}{name}: "<array type: {element}, length: {len(value)}>"')
        elif isinstance(value, _TimeBase):
            lines += [
                f"{pad}{name}: ",
                f"{pad}  secs: {value.secs}",
                f"{pad}  nsecs: {value.nsecs}",
            ]
        elif isinstance(value, Message):
            lines.append(f"{pad}{name}: ")
            lines += yaml_lines(value, indent + 1, noarr=noarr)
        elif isinstance(value, np.ndarray):
            lines.append(f"{pad}{name}: [{', '.join(format_scalar(v) for v in value.tolist())}]")
        elif isinstance(value, list):
            if value and isinstance(value[0], Message):
                lines.append(f"{pad}{name}: ")
                for item in value:
                    lines.append(f"{pad}  - ")
                    lines += yaml_lines(item, indent + 2, noarr=noarr)
            else:
                lines.append(f"{pad}{name}: [{', '.join(format_scalar(v) for v in value)}]")
        else:
            lines.append(f"{pad}{name}: {format_scalar(value)}")
    return lines
