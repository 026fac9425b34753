"""Friendly message classes built from the typestore's field definitions.

A message class has one slot per field, keyword (or all-positional)
construction with zero defaults, and checks every assignment: an unknown
field or a value of the wrong type raises a :class:`MessageError` naming the
field, the message type and what the field accepts.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from workbench.errors import MessageError
from workbench.msgs._fields import (
    DTYPES,
    BadValue,
    FieldSpec,
    _describe,
    list_checker,
    numeric_array_checker,
    scalar_checker,
    scalar_default,
)


class FieldError(MessageError, AttributeError):
    """A message has no field of that name."""

    _hint: str | None = None
    _name: str = ""
    _fields: tuple[str, ...] = ()

    @classmethod
    def no_field(cls, typename: str, name: str, fields: tuple[str, ...]) -> FieldError:
        """``typename`` has no field ``name``; the hint (the closest of ``fields``) is
        worked out when shown: attribute probes (``hasattr(msg, name)``,
        ``getattr(msg, name, default)``) raise this often, in tf's and navigation's hot
        paths, and never show it."""
        error = cls.__new__(cls)
        error.message = f"{typename} has no field '{name}'"
        error.path, error.line = None, None
        error._name, error._fields = name, fields
        Exception.__init__(error, error.message)
        return error

    @property
    def hint(self) -> str | None:
        if self._hint is None and self._name:
            import difflib

            close = difflib.get_close_matches(self._name, self._fields, n=1)
            fields = ", ".join(self._fields) or "none"
            self._hint = f"did you mean '{close[0]}'?" if close else f"its fields are: {fields}"
        return self._hint

    @hint.setter
    def hint(self, value: str | None) -> None:
        self._hint = value

    def __str__(self) -> str:
        return self.one_line()


class FieldTypeError(MessageError, TypeError):
    """A value does not fit the field it is assigned to."""


_UNSET = object()


class Message:
    """Base class of every message class (``workbench.msgs.<pkg>.<Name>``).

    Class attributes: ``_type`` (``"geometry_msgs/Twist"``), ``__msgtype__``
    (the typestore name ``"geometry_msgs/msg/Twist"``), ``_md5sum``,
    ``_full_text``, ``_has_header``, ``__slots__`` (field names, in order) and
    ``_slot_types`` (their ROS 1 types).
    """

    __slots__: ClassVar[tuple[str, ...]] = ()
    _type: ClassVar[str] = ""
    __msgtype__: ClassVar[str] = ""
    _has_header: ClassVar[bool] = False
    _slot_types: ClassVar[list[str]] = []
    _specs: ClassVar[tuple[FieldSpec, ...]] = ()
    _checkers: ClassVar[dict[str, Callable[[Any], Any]]] = {}
    _defaults: ClassVar[tuple[tuple[str, Callable[[], Any]], ...]] = ()

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        cls = type(self)
        if args:
            names = cls.__slots__
            if kwargs:
                raise MessageError(
                    f"{cls._type}: give field values either all by position or all by keyword"
                )
            if len(args) != len(names):
                raise MessageError(
                    f"{cls._type} takes {len(names)} positional values "
                    f"({', '.join(names) or 'none'}), got {len(args)}"
                )
            for name, value in zip(names, args, strict=True):
                self.__setattr__(name, value)
            return
        for name, factory in cls._defaults:
            value = kwargs.pop(name, _UNSET) if kwargs else _UNSET
            if value is _UNSET:
                object.__setattr__(self, name, factory())
            else:
                self.__setattr__(name, value)
        if kwargs:
            name = next(iter(kwargs))
            raise _unknown_field(cls, name)

    # Hidden from type checkers: the generated stubs (workbench/msgs/*.pyi) declare each
    # class's fields, and an unknown field must be a type error there, not ``Any``.
    if not TYPE_CHECKING:

        def __setattr__(self, name: str, value: Any) -> None:
            check = self._checkers.get(name)
            if check is None:
                raise _unknown_field(type(self), name)
            try:
                value = check(value)
            except BadValue as bad:
                spec = next(s for s in self._specs if s.name == name)
                raise FieldTypeError(
                    f"field '{name}' of {self._type} is {spec.ros_type} and needs "
                    f"{bad.expected}; got {_describe(value)}"
                ) from None
            object.__setattr__(self, name, value)

        def __getattr__(self, name: str) -> Any:
            if name.startswith("__"):
                raise AttributeError(name)
            raise _unknown_field(type(self), name)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Message) or other.__msgtype__ != self.__msgtype__:
            return NotImplemented
        for name in self.__slots__:
            mine, theirs = getattr(self, name), getattr(other, name)
            if isinstance(mine, np.ndarray) or isinstance(theirs, np.ndarray):
                if not np.array_equal(np.asarray(mine), np.asarray(theirs)):
                    return False
            elif mine != theirs:
                return False
        return True

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        body = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__slots__)
        return f"{type(self).__name__}({body})"

    def __str__(self) -> str:
        from workbench.msgs._convert import to_yaml

        return to_yaml(self)

    def __reduce__(self) -> tuple:
        return (_rebuild, (self._type, tuple(getattr(self, s.name) for s in self._specs)))

    def __copy__(self) -> Message:
        return type(self)._from_wire(*(getattr(self, s.name) for s in self._specs))

    def __deepcopy__(self, memo: dict) -> Message:
        import copy

        # the fields of the message type (a subclass such as rospy.Time adds none)
        values = (copy.deepcopy(getattr(self, spec.name), memo) for spec in self._specs)
        return type(self)._from_wire(*values)

    @classmethod
    def _from_wire(cls, *values: Any) -> Message:  # replaced per class by make_class
        raise NotImplementedError


def _rebuild(typename: str, values: tuple) -> Message:
    from workbench.msgs import get_type

    return get_type(typename)._from_wire(*values)


def _unknown_field(cls: type[Message], name: str) -> FieldError:
    return FieldError.no_field(cls._type, name, tuple(cls.__slots__))


class ServiceType:
    """Base class of service types: ``Spawn.Request``, ``Spawn.Response``, ``Spawn._md5sum``."""

    _type: ClassVar[str] = ""
    _md5sum: ClassVar[str] = ""
    _request_class: ClassVar[type[Message]]
    _response_class: ClassVar[type[Message]]
    Request: ClassVar[type[Message]]
    Response: ClassVar[type[Message]]

    def __init__(self) -> None:
        raise MessageError(
            f"{self._type} is a service type; build {self._type}.Request(...) "
            "or .Response(...) instead"
        )


def ros1_name(store_name: str) -> str:
    """``geometry_msgs/msg/Twist`` -> ``geometry_msgs/Twist``."""
    package, _, name = store_name.split("/")
    return f"{package}/{name}"


def _ros_type(spec_kind: str, elem: str, is_msg: bool, length: int) -> str:
    base = elem
    if is_msg:
        base = {
            "builtin_interfaces/msg/Time": "time",
            "builtin_interfaces/msg/Duration": "duration",
        }.get(elem) or ros1_name(elem)
    if spec_kind == "array":
        return f"{base}[{length}]"
    if spec_kind == "seq":
        return f"{base}[]"
    return base


def field_specs(fielddefs: list) -> tuple[FieldSpec, ...]:
    """Turn a typestore field list into :class:`FieldSpec` entries."""
    specs = []
    for name, desc in fielddefs:
        if name == "structure_needs_at_least_one_member":
            continue
        nodetype = int(desc[0])
        if nodetype in (1, 2):  # BASE, NAME
            kind, sub, length = ("base" if nodetype == 1 else "msg"), desc, 0
        else:  # ARRAY (3) or SEQUENCE (4)
            sub, length = desc[1]
            kind = "array" if nodetype == 3 else "seq"
            if kind == "seq":
                length = 0
        is_msg = int(sub[0]) == 2
        elem = sub[1] if is_msg else sub[1][0]
        specs.append(
            FieldSpec(name, kind, elem, is_msg, length, _ros_type(kind, elem, is_msg, length))
        )
    return tuple(specs)


def make_class(
    store_name: str,
    fielddefs: tuple,
    classes: dict[str, type[Message]],
    bases: tuple[type, ...] = (Message,),
) -> type[Message]:
    """Build the friendly class of one message type.

    Args:
        store_name: Typestore name (``geometry_msgs/msg/Twist``).
        fielddefs: The typestore's ``(constants, fields)`` for the type.
        classes: Store name -> class, filled by the caller; nested message
            fields look their class up here when first used.
        bases: Base classes (a mixin for time types, then :class:`Message`).
    """
    constants, fields = fielddefs
    specs = field_specs(fields)
    checkers: dict[str, Callable[[Any], Any]] = {}
    defaults: list[tuple[str, Callable[[], Any]]] = []
    for spec in specs:
        check, default = _checker_and_default(spec, classes)
        checkers[spec.name] = check
        defaults.append((spec.name, default))
    package, _, name = store_name.split("/")
    namespace: dict[str, Any] = {
        "__slots__": tuple(s.name for s in specs),
        "__module__": f"workbench.msgs.{package}",
        "__qualname__": name,
        "_type": f"{package}/{name}",
        "__msgtype__": store_name,
        "_has_header": bool(specs) and specs[0].elem == "std_msgs/msg/Header",
        "_slot_types": [s.ros_type for s in specs],
        "_specs": specs,
        "_checkers": checkers,
        "_defaults": tuple(defaults),
    }
    for const_name, _const_type, value in constants:
        namespace[const_name] = value
    cls: type[Message] = type(name, bases, namespace)
    cls._from_wire = _wire_constructor(cls)  # type: ignore[method-assign]
    return cls


def _wire_constructor(cls: type[Message]) -> Callable[..., Message]:
    """A constructor that trusts its values (the deserializer's), skipping checks."""
    setters = [cls.__dict__[name].__set__ for name in cls.__slots__]
    new = object.__new__
    lines = ["def _from_wire(*v):", "    self = new(cls)"]
    lines += [f"    s{i}(self, v[{i}])" for i in range(len(setters))]
    lines.append("    return self")
    scope: dict[str, Any] = {"new": new, "cls": cls}
    scope.update({f"s{i}": setter for i, setter in enumerate(setters)})
    exec("\n".join(lines), scope)  # noqa: S102 - code built from field indices only
    return staticmethod(scope["_from_wire"]).__get__(None, cls)


def _message_checker(elem: str, classes: dict[str, type[Message]]) -> Callable[[Any], Any]:
    def check(value: Any) -> Message:
        cls = classes[elem]
        if isinstance(value, cls):
            return value
        if isinstance(value, dict):
            try:
                return cls(**value)
            except MessageError as error:
                raise BadValue(f"a {cls._type} ({error.message})") from error
        if getattr(value, "__msgtype__", None) == elem:  # e.g. a plain rosbags object
            return cls(*(getattr(value, n) for n in cls.__slots__))
        raise BadValue(f"a {cls._type} message")

    return check


def _checker_and_default(
    spec: FieldSpec, classes: dict[str, type[Message]]
) -> tuple[Callable[[Any], Any], Callable[[], Any]]:
    elem = spec.elem
    if spec.elem_is_msg:
        elem_check = _message_checker(elem, classes)
        if spec.kind == "msg":
            return elem_check, lambda: classes[elem]()
        length = spec.length
        check = list_checker(elem_check, length, f"{ros1_name(elem)} messages")
        return check, lambda: [classes[elem]() for _ in range(length)]
    if spec.kind == "base":
        zero = scalar_default(elem)
        return scalar_checker(elem), lambda: zero
    if elem == "string":
        length = spec.length
        return list_checker(scalar_checker("string"), length, "strings"), lambda: [""] * length
    length = spec.length
    np_dtype = DTYPES[elem]
    return numeric_array_checker(elem, length), lambda: np.zeros(length, dtype=np_dtype)
