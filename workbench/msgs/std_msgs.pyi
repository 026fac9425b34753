"""Types of the std_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import builtin_interfaces
from workbench.msgs import std_msgs as msg
from workbench.msgs import std_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "Bool",
    "Byte",
    "ByteMultiArray",
    "Char",
    "ColorRGBA",
    "Duration",
    "Empty",
    "Float32",
    "Float32MultiArray",
    "Float64",
    "Float64MultiArray",
    "Header",
    "Int16",
    "Int16MultiArray",
    "Int32",
    "Int32MultiArray",
    "Int64",
    "Int64MultiArray",
    "Int8",
    "Int8MultiArray",
    "MultiArrayDimension",
    "MultiArrayLayout",
    "String",
    "Time",
    "UInt16",
    "UInt16MultiArray",
    "UInt32",
    "UInt32MultiArray",
    "UInt64",
    "UInt64MultiArray",
    "UInt8",
    "UInt8MultiArray",
    "msg",
    "srv",
]

class Bool(Message):
    """``std_msgs/Bool``."""

    data: bool
    def __init__(
        self,
        data: bool = ...,
    ) -> None: ...

class Byte(Message):
    """``std_msgs/Byte``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class ByteMultiArray(Message):
    """``std_msgs/ByteMultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Char(Message):
    """``std_msgs/Char``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class ColorRGBA(Message):
    """``std_msgs/ColorRGBA``."""

    r: float
    g: float
    b: float
    a: float
    def __init__(
        self,
        r: float = ...,
        g: float = ...,
        b: float = ...,
        a: float = ...,
    ) -> None: ...

class Duration(Message):
    """``std_msgs/Duration``."""

    @property
    def data(self) -> builtin_interfaces.Duration: ...
    @data.setter
    def data(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        data: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...

class Empty(Message):
    """``std_msgs/Empty``."""

    def __init__(self) -> None: ...

class Float32(Message):
    """``std_msgs/Float32``."""

    data: float
    def __init__(
        self,
        data: float = ...,
    ) -> None: ...

class Float32MultiArray(Message):
    """``std_msgs/Float32MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.float32]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Float64(Message):
    """``std_msgs/Float64``."""

    data: float
    def __init__(
        self,
        data: float = ...,
    ) -> None: ...

class Float64MultiArray(Message):
    """``std_msgs/Float64MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.float64]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Header(Message):
    """``std_msgs/Header``."""

    seq: int
    @property
    def stamp(self) -> builtin_interfaces.Time: ...
    @stamp.setter
    def stamp(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    frame_id: str
    def __init__(
        self,
        seq: int = ...,
        stamp: builtin_interfaces.Time | Mapping[str, Any] = ...,
        frame_id: str = ...,
    ) -> None: ...

class Int16(Message):
    """``std_msgs/Int16``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class Int16MultiArray(Message):
    """``std_msgs/Int16MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int16]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Int32(Message):
    """``std_msgs/Int32``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class Int32MultiArray(Message):
    """``std_msgs/Int32MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int32]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Int64(Message):
    """``std_msgs/Int64``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class Int64MultiArray(Message):
    """``std_msgs/Int64MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int64]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Int8(Message):
    """``std_msgs/Int8``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class Int8MultiArray(Message):
    """``std_msgs/Int8MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class MultiArrayDimension(Message):
    """``std_msgs/MultiArrayDimension``."""

    label: str
    size: int
    stride: int
    def __init__(
        self,
        label: str = ...,
        size: int = ...,
        stride: int = ...,
    ) -> None: ...

class MultiArrayLayout(Message):
    """``std_msgs/MultiArrayLayout``."""

    @property
    def dim(self) -> list[MultiArrayDimension]: ...
    @dim.setter
    def dim(self, value: Iterable[MultiArrayDimension | Mapping[str, Any]]) -> None: ...
    data_offset: int
    def __init__(
        self,
        dim: Iterable[MultiArrayDimension | Mapping[str, Any]] = ...,
        data_offset: int = ...,
    ) -> None: ...

class String(Message):
    """``std_msgs/String``."""

    data: str
    def __init__(
        self,
        data: str = ...,
    ) -> None: ...

class Time(Message):
    """``std_msgs/Time``."""

    @property
    def data(self) -> builtin_interfaces.Time: ...
    @data.setter
    def data(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        data: builtin_interfaces.Time | Mapping[str, Any] = ...,
    ) -> None: ...

class UInt16(Message):
    """``std_msgs/UInt16``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class UInt16MultiArray(Message):
    """``std_msgs/UInt16MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.uint16]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class UInt32(Message):
    """``std_msgs/UInt32``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class UInt32MultiArray(Message):
    """``std_msgs/UInt32MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.uint32]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class UInt64(Message):
    """``std_msgs/UInt64``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class UInt64MultiArray(Message):
    """``std_msgs/UInt64MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.uint64]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class UInt8(Message):
    """``std_msgs/UInt8``."""

    data: int
    def __init__(
        self,
        data: int = ...,
    ) -> None: ...

class UInt8MultiArray(Message):
    """``std_msgs/UInt8MultiArray``."""

    @property
    def layout(self) -> MultiArrayLayout: ...
    @layout.setter
    def layout(self, value: MultiArrayLayout | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.uint8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        layout: MultiArrayLayout | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...
