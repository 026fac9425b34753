"""rosparam's operations on a parameter server: YAML in and out, files, namespaces."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import yaml

from workbench.errors import BusError
from workbench.limits import load_yaml, load_yaml_file


def _full(name: str) -> str:
    return name if name.startswith("/") else "/" + name


def list_names(server: Any, namespace: str = "/") -> list[str]:
    """Parameter names under ``namespace`` (``rosparam list``)."""
    ns = _full(namespace).rstrip("/") + "/"
    return [n for n in server.names() if ns == "/" or n.startswith(ns) or n == ns.rstrip("/")]


def to_yaml(value: Any) -> str:
    """A value as rosparam prints it (block style, no document end marker)."""
    text = yaml.safe_dump(value, default_flow_style=False, sort_keys=True)
    if text.endswith("\n...\n"):
        text = text[: -len("\n...\n")]
    return text.rstrip("\n")


def get_text(server: Any, name: str) -> str:
    """``rosparam get NAME``.

    Raises:
        BusError: the parameter is not set.
    """
    try:
        return to_yaml(server.get(_full(name)))
    except KeyError:
        raise BusError(
            f"parameter [{_full(name)}] is not set", hint="'workbench param list' shows them"
        ) from None


def parse_value(text: str) -> Any:
    """A command-line value as YAML (``150`` is an int, ``'[1, 2]'`` a list).

    Raises:
        BusError: not valid YAML.
    """
    return load_yaml(text, f"value {_short(text)}", error=BusError)


def _short(text: str) -> str:
    return repr(text if len(text) <= 40 else text[:37] + "...")


def set_text(server: Any, name: str, text: str) -> None:
    """``rosparam set NAME VALUE``."""
    server.set(_full(name), parse_value(text))


def delete(server: Any, name: str) -> None:
    """``rosparam delete NAME``."""
    try:
        server.delete(_full(name))
    except KeyError:
        raise BusError(f"parameter [{_full(name)}] is not set") from None


def dump(server: Any, path: str | os.PathLike[str], namespace: str = "/") -> Path:
    """``rosparam dump FILE [NAMESPACE]``: the namespace's tree as YAML.

    Raises:
        BusError: the namespace is not set or the file cannot be written.
    """
    path = Path(path)
    try:
        value = server.get(_full(namespace))
    except KeyError:
        raise BusError(f"parameter [{_full(namespace)}] is not set") from None
    try:
        path.write_text(yaml.safe_dump(value, default_flow_style=False, sort_keys=True))
    except OSError as error:
        raise BusError(f"cannot write parameters: {error.strerror or error}", path=path) from None
    return path


def load(server: Any, path: str | os.PathLike[str], namespace: str = "/") -> list[str]:
    """``rosparam load FILE [NAMESPACE]``: set every value in the file; returns the names set.

    Raises:
        BusError: missing file or invalid YAML (with the line).
    """
    path = Path(path)
    data = load_yaml_file(path, "parameter file", BusError)
    base = _full(namespace).rstrip("/")
    names: list[str] = []

    def walk(prefix: str, value: Any) -> None:
        if isinstance(value, dict) and value:
            for key, child in value.items():
                walk(f"{prefix}/{key}", child)
        else:
            server.set(prefix or "/", value)
            names.append(prefix)

    if data is None:
        return names
    if not isinstance(data, dict):
        if not base:
            raise BusError("a parameter file without a namespace must hold a dict", path=path)
        server.set(base, data)
        return [base]
    walk(base, data)
    return names
