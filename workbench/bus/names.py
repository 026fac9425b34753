"""ROS graph names: validation, resolution, remapping and command-line arguments.

The rules are ROS 1's: a name is global (``/a/b``), relative (``a/b``,
resolved in the node's namespace) or private (``~a``, resolved under the node
name). Remappings (``from:=to``) apply to resolved names. Special arguments
on a script's command line: ``__name:=``, ``__ns:=``, ``_param:=value``
(a private parameter, value read as YAML) and ``__log``/``__ip``/``__hostname``/
``__master`` (accepted and ignored).

Unlike ROS, a name is at most :data:`MAX_NAME_LENGTH` characters (resolved):
names travel inside the transport's keys, which must fit one network batch.
"""

from __future__ import annotations

import os
import re
import time
from dataclasses import dataclass, field
from typing import Any

from workbench.errors import BusError


class InvalidNameError(BusError, ValueError):
    """A topic, service, parameter or node name breaks the ROS naming rules."""


#: Longest graph name (a resolved topic, service, node or parameter name), in characters.
MAX_NAME_LENGTH = 512

_NAME_RE = re.compile(r"^[~/]?([A-Za-z][A-Za-z0-9_]*)?(/[A-Za-z][A-Za-z0-9_]*)*/?$")
_BASE_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


def _check_length(name: str, what: str) -> None:
    if len(name) > MAX_NAME_LENGTH:
        raise InvalidNameError(
            f"{what} '{name[:40]}...' is {len(name):,} characters long, more than the "
            f"{MAX_NAME_LENGTH} a name may have",
            hint="use a shorter name",
        )


def check_name(name: str, what: str = "name") -> str:
    """Raise :class:`InvalidNameError` unless ``name`` is a legal graph resource name."""
    if not isinstance(name, str):
        raise InvalidNameError(f"{what} must be a string, not {type(name).__name__}")
    _check_length(name, what)
    if name in ("", "/", "~"):
        return name
    ok = _NAME_RE.match(name) is not None and "//" not in name
    if name.startswith("~/") or (name.endswith("/") and name != "/"):
        ok = False
    if not ok:
        raise InvalidNameError(
            f"'{name}' is not a valid ROS {what}",
            hint="use letters, digits, '_' and '/'; start each part with a letter "
            "(e.g. 'turtle1/cmd_vel', '/chatter', '~rate')",
        )
    return name


def check_base_name(name: str, what: str = "node name") -> str:
    """A base name (no namespace): a letter then letters, digits or ``_``."""
    if isinstance(name, str):
        _check_length(name, what)
    if not isinstance(name, str) or not _BASE_RE.match(name):
        hint = (
            "namespaces are not allowed here; use namespace= or __ns:="
            if "/" in str(name)
            else None
        )
        raise InvalidNameError(
            f"'{name}' is not a valid {what}",
            hint=hint or "use a letter followed by letters, digits or '_'",
        )
    return name


def join(namespace: str, name: str) -> str:
    """Join a namespace and a relative name: ``join('/a', 'b') == '/a/b'``."""
    if not name:
        return namespace or "/"
    if namespace in ("", "/"):
        return "/" + name
    return namespace.rstrip("/") + "/" + name


def namespace_of(name: str) -> str:
    """The namespace of a global name: ``/a/b/c`` -> ``/a/b``; ``/c`` -> ``/``."""
    head = name.rstrip("/").rsplit("/", 1)[0]
    return head or "/"


def canonical_namespace(namespace: str | None) -> str:
    """``None``/``''`` -> ``/``; ``ns`` -> ``/ns``; no trailing slash."""
    if not namespace:
        return "/"
    check_name(namespace.rstrip("/") or "/", "namespace")
    if namespace.startswith("~"):
        raise InvalidNameError(f"namespace '{namespace}' cannot be private")
    if not namespace.startswith("/"):
        namespace = "/" + namespace
    return namespace.rstrip("/") or "/"


def resolve(name: str, namespace: str, node_name: str, what: str = "name") -> str:
    """Resolve a name to a global one, as ROS does (no remapping).

    Args:
        name: The name as written (``chatter``, ``/chatter``, ``~rate``).
        namespace: The node's namespace (``/`` or ``/ns``).
        node_name: The node's global name (``/ns/talker``), used for ``~`` names.
        what: What the name is, for error messages.
    """
    check_name(name, what)
    if name.startswith("/"):
        resolved = name
    elif name.startswith("~"):
        resolved = join(node_name, name[1:])
    else:
        resolved = join(namespace, name)
    resolved = resolved.rstrip("/") or "/"
    _check_length(resolved, what)
    return resolved


def anonymous_name(base: str) -> str:
    """``base_<pid>_<ms since epoch>``, as rospy builds anonymous names."""
    return f"{base}_{os.getpid()}_{int(time.time() * 1000)}"


@dataclass
class CommandLine:
    """The ROS special arguments found on a command line.

    Attributes:
        remappings: ``from`` -> ``to`` as written (resolved later against the node).
        node_name: ``__name:=`` value, if given.
        namespace: ``__ns:=`` value, if given.
        params: Private parameters from ``_name:=value`` (values parsed as YAML).
        others: The arguments that are not ROS arguments (``rospy.myargv``).
    """

    remappings: dict[str, str] = field(default_factory=dict)
    node_name: str | None = None
    namespace: str | None = None
    params: dict[str, Any] = field(default_factory=dict)
    others: list[str] = field(default_factory=list)


_IGNORED = {"__log", "__ip", "__hostname", "__master"}


def parse_command_line(argv: list[str]) -> CommandLine:
    """Split ``argv`` into ROS remapping arguments and the rest.

    Raises:
        InvalidNameError: A remapping names an invalid graph name.
    """
    from workbench.limits import load_yaml

    result = CommandLine()
    for arg in argv:
        if ":=" not in arg or arg.startswith("-"):
            result.others.append(arg)
            continue
        key, value = arg.split(":=", 1)
        if key == "__name":
            result.node_name = check_base_name(value)
        elif key == "__ns":
            result.namespace = canonical_namespace(value)
        elif key in _IGNORED:
            continue
        elif key.startswith("_") and not key.startswith("__"):
            name = key[1:]
            check_name(name, "parameter name")
            try:
                result.params[name] = load_yaml(value, f"_{name}", error=BusError) if value else ""
            except BusError as error:
                if "is not valid YAML" not in error.message:
                    raise  # past a bound; text that is not YAML is a string, as in rospy
                result.params[name] = value
        else:
            check_name(key, "remapping source")
            check_name(value, "remapping target")
            result.remappings[key] = value
    return result


def myargv(argv: list[str]) -> list[str]:
    """``argv`` without the ROS remapping arguments (``rospy.myargv``)."""
    return [arg for arg in argv if ":=" not in arg or arg.startswith("-")]
