"""Answering a device's ``nh.getParam`` (rosserial_msgs/RequestParam), as rosserial_python does.

A parameter is sent as a list of one type: integers and booleans in ``ints``,
floats in ``floats``, strings in ``strings``; a single value is a list of one.
A missing parameter, a dictionary or a list of mixed types is not sent (the
device times out) and the host logs rosserial_python's line for it.
"""

from __future__ import annotations

from typing import Any

from workbench.errors import MessageError
from workbench.msgs import get_type


def parameter_response(node: Any, name: str, log: Any) -> Any | None:
    """The ``RequestParamResponse`` for parameter ``name`` of ``node``, or None (logged).

    Args:
        node: The host's bus node (``~name`` is its private parameter).
        name: The name the device asked for.
        log: Where the refusals go.
    """
    try:
        value = node.get_param(name)
    except (KeyError, ValueError):
        log.error("Parameter %s does not exist", name)
        return None
    except Exception as error:  # a malformed name: the bus says why
        log.error("Parameter %s does not exist (%s)", name, error)
        return None
    if value is None:
        log.error("Parameter %s does not exist", name)
        return None
    if isinstance(value, dict):
        log.error("Cannot send param %s because it is a dictionary", name)
        return None
    values = list(value) if isinstance(value, (list, tuple)) else [value]
    response = get_type("rosserial_msgs/RequestParamResponse")()
    if not values:
        return response
    kind = type(values[0])
    if any(type(v) is not kind for v in values):
        log.error("All Paramers in the list %s must be of the same type", name)
        return None
    try:
        if kind in (int, bool):
            response.ints = [int(v) for v in values]
        elif kind is float:
            response.floats = values
        elif kind is str:
            response.strings = values
    except MessageError as error:  # an integer beyond int32, say
        log.error("Cannot send param %s: %s", name, error.message)
        return None
    return response
