"""``rostopic pub`` / ``rosservice call`` arguments: YAML text to messages.

Each command-line argument is one YAML value. Several arguments fill the
message's fields in order (``'[2.0, 0.0, 0.0]' '[0.0, 0.0, 1.8]'`` is a
Twist's linear and angular); a single YAML mapping fills fields by name
(``'{linear: {x: 2.0}}'``); a single value fills a one-field message.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from workbench.errors import MessageError


def parse_yaml_args(args: Sequence[str]) -> list[Any]:
    """Each argument parsed as YAML (``on``/``off`` are not booleans, as in ROS 1 tools).

    Raises:
        MessageError: an argument is not valid YAML (names it).
    """
    from workbench.limits import load_yaml

    values = []
    for i, text in enumerate(args, start=1):
        shown = repr(text if len(text) <= 40 else text[:37] + "...")
        try:
            value = load_yaml(text, f"argument {i} ({shown})", error=MessageError)
            values.append(value if text.strip() else "")
        except MessageError as error:
            hint = "quote lists and dicts: '[2.0, 0.0, 0.0]'"
            raise MessageError(error.message, hint=error.hint or hint) from None
    return values


def message_from_args(typename: str | type, args: Sequence[str], *, what: str = "") -> Any:
    """Build a message of ``typename`` from command-line YAML arguments.

    Args:
        typename: ``geometry_msgs/Twist`` or a message class.
        args: The arguments after the type (``--`` already removed).
        what: Where the message goes (``topic /turtle1/cmd_vel``), for errors.

    Raises:
        MessageError: the values do not fit the type; says which field and what it needs.
    """
    from workbench.msgs import from_dict, get_type

    cls: Any = get_type(typename) if isinstance(typename, str) else typename
    values = parse_yaml_args(args)
    if not values:
        data: Any = {}
    elif len(values) == 1 and isinstance(values[0], dict):
        data = values[0]
    elif len(values) == 1 and len(cls.__slots__) == 1:
        data = [values[0]]
    else:
        data = values
    data = _fix_service_words(cls, data)
    try:
        return from_dict(cls, data)
    except MessageError as error:
        prefix = f"{what}: " if what else ""
        fields = " ".join(f"{n}:{t}" for n, t in zip(cls.__slots__, cls._slot_types, strict=True))
        raise MessageError(
            f"{prefix}{error.message}",
            hint=error.hint or f"{cls._type} takes: {fields or 'no fields'}",
        ) from None


def _fix_service_words(cls: Any, data: Any) -> Any:
    """YAML 1.1 reads ``on``/``off``/``yes``/``no`` as booleans; a uint8 field wants 1/0.

    ``rosservice call /turtle1/set_pen 255 0 255 3 on`` relies on this: ``off`` is uint8.
    """
    specs = {s.name: s for s in getattr(cls, "_specs", ())}
    names = list(cls.__slots__)

    def fix(name: str, value: Any) -> Any:
        spec = specs.get(name)
        if (
            spec is not None
            and isinstance(value, bool)
            and spec.kind == "base"
            and spec.elem not in ("bool", "string")
        ):
            return int(value)
        return value

    if isinstance(data, dict):
        return {k: fix(k, v) for k, v in data.items()}
    if isinstance(data, list):
        return [fix(names[i], v) if i < len(names) else v for i, v in enumerate(data)]
    return data
