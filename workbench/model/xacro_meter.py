"""The bounds of a xacro file's expressions: sizes, integer bits, work and time.

Every operation a model's expression performs is charged to the :class:`Meter` of
the expansion in progress (see :func:`metered`): one unit per step, and the size of
a value whenever an operation reads or copies all of it (:func:`weight`). Past
:data:`MAX_STEPS` units or :data:`MAX_SECONDS` seconds the expansion stops with an
:class:`ExpressionLimitError`. Integers and values are bounded before anything is
computed with them, so no single step runs long in C and Ctrl-C always gets through.
"""

from __future__ import annotations

import contextlib
import time
import types
from collections.abc import Iterator
from typing import Any

from workbench.errors import ModelError

#: Largest integer a model expression may make, in bits (about 1233 decimal digits).
MAX_INT_BITS = 4096
#: Largest value a model expression may make: characters of a string, items of a collection
#: (counted through nested collections).
MAX_SIZE = 1_000_000
#: Work units one file's expressions may spend (an operation on a value of size n costs n).
MAX_STEPS = 2_000_000
#: Seconds one file's expansion may take (a backstop: the bounds above stop hostile files
#: within a few seconds; xacro itself needs a few for thousands of macro calls).
MAX_SECONDS = 60.0
#: Longest expression text, characters.
MAX_EXPRESSION_LENGTH = 10_000
#: Widths and precisions allowed in ``%`` formats and f-strings.
MAX_FORMAT_WIDTH = 10_000


class ExpressionLimitError(ModelError):
    """A xacro expression needs more work, memory or time than a model file may use."""


# --- the meter ----------------------------------------------------------------------


class Meter:
    """Work and time spent by one file's expressions.

    Args:
        max_steps: Work units allowed.
        max_seconds: Wall-clock seconds allowed from now.
    """

    def __init__(self, max_steps: int = MAX_STEPS, max_seconds: float = MAX_SECONDS) -> None:
        self.max_steps = max_steps
        self.max_seconds = max_seconds
        self.steps = 0
        self.started = time.monotonic()
        self._next_clock = 10_000

    def charge(self, units: int = 1) -> None:
        """Spend ``units``; raise :class:`ExpressionLimitError` past a bound."""
        self.steps += units
        if self.steps > self.max_steps:
            raise ExpressionLimitError(
                f"the expressions need more than {self.max_steps:,} operations",
                hint="a model file may compute, but within bounds; see 'Limits on input' "
                "in the README",
            )
        if self.steps >= self._next_clock:
            self._next_clock = self.steps + 10_000
            self.check_time()

    def check_time(self) -> None:
        """Raise :class:`ExpressionLimitError` once the time is up."""
        if time.monotonic() - self.started > self.max_seconds:
            raise ExpressionLimitError(
                f"expanding the file takes more than {self.max_seconds:g} s",
                hint="a model file may compute, but within bounds; see 'Limits on input' "
                "in the README",
            )


_meter: Meter | None = None


@contextlib.contextmanager
def metered(meter: Meter) -> Iterator[Meter]:
    """Charge every expression evaluated inside to ``meter``."""
    global _meter
    previous, _meter = _meter, meter
    try:
        yield meter
    finally:
        _meter = previous


def meter_in_use() -> Meter | None:
    """The meter of the expansion in progress, if any."""
    return _meter


def charge(units: int = 1) -> None:
    if _meter is not None:  # outside an evaluation (xacro printing a result) nothing is charged
        _meter.charge(units)


# --- sizes ----------------------------------------------------------------------------

_SCALARS = (int, float, complex, bool, type(None))
DATA_TYPES = (str, bytes, list, tuple, dict, set, frozenset, range, *_SCALARS)
_COLLECTIONS: tuple[type, ...] = (list, tuple, set, frozenset, types.MappingProxyType)
_COLLECTIONS += (type({}.keys()), type({}.values()), type({}.items()))


def weight(value: Any, cap: int = MAX_SIZE) -> int:
    """How much work converting or comparing ``value`` costs: characters plus items, deep.

    Counting stops just above ``cap`` (a shared or endless structure cannot hang it).
    """
    total = 0
    stack = [value]
    while stack and total <= cap:
        item = stack.pop()
        if isinstance(item, str | bytes):
            total += len(item)
        elif isinstance(item, int):
            total += 1 + item.bit_length() // 64
        elif isinstance(item, _SCALARS):
            total += 1
        elif isinstance(item, range):
            total += len(item)
        elif isinstance(item, dict):
            total += 1
            stack.extend(dict.keys(item))
            stack.extend(dict.values(item))
            parent = getattr(item, "parent", None)  # a xacro namespace prints its parents too
            if isinstance(parent, dict) and parent is not item:
                stack.append(parent)
        elif isinstance(item, _COLLECTIONS):
            total += 1
            stack.extend(item)  # type: ignore[arg-type]
        else:
            total += 1
    return total


def check_size(value: Any, what: str = "the result") -> Any:
    size = weight(value)
    if size > MAX_SIZE:
        raise ExpressionLimitError(
            f"{what} would hold more than {MAX_SIZE:,} characters or items",
            hint="a model file may compute, but within bounds; see 'Limits on input' in the README",
        )
    charge(size)
    return value


def charge_weight(value: Any) -> None:
    """Charge what reading ``value`` costs; refuse a value past :data:`MAX_SIZE`."""
    check_size(value, "a value")


def check_int(value: Any) -> Any:
    if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
        raise ExpressionLimitError(
            f"the result has {value.bit_length():,} bits; a model file may compute integers "
            f"of at most {MAX_INT_BITS} bits",
            hint="use floats, such as 1e300, for very large numbers",
        )
    return value


def int_bits_limit(bits: float, what: str) -> None:
    if bits > MAX_INT_BITS:
        raise ExpressionLimitError(
            f"{what} would have about {bits:,.0f} bits; a model file may compute integers "
            f"of at most {MAX_INT_BITS} bits",
            hint="use floats, such as 9.0**99, for very large numbers",
        )
