"""Which types get a ``ros_lib`` header: every message and service workbench knows.

The message store holds the ROS Noetic message set, the types workbench adds
(turtlesim, rosserial_msgs, gazebo_msgs ...) and whatever a script registered
(:func:`workbench.msgs.register_message`); :func:`register_package_dir` adds a ROS
package folder's ``msg/*.msg`` and ``srv/*.srv`` the way catkin would find them.

Two kinds of store entries get no header of their own, as in rosserial: the
request and response messages of a service (they live in the service's header)
and ``builtin_interfaces`` (``time`` and ``duration`` are ``ros::Time`` and
``ros::Duration`` of the Arduino library's runtime). A type with a field named
after a C++ keyword (``double``, ``class`` ...) cannot become a C++ class member:
it is left out with one warning naming the type and the field (rosserial would
write a header that does not compile).
"""

from __future__ import annotations

import difflib
import logging
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from workbench.errors import MessageError, SerialError
from workbench.msgs import (
    Message,
    ServiceType,
    get_service,
    get_type,
    list_services,
    list_types,
    register_message,
    register_service,
)

#: Packages of the store that are ROS 1 primitives rather than messages.
SKIPPED_PACKAGES = frozenset({"builtin_interfaces"})

#: C++11's keywords and alternative tokens: not usable as member names.
CPP_KEYWORDS = frozenset(
    [
        "alignas",
        "alignof",
        "and",
        "and_eq",
        "asm",
        "auto",
        "bitand",
        "bitor",
        "bool",
        "break",
        "case",
        "catch",
        "char",
        "char16_t",
        "char32_t",
        "class",
        "compl",
        "const",
        "constexpr",
        "const_cast",
        "continue",
        "decltype",
        "default",
        "delete",
        "do",
        "double",
        "dynamic_cast",
        "else",
        "enum",
        "explicit",
        "export",
        "extern",
        "false",
        "float",
        "for",
        "friend",
        "goto",
        "if",
        "inline",
        "int",
        "long",
        "mutable",
        "namespace",
        "new",
        "noexcept",
        "not",
        "not_eq",
        "nullptr",
        "operator",
        "or",
        "or_eq",
        "private",
        "protected",
        "public",
        "register",
        "reinterpret_cast",
        "return",
        "short",
        "signed",
        "sizeof",
        "static",
        "static_assert",
        "static_cast",
        "struct",
        "switch",
        "template",
        "this",
        "thread_local",
        "throw",
        "true",
        "try",
        "typedef",
        "typeid",
        "typename",
        "union",
        "unsigned",
        "using",
        "virtual",
        "void",
        "volatile",
        "wchar_t",
        "while",
        "xor",
        "xor_eq",
    ]
)

_LOG = logging.getLogger("workbench.serial")


def keyword_field(cls: type[Message]) -> str | None:
    """The first field of ``cls`` named after a C++ keyword, or None."""
    return next((s.name for s in cls._specs if s.name in CPP_KEYWORDS), None)


def _exportable(name: str, parts: Sequence[type[Message]]) -> bool:
    for part in parts:
        field = keyword_field(part)
        if field is not None:
            _LOG.warning(
                "%s left out: its field '%s' is a C++ keyword, which a header cannot declare",
                name,
                field,
            )
            return False
    return True


@dataclass(frozen=True)
class PackageTypes:
    """The message and service types of one package, sorted by name."""

    name: str
    messages: tuple[type[Message], ...]
    services: tuple[type[ServiceType], ...]


def known_packages(only: Sequence[str] | None = None) -> list[PackageTypes]:
    """The packages to export, sorted, with their message and service types.

    Args:
        only: Package names to keep; None keeps every package.

    Raises:
        SerialError: A name in ``only`` is not a package of any known type.
    """
    services = list_services()
    inside_services = {f"{name}{part}" for name in services for part in ("Request", "Response")}
    by_package: dict[str, tuple[list[str], list[str]]] = {}
    wanted = None if only is None else set(only)
    for name in list_types():
        package = name.split("/")[0]
        if name in inside_services or (wanted is not None and package not in wanted):
            by_package.setdefault(package, ([], []))
        elif _exportable(name, [get_type(name)]):
            by_package.setdefault(package, ([], []))[0].append(name)
    for name in services:
        package = name.split("/")[0]
        service = get_service(name)
        if wanted is not None and package not in wanted:
            by_package.setdefault(package, ([], []))
        elif _exportable(name, [service.Request, service.Response]):
            by_package.setdefault(package, ([], []))[1].append(name)
    for package in SKIPPED_PACKAGES:
        by_package.pop(package, None)
    names = sorted(by_package)
    if only is not None:
        for package in only:
            if package not in by_package:
                close = difflib.get_close_matches(package, names, n=3)
                hint = f"did you mean {', '.join(close)}?" if close else "see `workbench msg list`"
                raise SerialError(f"no message or service types in package '{package}'", hint=hint)
        names = [name for name in names if name in set(only)]
    return [
        PackageTypes(
            package,
            tuple(get_type(name) for name in by_package[package][0]),
            tuple(get_service(name) for name in by_package[package][1]),
        )
        for package in names
    ]


def package_name(directory: Path) -> str:
    """The name of a ROS package folder: its package.xml's ``<name>``, else the folder's name."""
    marker = directory / "package.xml"
    if marker.is_file():
        try:
            text = marker.read_text(errors="replace")
        except OSError as error:
            raise SerialError(f"cannot read {marker}: {error.strerror}") from None
        match = re.search(r"<name>\s*([^<\s]+)\s*</name>", text)
        if match:
            return match.group(1)
    return directory.resolve().name


def register_package_dir(directory: str | Path) -> str:
    """Register the ``msg/*.msg`` and ``srv/*.srv`` of a ROS package folder.

    Args:
        directory: The package folder (the one holding ``package.xml``, ``msg/``, ``srv/``).

    Returns:
        The package name the types were registered under.

    Raises:
        SerialError: The folder has no ``msg/`` or ``srv/`` files, or a file does not parse.
    """
    folder = Path(directory)
    files = sorted(folder.glob("msg/*.msg")) + sorted(folder.glob("srv/*.srv"))
    if not files:
        raise SerialError(
            f"{folder} holds no msg/*.msg or srv/*.srv files",
            hint="give the folder of a ROS package with message definitions",
        )
    package = package_name(folder)
    for path in files:
        try:
            text = path.read_text()
        except (OSError, UnicodeDecodeError) as error:
            raise SerialError(f"cannot read {path}: {error}") from None
        register = register_message if path.suffix == ".msg" else register_service
        try:
            register(f"{package}/{path.stem}", text)
        except MessageError as error:
            # the parser's message quotes the whole text over several lines: keep the first
            raise SerialError(
                error.message.splitlines()[0].rstrip(":"),
                path=path,
                hint=error.hint or "each line is 'type name' or 'type NAME=value'",
            ) from None
    return package
