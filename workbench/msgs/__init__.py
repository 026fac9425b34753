"""ROS 1 message and service types.

The full Noetic message set comes from the rosbags typestore (definitions,
md5sums and ROS 1 serialization); the types the labs need that it lacks
(turtlesim, tf2_msgs, std_srvs, beginner_tutorials, rosserial_msgs, gazebo_msgs ...) are
registered from their ``.msg``/``.srv`` text. Every type is a friendly class::

    from workbench.msgs.geometry_msgs import Twist, Vector3
    cmd = Twist(linear=Vector3(x=2.0))           # other fields are zero
    from workbench.msgs.turtlesim import Spawn
    req = Spawn.Request(x=1.0, y=2.0, name="t2")  # Spawn._md5sum is ROS's service md5

Assigning an unknown field or a value of the wrong type raises
:class:`~workbench.errors.MessageError` naming the field and the type.
Numeric arrays are stored as numpy arrays of the wire dtype (lists and bytes
are converted on assignment).
"""

from __future__ import annotations

from typing import Any

from workbench.errors import MessageError
from workbench.msgs._classes import FieldError, FieldTypeError, Message, ServiceType
from workbench.msgs._convert import from_dict as _from_dict
from workbench.msgs._convert import to_dict, to_yaml
from workbench.msgs._store import UnknownTypeError, store

__all__ = [
    "Duration",
    "FieldError",
    "FieldTypeError",
    "Message",
    "MessageError",
    "ServiceType",
    "Time",
    "UnknownTypeError",
    "definition",
    "deserialize",
    "from_dict",
    "get_service",
    "get_type",
    "is_service",
    "list_services",
    "list_types",
    "md5sum",
    "register_message",
    "register_service",
    "serialize",
    "service_definition",
    "to_dict",
    "to_yaml",
    "type_name",
]


def get_type(typename: str) -> Any:
    """The class of a message or service type.

    Args:
        typename: ``package/Name`` (``geometry_msgs/Twist``); ``package/msg/Name`` works too.

    Returns:
        A :class:`Message` subclass, or a :class:`ServiceType` subclass for a service.

    Raises:
        MessageError: Unknown type (the message suggests close names) or malformed name.
    """
    types = store()
    try:
        return types.message_class(typename)
    except UnknownTypeError:
        if "/msg/" not in typename:
            try:
                return types.service_class(typename)
            except UnknownTypeError:
                pass
        raise


def get_service(typename: str) -> type[ServiceType]:
    """The class of a service type (``turtlesim/Spawn``); unknown -> MessageError."""
    return store().service_class(typename)


def is_service(cls: Any) -> bool:
    """Whether ``cls`` is a service type (has ``Request``/``Response``)."""
    return isinstance(cls, type) and issubclass(cls, ServiceType)


def type_name(msg_or_cls: Any) -> str:
    """``geometry_msgs/Twist`` for a message, a message class or a service class."""
    name = getattr(msg_or_cls, "_type", None)
    if not isinstance(name, str) or not name:
        raise MessageError(f"{msg_or_cls!r} is not a message or service type")
    return name


def serialize(msg: Message) -> bytes:
    """The ROS 1 wire bytes of a message (as in bags and on the network).

    Raises:
        MessageError: ``msg`` is not a message, or a field holds a value that does not fit.
    """
    if not isinstance(msg, Message):
        raise MessageError(
            f"cannot serialize {type(msg).__name__}: it is not a workbench message",
            hint="build one with workbench.msgs.get_type(name)(...)",
        )
    try:
        return bytes(store().ts.serialize_ros1(msg, msg.__msgtype__))
    except MessageError:
        raise
    except Exception as error:
        _revalidate(msg)
        raise MessageError(f"cannot serialize {msg._type}: {error}") from None


def _revalidate(msg: Message) -> None:
    """Re-assign every field so a value changed in place (a list) is named in the error."""
    for name in msg.__slots__:
        value = getattr(msg, name)
        if isinstance(value, Message):
            _revalidate(value)
        elif isinstance(value, list) and value and isinstance(value[0], Message):
            for item in value:
                _revalidate(item)
        setattr(msg, name, value)


def deserialize(data: bytes | bytearray | memoryview, typename: str) -> Message:
    """A message from its ROS 1 wire bytes.

    Raises:
        MessageError: Unknown type, or bytes that are not a ``typename`` (truncated, too long).
    """
    types = store()
    cls = types.message_class(typename)
    try:
        # The typestore declares bytes | memoryview and returns object; a bytearray works too.
        message: Message = types.ts.deserialize_ros1(data, cls.__msgtype__)  # type: ignore[arg-type, assignment]
        return message
    except Exception as error:
        raise MessageError(
            f"{len(data)} bytes are not a valid {cls._type}: {error}",
            hint="check that both sides use the same message type (md5sum)",
        ) from None


def md5sum(typename: str) -> str:
    """The ROS 1 md5sum of a message type, or of a service type (as ROS computes it)."""
    types = store()
    try:
        return types.definition_and_md5(typename)[1]
    except UnknownTypeError:
        return types.service_class(typename)._md5sum


def definition(typename: str) -> str:
    """The full ROS 1 definition of a message type, dependencies appended as in bag files."""
    return store().definition_and_md5(typename)[0]


def service_definition(typename: str) -> str:
    """The request and response definitions of a service, separated by ``---``."""
    service = store().service_class(typename)
    request = store().ts.generate_msgdef(service.Request.__msgtype__)[0].split("=" * 80)[0]
    response = store().ts.generate_msgdef(service.Response.__msgtype__)[0].split("=" * 80)[0]
    return f"{request}---\n{response}"


def from_dict(typename: str | type[Message], data: Any) -> Message:
    """A message from a dict (fields by name) or a list (fields by position, ``rostopic pub`` style).

    Args:
        typename: ``package/Name`` or a message class.
        data: Dict, list, or a bare value for a one-field message; nested messages likewise.
    """
    cls = get_type(typename) if isinstance(typename, str) else typename
    if is_service(cls):
        raise MessageError(f"{cls._type} is a service; use {cls._type}Request or Response")
    return _from_dict(cls, data)


def list_types(package: str | None = None) -> list[str]:
    """All message type names (``package/Name``), optionally of one package."""
    names = store().message_names()
    return [n for n in names if package is None or n.split("/")[0] == package]


def list_services(package: str | None = None) -> list[str]:
    """All service type names, optionally of one package."""
    names = store().service_names()
    return [n for n in names if package is None or n.split("/")[0] == package]


def register_message(typename: str, text: str) -> type[Message]:
    """Register a message type from ``.msg`` text (or a bag's full definition)."""
    return store().register_message(typename, text)


def register_service(typename: str, text: str) -> type[ServiceType]:
    """Register a service type from ``.srv`` text."""
    return store().register_service(typename, text)


#: "Time"/"Duration" -> (the store they came from, the class): simulators stamp every message.
_TIME_CLASSES: dict[str, tuple[Any, Any]] = {}


def __getattr__(name: str) -> Any:
    # Time and Duration are classes of the lazily built store.
    if name in ("Time", "Duration"):
        types = store()
        cached = _TIME_CLASSES.get(name)
        if cached is None or cached[0] is not types:
            cached = (types, types.message_class(f"builtin_interfaces/{name}"))
            _TIME_CLASSES[name] = cached
        return cached[1]
    raise AttributeError(f"module 'workbench.msgs' has no attribute '{name}'")
