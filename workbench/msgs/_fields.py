"""Field checkers and defaults for message classes.

Each field of a message gets a *checker* (value -> stored value, raising
:class:`BadValue` when the value cannot be stored in that field) and a
*default* factory (the zero value). Numeric arrays are stored as numpy
arrays of the wire dtype, because that is what the ROS 1 serializer writes.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

INT_RANGES: dict[str, tuple[int, int]] = {
    "int8": (-(2**7), 2**7 - 1),
    "byte": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "char": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
FLOATS = {"float32", "float64"}
DTYPES: dict[str, Any] = {
    "bool": np.bool_,
    "int8": np.int8,
    "byte": np.int8,
    "uint8": np.uint8,
    "char": np.uint8,
    "int16": np.int16,
    "uint16": np.uint16,
    "int32": np.int32,
    "uint32": np.uint32,
    "int64": np.int64,
    "uint64": np.uint64,
    "float32": np.float32,
    "float64": np.float64,
}


class BadValue(Exception):
    """Internal: a value does not fit a field; ``expected`` says what would."""

    def __init__(self, expected: str) -> None:
        super().__init__(expected)
        self.expected = expected


@dataclass(frozen=True)
class FieldSpec:
    """One field of a message type.

    Attributes:
        name: Field name.
        kind: ``base``, ``msg``, ``array`` (fixed length) or ``seq`` (variable length).
        elem: Primitive type name (``float64``, ``string`` ...) or a store type name
            (``geometry_msgs/msg/Vector3``) for ``msg`` fields and message arrays.
        elem_is_msg: Whether ``elem`` names a message type.
        length: Fixed array length (0 for sequences and scalars).
        ros_type: The field's type as ROS 1 writes it (``float64[9]``, ``geometry_msgs/Vector3[]``).
    """

    name: str
    kind: str
    elem: str
    elem_is_msg: bool
    length: int
    ros_type: str


def _describe(value: Any) -> str:
    text = repr(value)
    if len(text) > 40:
        text = text[:37] + "..."
    return f"{text} ({type(value).__name__})"


def scalar_checker(prim: str) -> Callable[[Any], Any]:
    """Checker for one primitive value."""
    if prim == "string":

        def check_string(value: Any) -> str:
            if isinstance(value, str):
                return value
            if isinstance(value, (bytes, bytearray)):
                try:
                    return bytes(value).decode()
                except UnicodeDecodeError as error:
                    raise BadValue("a UTF-8 string") from error
            raise BadValue("a str")

        return check_string
    if prim == "bool":

        def check_bool(value: Any) -> bool:
            if isinstance(value, (bool, np.bool_)) or (
                isinstance(value, (int, np.integer)) and value in (0, 1)
            ):
                return bool(value)
            raise BadValue("a bool")

        return check_bool
    if prim in FLOATS:

        def check_float(value: Any) -> float:
            if isinstance(value, float):
                return value
            if isinstance(value, (int, np.integer, np.floating)) and not isinstance(value, bool):
                try:
                    return float(value)
                except OverflowError:  # an int past 1.8e308 has no float
                    raise BadValue("a float (this integer is too large for one)") from None
            raise BadValue("a float")

        return check_float
    low, high = INT_RANGES[prim]

    def check_int(value: Any) -> int:
        if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            value = int(value)
            if low <= value <= high:
                return value
            raise BadValue(f"an integer in [{low}, {high}]")
        if isinstance(value, float) and value.is_integer() and low <= value <= high:
            return int(value)
        raise BadValue("an int")

    return check_int


def scalar_default(prim: str) -> Any:
    """The zero value of a primitive type."""
    if prim == "string":
        return ""
    if prim == "bool":
        return False
    if prim in FLOATS:
        return 0.0
    return 0


def numeric_array_checker(prim: str, length: int) -> Callable[[Any], np.ndarray]:
    """Checker for a numeric (or bool) array; ``length`` 0 means any length."""
    dtype = np.dtype(DTYPES[prim])
    is_int = prim in INT_RANGES
    what = f"{length} numbers" if length else "a sequence of numbers"

    def check(value: Any) -> np.ndarray:
        if isinstance(value, (bytes, bytearray, memoryview)) and dtype.itemsize == 1:
            array = np.frombuffer(bytes(value), dtype=dtype)
        elif isinstance(value, np.ndarray) and value.dtype == dtype:
            array = value
        else:
            if isinstance(value, (str, dict)) or not hasattr(value, "__len__"):
                raise BadValue(what)
            try:
                source = np.asarray(value)
                if source.ndim != 1 and source.size:
                    raise BadValue(f"a flat sequence ({what})")
                if is_int and source.size:
                    if source.dtype.kind not in "iub":
                        raise BadValue(f"{what} that are integers")
                    low, high = INT_RANGES[prim]
                    if source.min() < low or source.max() > high:
                        raise BadValue(f"integers in [{low}, {high}]")
                array = source.astype(dtype).reshape(-1)
            except (TypeError, ValueError, OverflowError) as error:
                raise BadValue(what) from error
        if length and array.shape[0] != length:
            raise BadValue(f"exactly {length} values, not {array.shape[0]}")
        return array

    return check


def list_checker(elem_check: Callable[[Any], Any], length: int, what: str) -> Callable[[Any], list]:
    """Checker for a list of strings or messages."""

    def check(value: Any) -> list:
        if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
            raise BadValue(f"a list of {what}")
        items = [elem_check(item) for item in value]
        if length and len(items) != length:
            raise BadValue(f"exactly {length} {what}, not {len(items)}")
        return items

    return check
