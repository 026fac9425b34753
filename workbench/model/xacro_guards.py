"""The guards a model's rewritten expressions run through (see :mod:`workbench.model.xacro_eval`).

* **calls** reach only the functions workbench exposes (:class:`SafeFunction`) and
  lambdas written in the model; everything a model can reach is data or one of those;
* **attributes** are property namespaces, YAML keys, and a list of harmless methods of
  strings, numbers and containers (no ``format``: it walks attributes by name);
* **operators, subscripts, loops and comparisons** are charged to the meter of
  :mod:`workbench.model.xacro_meter`, and bounded before they run.
"""

from __future__ import annotations

import math
import operator
import re
import types
from collections.abc import Callable, Iterator
from typing import Any

from workbench.errors import ModelError
from workbench.model.xacro_meter import (
    DATA_TYPES,
    MAX_FORMAT_WIDTH,
    MAX_SIZE,
    ExpressionLimitError,
    charge,
    charge_weight,
    check_int,
    check_size,
    int_bits_limit,
    weight,
)

#: The file name compiled expressions carry (tells a model's own lambdas from anything else).
SANDBOX_FILENAME = "<xacro expression>"


class ExpressionError(ModelError):
    """A xacro expression uses something a model file may not (a refusal, not a limit)."""


# --- operators --------------------------------------------------------------------------

_BINARY: dict[str, Callable[[Any, Any], Any]] = {
    "Add": operator.add,
    "Sub": operator.sub,
    "Mult": operator.mul,
    "MatMult": operator.matmul,
    "Div": operator.truediv,
    "FloorDiv": operator.floordiv,
    "Mod": operator.mod,
    "Pow": operator.pow,
    "LShift": operator.lshift,
    "RShift": operator.rshift,
    "BitOr": operator.or_,
    "BitXor": operator.xor,
    "BitAnd": operator.and_,
}

_SEQUENCES = (str, bytes, list, tuple)
_PERCENT_FIELD = re.compile(r"%(?:\([^)]*\))?[-+ #0]*(\*|\d+)?(?:\.(\*|\d+))?")


def is_int(value: Any) -> bool:
    """An integer (``bool`` included, as Python counts it)."""
    return isinstance(value, int)


def _check_percent_format(text: str | bytes) -> None:
    pattern = text.decode("latin-1") if isinstance(text, bytes) else text
    for match in _PERCENT_FIELD.finditer(pattern):
        for number in match.groups():
            if number == "*" or (number is not None and int(number) > MAX_FORMAT_WIDTH):
                raise ExpressionLimitError(
                    f"the format '{match.group()}' asks for a field wider than "
                    f"{MAX_FORMAT_WIDTH} characters"
                )


def binary(name: str, left: Any, right: Any) -> Any:
    """``left <op> right`` with the work charged and the result bounded."""
    charge(1)
    if name == "Pow" and is_int(left) and is_int(right) and right > 0 and abs(left) > 1:
        int_bits_limit(right * math.log2(abs(left)), "the power")
    elif name == "LShift" and is_int(left) and is_int(right) and left != 0 and right > 0:
        int_bits_limit(left.bit_length() + right, "the shift")
    elif name == "Mult":
        for sequence, count in ((left, right), (right, left)):
            if isinstance(sequence, _SEQUENCES) and is_int(count) and count > 0:
                size = weight(sequence) * count
                if size > MAX_SIZE:
                    raise ExpressionLimitError(
                        f"repeating a value {count:,} times would make more than "
                        f"{MAX_SIZE:,} characters or items"
                    )
                charge(size)
        if is_int(left) and is_int(right):
            int_bits_limit(left.bit_length() + right.bit_length(), "the product")
    elif name == "Add" and isinstance(left, _SEQUENCES) and isinstance(right, _SEQUENCES):
        charge(len(left) + len(right))
        if weight(left) + weight(right) > MAX_SIZE:
            raise ExpressionLimitError(
                f"joining the values would make more than {MAX_SIZE:,} characters or items"
            )
    elif name == "Mod" and isinstance(left, str | bytes):
        _check_percent_format(left)
        charge_weight(left)
        charge_weight(right)
    try:
        return check_int(_BINARY[name](left, right))
    except OverflowError:
        raise ExpressionLimitError("the result is too large for a floating-point number") from None


# --- attributes and methods -------------------------------------------------------------

_STR_METHODS = frozenset(
    ("capitalize", "casefold", "count", "endswith", "find", "index", "isalnum", "isalpha")
    + ("isdecimal", "isdigit", "islower", "isnumeric", "isspace", "istitle", "isupper", "join")
    + ("lower", "lstrip", "partition", "removeprefix", "removesuffix", "replace", "rfind")
    + ("rindex", "rpartition", "rsplit", "rstrip", "split", "splitlines", "startswith", "strip")
    + ("swapcase", "title", "upper", "center", "ljust", "rjust", "zfill", "expandtabs")
)
_LIST_METHODS = frozenset({"count", "index"})
_DICT_METHODS = frozenset({"keys", "values", "items", "get", "copy"})
_SET_METHODS = frozenset(
    ("union", "intersection", "difference", "symmetric_difference", "issubset", "issuperset")
    + ("isdisjoint", "copy")
)
_NUMBER_ATTRIBUTES = frozenset(
    ("real", "imag", "conjugate", "numerator", "denominator", "bit_length", "is_integer")
    + ("as_integer_ratio",)
)
_PADDING = frozenset({"center", "ljust", "rjust", "zfill"})


class SafeFunction:
    """A function a model's expressions may call; it charges its own work.

    Args:
        function: What it calls.
        name: The name shown in messages (``python.len``).
        consumes: Its iterable arguments are read item by item (charged per item).
    """

    def __init__(self, function: Callable[..., Any], name: str, consumes: bool = False) -> None:
        self.function = function
        self.name = name
        self.consumes = consumes

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        charge(1)
        for value in (*args, *kwargs.values()):
            charge_weight(value)
        if self.consumes:
            args = tuple(metered_items(a) if _is_lazy(a) else a for a in args)
        result = self.function(*args, **kwargs)
        if isinstance(result, str | bytes | list | tuple | dict | set | frozenset):
            check_size(result)
        return check_int(result)

    def __repr__(self) -> str:
        return f"<function {self.name}>"


def _is_lazy(value: Any) -> bool:
    return not isinstance(value, DATA_TYPES) and hasattr(value, "__iter__")


def metered_items(iterable: Any) -> Iterator[Any]:
    """The items of ``iterable``, each charged by its weight."""
    for item in iterable:
        charge_weight(item)
        yield item


def iterate(iterable: Any) -> Iterator[Any]:
    """The items of a comprehension's ``for``, one work unit each."""
    charge(1)
    for item in iterable:
        charge(1)
        yield item


def _method(value: Any, name: str) -> SafeFunction:
    bound = getattr(value, name)

    def call(*args: Any, **kwargs: Any) -> Any:
        charge_weight(value)
        if name in _PADDING or name == "expandtabs":
            width = args[0] if args else kwargs.get("width", kwargs.get("tabsize", 8))
            size = width * (len(value) if name == "expandtabs" else 1)
            if is_int(width) and size > MAX_SIZE:
                raise ExpressionLimitError(f"{name}() would make more than {MAX_SIZE:,} characters")
        elif name == "replace" and len(args) >= 2 and isinstance(args[0], str | bytes):
            old, new = args[0], args[1]
            count = len(value) + 1 if not old else value.count(old)
            if len(value) + count * max(0, len(new) - len(old)) > MAX_SIZE:
                raise ExpressionLimitError(
                    f"replace() would make more than {MAX_SIZE:,} characters"
                )
        elif name == "join" and args:
            parts = list(metered_items(args[0]))
            if sum(weight(part) for part in parts) > MAX_SIZE:
                raise ExpressionLimitError(f"join() would make more than {MAX_SIZE:,} characters")
            args = (parts, *args[1:])
        return bound(*args, **kwargs)

    return SafeFunction(call, f"{type(value).__name__}.{name}")


def attribute(value: Any, name: str) -> Any:
    """``value.name`` for namespaces, YAML mappings and a few harmless methods only."""
    import xacro

    charge(1)
    if name.startswith("_"):
        raise ExpressionError(f"attribute '{name}' is not available in a model file")
    if isinstance(value, xacro.NameSpace):
        try:
            return xacro.Table.__getitem__(value, name)
        except KeyError:
            removed = vars(value).get("removed_names", {}).get(name)
            if removed is not None:
                raise ExpressionError(removed) from None
            raise NameError(f"name '{name}' is not defined") from None
    if isinstance(value, xacro.YamlDictWrapper) and name not in _DICT_METHODS:
        return xacro.YamlDictWrapper.__getattr__(value, name)
    allowed: frozenset[str] = frozenset()
    if isinstance(value, str):
        allowed = _STR_METHODS
    elif isinstance(value, list | tuple):
        allowed = _LIST_METHODS
    elif isinstance(value, dict):
        allowed = _DICT_METHODS
    elif isinstance(value, set | frozenset):
        allowed = _SET_METHODS
    elif isinstance(value, int | float | complex):
        allowed = _NUMBER_ATTRIBUTES
    if name not in allowed:
        raise ExpressionError(
            f"'{type(value).__name__}.{name}' is not available in a model file",
            hint="expressions may use properties, arithmetic, math and a few string methods",
        )
    found = getattr(value, name)
    return _method(value, name) if callable(found) else found


def call(function: Any, /, *args: Any, **kwargs: Any) -> Any:
    """Call ``function`` if it is one a model may call: an exposed one or its own lambda."""
    charge(1)
    own_lambda = (
        isinstance(function, types.FunctionType)
        and function.__code__.co_filename == SANDBOX_FILENAME
    )
    if not (own_lambda or isinstance(function, SafeFunction)):
        raise ExpressionError(
            f"calling a {type(function).__name__} is not available in a model file",
            hint="expressions may call the functions of xacro's python, math and xacro "
            "namespaces and their own lambdas",
        )
    return function(*args, **kwargs)


def item(value: Any, key: Any) -> Any:
    """``value[key]``; a slice is charged by the length of what it copies."""
    if isinstance(key, slice) and hasattr(value, "__len__"):
        charge(1 + len(value))
    else:
        charge(1 + (weight(key) if isinstance(key, str | bytes | tuple) else 0))
    return value[key]


def charged(value: Any) -> Any:
    """``value`` unchanged, after charging what comparing or printing it costs."""
    charge_weight(value)
    return value


#: What ``python.NAME`` says for the builtins ROS's xacro exposes and workbench does not.
REMOVED_PYTHON = {
    name: f"python.{name} is not available in a model file (workbench evaluates xacro "
    "expressions without access to Python's internals)"
    for name in ("vars", "getattr", "setattr", "globals", "locals", "eval", "exec", "open")
}
