"""The ``python`` and ``math`` namespaces a model's xacro expressions see, re-made and bounded.

xacro exposes builtins (``python.len``, ``python.sorted`` ...) and every public name
of :mod:`math`. Here each is a :class:`~workbench.model.xacro_guards.SafeFunction`
that charges its work; ``vars``, ``getattr`` and their kin are gone, ``type`` answers
only for plain data, and the functions that could compute for ever in C (``range``,
``round``, ``factorial``, ``comb``, ``perm``, ``prod``, ``lcm``, ``sum``, ``sorted``)
are bounded first.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from workbench.model.xacro_guards import ExpressionError, SafeFunction, binary, is_int
from workbench.model.xacro_meter import (
    MAX_SIZE,
    ExpressionLimitError,
    charge,
    check_int,
)


def _bounded_range(*args: Any) -> range:
    values = range(*args)
    if len(values) > MAX_SIZE:
        raise ExpressionLimitError(f"a range of {len(values):,} numbers; at most {MAX_SIZE:,}")
    return values


def _bounded_round(number: Any, ndigits: Any = None) -> Any:
    if ndigits is not None and is_int(ndigits) and abs(ndigits) > 1000:
        raise ExpressionLimitError(f"round() to {ndigits} digits; at most 1000")
    return round(number, ndigits) if ndigits is not None else round(number)


def _sum(iterable: Any, start: Any = 0) -> Any:
    if not isinstance(start, int | float | complex):
        raise ExpressionError("sum() adds numbers only in a model file")
    total = start
    for value in iterable:
        total = binary("Add", total, value)
    return total


def _sorted(iterable: Any, **kwargs: Any) -> list[Any]:
    values = list(iterable)
    charge(len(values) * max(1, len(values).bit_length()))
    return sorted(values, **kwargs)


def _small_int_arguments(function: Callable[..., Any], limit: int = 10_000) -> Callable[..., Any]:
    def bounded(*args: Any) -> Any:
        for value in args:
            if is_int(value) and abs(value) > limit:
                raise ExpressionLimitError(
                    f"{function.__name__}() of {value}; at most {limit} in a model file"
                )
        return function(*args)

    return bounded


def _prod(iterable: Any, *, start: Any = 1) -> Any:
    """``math.prod`` one factor at a time, so a product cannot outgrow :data:`MAX_INT_BITS`."""
    total = start
    for value in iterable:
        total = check_int(total * value)
    return total


def _lcm(*values: Any) -> Any:
    """``math.lcm`` one number at a time, bounded like :func:`_prod`."""
    total = 1
    for value in values:
        total = check_int(math.lcm(total, value))
    return total


def _type(value: Any) -> Any:
    exposed = _TYPE_WRAPPERS.get(type(value))
    if exposed is None:
        raise ExpressionError(
            f"python.type() of a {type(value).__name__} is not available in a model file"
        )
    return exposed


def _types(spec: Any) -> Any:
    if isinstance(spec, tuple):
        return tuple(_types(s) for s in spec)
    if isinstance(spec, SafeFunction) and isinstance(spec.function, type):
        return spec.function
    raise ExpressionError("isinstance() takes the types of the python namespace")


def _isinstance(value: Any, spec: Any) -> bool:
    return isinstance(value, _types(spec))


def _issubclass(value: Any, spec: Any) -> bool:
    return issubclass(_types(value), _types(spec))


_CONSUMERS = {"list", "tuple", "set", "frozenset", "dict", "min", "max", "any", "all"}
_CONSUMERS |= {"enumerate", "zip", "map", "filter", "reversed"}
_PLAIN: tuple[str, ...] = ("bool", "float", "int", "complex", "str", "repr", "len", "abs")
_PLAIN += ("divmod",)
_PLAIN += ("ord", "hash", "slice", "list", "tuple", "set", "frozenset", "dict", "min", "max")
_PLAIN += ("any", "all", "enumerate", "zip", "map", "filter", "reversed")

_TYPE_WRAPPERS: dict[type, SafeFunction] = {}


def python_functions() -> dict[str, Any]:
    """xacro's ``python`` namespace, re-made: the builtins it exposes, each one guarded.

    ``vars``, ``type`` of anything but plain data, and attribute walks are gone.
    """
    import builtins

    functions: dict[str, Any] = {"True": True, "False": False}
    for name in _PLAIN:
        functions[name] = SafeFunction(
            getattr(builtins, name), f"python.{name}", consumes=name in _CONSUMERS
        )
    functions["range"] = SafeFunction(_bounded_range, "python.range")
    functions["round"] = SafeFunction(_bounded_round, "python.round")
    functions["sum"] = SafeFunction(_sum, "python.sum", consumes=True)
    functions["sorted"] = SafeFunction(_sorted, "python.sorted", consumes=True)
    functions["type"] = SafeFunction(_type, "python.type")
    functions["isinstance"] = SafeFunction(_isinstance, "python.isinstance")
    functions["issubclass"] = SafeFunction(_issubclass, "python.issubclass")
    for name in ("bool", "float", "int", "complex", "str", "list", "tuple", "set"):
        _TYPE_WRAPPERS[getattr(builtins, name)] = functions[name]
    for name in ("frozenset", "dict", "slice"):
        _TYPE_WRAPPERS[getattr(builtins, name)] = functions[name]
    return functions


def math_functions() -> dict[str, Any]:
    """xacro's ``math`` namespace: every public name of :mod:`math`, the integer ones bounded."""
    special = {
        "factorial": _small_int_arguments(math.factorial, 2000),
        "comb": _small_int_arguments(math.comb),
        "perm": _small_int_arguments(math.perm),
        "prod": _prod,
        "lcm": _lcm,
    }
    functions: dict[str, Any] = {}
    for name, value in vars(math).items():
        if name.startswith("_"):
            continue
        if callable(value):
            consumes = name in ("fsum", "prod", "dist", "hypot")
            functions[name] = SafeFunction(special.get(name, value), f"math.{name}", consumes)
        else:
            functions[name] = value
    return functions
