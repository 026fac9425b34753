"""The parameter server: a tree of YAML values addressed by global names.

Semantics follow the ROS 1 master: setting a dict replaces that subtree,
getting a namespace returns it as a dict, ``search`` walks up from the
caller's namespace, and values are YAML types (bool, int, float, str, lists
and dicts of them).
"""

from __future__ import annotations

import copy
import threading
from typing import Any

from workbench.bus.names import InvalidNameError, check_name, join, namespace_of
from workbench.errors import BusError


class ParameterError(BusError, KeyError):
    """A parameter does not exist or has a value that is not a YAML type."""

    def __str__(self) -> str:
        return self.one_line()


def _parts(name: str) -> list[str]:
    if not name.startswith("/"):
        raise InvalidNameError(f"parameter name '{name}' must be resolved to a global name first")
    check_name(name, "parameter name")
    return [p for p in name.split("/") if p]


def plain_value(value: Any, name: str) -> Any:
    """Check a value is a YAML type and return it as plain Python (numpy -> builtins)."""
    if isinstance(value, (bool, int, float, str)):
        return value
    if hasattr(value, "tolist") and not isinstance(value, (list, dict)):  # numpy
        return plain_value(value.tolist(), name)
    if isinstance(value, (list, tuple)):
        return [plain_value(item, name) for item in value]
    if isinstance(value, dict):
        return {str(k): plain_value(v, f"{name}/{k}") for k, v in value.items()}
    if value is None:
        raise ParameterError(f"parameter {name}: None cannot be stored", hint="delete it instead")
    raise ParameterError(
        f"parameter {name}: a {type(value).__name__} is not a YAML value",
        hint="use bool, int, float, str, or lists/dicts of them",
    )


class ParameterServer:
    """A thread-safe parameter tree (the in-process half of ``workbench core``)."""

    def __init__(self) -> None:
        self._tree: dict[str, Any] = {}
        self._lock = threading.RLock()

    def set(self, name: str, value: Any) -> None:
        """Set a parameter; a dict value replaces the whole subtree under ``name``."""
        parts = _parts(name)
        value = plain_value(value, name)
        with self._lock:
            if not parts:
                if not isinstance(value, dict):
                    raise ParameterError("the root parameter '/' can only be set to a dict")
                self._tree = copy.deepcopy(value)
                return
            node = self._tree
            for part in parts[:-1]:
                child = node.get(part)
                if not isinstance(child, dict):
                    child = node[part] = {}
                node = child
            node[parts[-1]] = copy.deepcopy(value)

    def get(self, name: str) -> Any:
        """The value (a copy) at ``name``; a namespace comes back as a dict.

        Raises:
            ParameterError: No such parameter.
        """
        with self._lock:
            node: Any = self._tree
            for part in _parts(name):
                if not isinstance(node, dict) or part not in node:
                    raise ParameterError(f"parameter {name} is not set")
                node = node[part]
            return copy.deepcopy(node)

    def has(self, name: str) -> bool:
        try:
            self.get(name)
        except ParameterError:
            return False
        return True

    def delete(self, name: str) -> None:
        """Delete a parameter or a whole namespace.

        Raises:
            ParameterError: No such parameter.
        """
        parts = _parts(name)
        with self._lock:
            if not parts:
                self._tree = {}
                return
            node: Any = self._tree
            for part in parts[:-1]:
                if not isinstance(node, dict) or part not in node:
                    raise ParameterError(f"parameter {name} is not set")
                node = node[part]
            if not isinstance(node, dict) or parts[-1] not in node:
                raise ParameterError(f"parameter {name} is not set")
            del node[parts[-1]]

    def names(self) -> list[str]:
        """All leaf parameter names, sorted (``rosparam list``)."""
        out: list[str] = []

        def walk(prefix: str, node: Any) -> None:
            if isinstance(node, dict) and node:
                for key, child in node.items():
                    walk(join(prefix, key), child)
            elif prefix != "/":
                out.append(prefix)

        with self._lock:
            walk("/", self._tree)
        return sorted(out)

    def search(self, namespace: str, key: str) -> str | None:
        """Find ``key`` from ``namespace`` upwards; returns the global name or None.

        Args:
            namespace: Where to start (a node's namespace or name, global).
            key: A relative name; its first part is what is looked for.
        """
        check_name(key, "parameter name")
        key = key.lstrip("/~")
        first = key.split("/")[0]
        ns = namespace
        while True:
            if self.has(join(ns, first)):
                return join(ns, key)
            if ns == "/":
                return None
            ns = namespace_of(ns)

    def snapshot(self) -> dict[str, Any]:
        with self._lock:
            return copy.deepcopy(self._tree)
