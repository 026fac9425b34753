"""The process-wide message type store (created on first use).

It wraps a rosbags ``Stores.ROS1_NOETIC`` typestore, registers the extra
types from :mod:`workbench.msgs._definitions`, builds one friendly class per
message type and one :class:`ServiceType` per service. The typestore's
deserializer constructs the friendly classes directly.
"""

from __future__ import annotations

import difflib
import hashlib
import re
import threading
from typing import Any

from workbench.errors import MessageError
from workbench.msgs._classes import Message, ServiceType, make_class, ros1_name
from workbench.msgs._time import DurationMixin, TimeMixin

_TIME = "builtin_interfaces/msg/Time"
_DURATION = "builtin_interfaces/msg/Duration"
_NAME_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*/(?:(?:msg|srv)/)?[A-Za-z][A-Za-z0-9_]*$")


class UnknownTypeError(MessageError, KeyError):
    """No message or service type of that name is registered."""

    def __str__(self) -> str:  # KeyError would quote the message
        return self.one_line()


class TypeStore:
    """Message classes, service types, definitions and md5sums."""

    def __init__(self) -> None:
        from rosbags.typesys import Stores, get_typestore

        self.lock = threading.RLock()
        self.ts = get_typestore(Stores.ROS1_NOETIC)
        self.classes: dict[str, type[Message]] = {}
        self.services: dict[str, type[ServiceType]] = {}
        self._defs: dict[str, tuple[str, str]] = {}
        self._build_classes()
        from workbench.msgs._definitions import MESSAGES, SERVICES

        for name, text in MESSAGES.items():
            self.register_message(name, text)
        for name, text in SERVICES.items():
            self.register_service(name, text)

    # --- building -------------------------------------------------------------------

    def _build_classes(self) -> None:
        for name in list(self.ts.fielddefs):
            if name in self.classes:
                continue
            bases: tuple[type, ...] = (Message,)
            if name == _TIME:
                bases = (TimeMixin, Message)
            elif name == _DURATION:
                bases = (DurationMixin, Message)
            cls = make_class(name, self.ts.fielddefs[name], self.classes, bases)
            self.classes[name] = cls
            # The generated deserializer calls types[name](*values): give it the
            # unchecked constructor so decoding does not re-validate every field.
            self.ts.types[name] = cls._from_wire  # type: ignore[assignment]
        if _TIME in self.classes and _DURATION in self.classes:
            for name in (_TIME, _DURATION):
                self.classes[name]._time_class = self.classes[_TIME]  # type: ignore[attr-defined]
                self.classes[name]._duration_class = self.classes[_DURATION]  # type: ignore[attr-defined]

    def register_message(self, typename: str, text: str) -> type[Message]:
        """Register a message type from its ``.msg`` text (dependencies may follow, as in bags).

        Args:
            typename: ``package/Name``.
            text: The ``.msg`` text; a bag's full definition (with ``MSG:`` sections) works too.

        Returns:
            The message class.
        """
        from rosbags.typesys import TypesysError, get_types_from_msg

        store_name = normalize(typename)
        with self.lock:
            try:
                types = get_types_from_msg(text, store_name)
                self.ts.register(types)
            except TypesysError as error:
                raise MessageError(f"cannot register {typename}: {error}") from None
            except Exception as error:  # the parser's own errors: bad .msg text
                raise MessageError(
                    f"cannot parse the definition of {typename}: {type(error).__name__}: {error}"
                ) from None
            self._build_classes()
            return self.classes[store_name]

    def register_service(self, typename: str, text: str) -> type[ServiceType]:
        """Register a service type from its ``.srv`` text (request ``---`` response)."""
        parts = re.split(r"^---[ \t]*$", text, maxsplit=1, flags=re.MULTILINE)
        if len(parts) != 2:
            raise MessageError(f"the definition of service {typename} has no '---' line")
        ros_name = ros1_name(normalize(typename))
        with self.lock:
            request = self.register_message(f"{ros_name}Request", parts[0])
            response = self.register_message(f"{ros_name}Response", parts[1].lstrip("\n"))
            md5 = hashlib.md5(
                (self.md5_text(request.__msgtype__) + self.md5_text(response.__msgtype__)).encode()
            ).hexdigest()
            package, name = ros_name.split("/")
            service = type(
                name,
                (ServiceType,),
                {
                    "__module__": f"workbench.msgs.{package}",
                    "__qualname__": name,
                    "_type": ros_name,
                    "_md5sum": md5,
                    "_request_class": request,
                    "_response_class": response,
                    "Request": request,
                    "Response": response,
                },
            )
            self.services[ros_name] = service
            return service

    # --- lookup ---------------------------------------------------------------------

    def message_class(self, typename: str) -> type[Message]:
        cls = self.classes.get(normalize(typename))
        if cls is None:
            raise self._unknown(typename, "message")
        return cls

    def service_class(self, typename: str) -> type[ServiceType]:
        key = ros1_name(normalize(typename).replace("/srv/", "/msg/"))
        service = self.services.get(key)
        if service is None:
            raise self._unknown(typename, "service")
        return service

    def _unknown(self, typename: str, kind: str) -> UnknownTypeError:
        names = self.service_names() if kind == "service" else self.message_names()
        close = difflib.get_close_matches(typename, names, n=3, cutoff=0.6)
        if not close:
            tail = typename.rsplit("/", 1)[-1].lower()
            close = [n for n in names if n.rsplit("/", 1)[-1].lower() == tail][:3]
        hint = (
            f"did you mean {', '.join(close)}?"
            if close
            else f"'workbench {'srv' if kind == 'service' else 'msg'} list' shows the known types"
        )
        return UnknownTypeError(f"unknown {kind} type '{typename}'", hint=hint)

    def message_names(self) -> list[str]:
        return sorted(ros1_name(n) for n in self.classes)

    def service_names(self) -> list[str]:
        return sorted(self.services)

    # --- definitions and md5 ----------------------------------------------------------

    def definition_and_md5(self, typename: str) -> tuple[str, str]:
        store_name = self.message_class(typename).__msgtype__
        cached = self._defs.get(store_name)
        if cached is None:
            with self.lock:
                cached = self.ts.generate_msgdef(store_name)
                self._defs[store_name] = cached
        return cached

    def md5_text(self, store_name: str) -> str:
        """The text ROS hashes for a type (nested types replaced by their md5sums)."""
        constants, fields = self.ts.fielddefs[store_name]
        lines = [f"{typ} {name}={value}" for name, typ, value in constants]
        desc: Any  # the typestore's nested field descriptions (node type, details)
        special = {_TIME: "time", _DURATION: "duration"}
        for name, desc in fields:
            if name == "structure_needs_at_least_one_member":
                continue
            nodetype = int(desc[0])
            if nodetype == 1:
                prim, limit = desc[1]
                lines.append(f"{_prim(prim, limit)} {name}")
            elif nodetype == 2:
                sub = desc[1]
                lines.append(f"{special.get(sub) or self.definition_and_md5(sub)[1]} {name}")
            else:
                (subtype, sub), count = desc[1]
                if int(subtype) == 1 or sub in special:
                    base = _prim(*sub) if int(subtype) == 1 else special[sub]
                    size = "" if count == 0 else str(count) if nodetype == 3 else f"<={count}"
                    lines.append(f"{base}[{size}] {name}")
                else:
                    lines.append(f"{self.definition_and_md5(sub)[1]} {name}")
        return "\n".join(lines)


def _prim(prim: str, limit: Any) -> str:
    return f"string<={limit}" if prim == "string" and limit else prim


def normalize(typename: str) -> str:
    """``pkg/Name`` or ``pkg/msg/Name`` -> the typestore's ``pkg/msg/Name``.

    Raises:
        MessageError: The name is not of the form ``package/Name``.
    """
    if not isinstance(typename, str) or not _NAME_RE.match(typename):
        raise MessageError(
            f"'{typename}' is not a message type name",
            hint="write it as package/Name, e.g. geometry_msgs/Twist",
        )
    parts = typename.split("/")
    return f"{parts[0]}/msg/{parts[-1]}"


_STORE: TypeStore | None = None
_STORE_LOCK = threading.Lock()


def store() -> TypeStore:
    """The process-wide type store (built on first use, about 0.15 s)."""
    global _STORE
    if _STORE is None:
        with _STORE_LOCK:
            if _STORE is None:
                _STORE = TypeStore()
    return _STORE
