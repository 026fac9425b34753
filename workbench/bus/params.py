"""The parameter server: a tree of YAML values addressed by global names.

Semantics follow the ROS 1 master: setting a dict replaces that subtree,
getting a namespace returns it as a dict, ``search`` walks up from the
caller's namespace, and values are YAML types (bool, int, float, str, lists
and dicts of them).
"""

from __future__ import annotations

import copy
import json
import threading
from typing import Any

from workbench.bus.names import InvalidNameError, check_name, join, namespace_of
from workbench.errors import BusError
from workbench.limits import MiB, TreeLimits, check_tree, human_bytes, tree_size

#: Bounds on one parameter's value: nesting, elements (lists, dicts and scalars) and text.
VALUE_LIMITS = TreeLimits(max_depth=32, max_nodes=500_000, max_bytes=16 * MiB)
#: Bounds on everything a parameter server holds (``rosparam get /`` sends all of it).
SERVER_LIMITS = TreeLimits(max_depth=32 + 256, max_nodes=2_000_000, max_bytes=64 * MiB)

_MISSING = object()


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
    """Check a value is a YAML type and return it as plain Python (numpy -> builtins).

    Call :func:`checked_value` for values from outside: this one recurses.
    """
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


def checked_value(value: Any, name: str) -> Any:
    """``value`` as plain Python, within :data:`VALUE_LIMITS` (depth, elements, text).

    Raises:
        ParameterError: Not a YAML value, or past a bound (a 3000-deep list, an
            alias bomb's millions of elements).
    """
    what = f"the value of parameter {name}"
    check_tree(value, what, VALUE_LIMITS, ParameterError)
    plain = plain_value(value, name)
    if plain is not value:  # numpy arrays become lists: count what they became
        check_tree(plain, what, VALUE_LIMITS, ParameterError)
    return plain


class ParameterServer:
    """A thread-safe parameter tree (the in-process half of ``workbench core``).

    It holds at most :data:`SERVER_LIMITS` (elements and bytes of text over all
    parameters) and refuses a value past :data:`VALUE_LIMITS`; nothing a client
    sends can make it copy or serialize more than that.
    """

    def __init__(self) -> None:
        self._tree: dict[str, Any] = {}
        self._lock = threading.RLock()
        self._nodes = 1  # tree_size(self._tree), kept up to date
        self._bytes = 0

    def _account(self, removed: Any, added: Any, name: str) -> None:
        """Update the running size for ``removed`` -> ``added``; refuse past the bound."""
        old_nodes, old_bytes = tree_size(removed) if removed is not _MISSING else (0, 0)
        new_nodes, new_bytes = tree_size(added) if added is not _MISSING else (0, 0)
        nodes = self._nodes - old_nodes + new_nodes
        size = self._bytes - old_bytes + new_bytes
        if added is not _MISSING and (
            nodes > SERVER_LIMITS.max_nodes or size > SERVER_LIMITS.max_bytes
        ):
            raise ParameterError(
                f"parameter {name}: the parameter server would hold more than "
                f"{SERVER_LIMITS.max_nodes:,} elements or {human_bytes(SERVER_LIMITS.max_bytes)} "
                f"of text (it holds {self._nodes:,} and {human_bytes(self._bytes)})",
                hint="delete parameters that are no longer needed",
            )
        self._nodes, self._bytes = nodes, size

    def set(self, name: str, value: Any) -> None:
        """Set a parameter; a dict value replaces the whole subtree under ``name``.

        Raises:
            ParameterError: Not a YAML value, past :data:`VALUE_LIMITS`, or the
                server would pass :data:`SERVER_LIMITS`.
        """
        parts = _parts(name)
        value = checked_value(value, name)
        with self._lock:
            if not parts:
                if not isinstance(value, dict):
                    raise ParameterError("the root parameter '/' can only be set to a dict")
                self._account(self._tree, value, name)
                self._tree = value
                return
            node = self._tree
            for depth, part in enumerate(parts[:-1]):
                child = node.get(part, _MISSING)
                if not isinstance(child, dict):
                    # a leaf in the way becomes a namespace, as in ROS
                    self._account(child, {}, join("/", "/".join(parts[: depth + 1])))
                    child = node[part] = {}
                node = child
            self._account(node.get(parts[-1], _MISSING), value, name)
            node[parts[-1]] = value

    def _find(self, name: str) -> Any:
        """The stored value at ``name`` (not a copy; hold the lock)."""
        node: Any = self._tree
        for part in _parts(name):
            if not isinstance(node, dict) or part not in node:
                raise ParameterError(f"parameter {name} is not set")
            node = node[part]
        return node

    def get(self, name: str) -> Any:
        """The value (a copy) at ``name``; a namespace comes back as a dict.

        Raises:
            ParameterError: No such parameter.
        """
        with self._lock:
            return copy.deepcopy(self._find(name))

    def get_json(self, name: str) -> str:
        """The value at ``name`` as JSON text, serialized without copying the tree first.

        Raises:
            ParameterError: No such parameter.
        """
        with self._lock:
            return json.dumps(self._find(name))

    def has(self, name: str) -> bool:
        with self._lock:
            try:
                self._find(name)
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
                self._nodes, self._bytes = 1, 0
                return
            node: Any = self._tree
            for part in parts[:-1]:
                if not isinstance(node, dict) or part not in node:
                    raise ParameterError(f"parameter {name} is not set")
                node = node[part]
            if not isinstance(node, dict) or parts[-1] not in node:
                raise ParameterError(f"parameter {name} is not set")
            self._account(node.pop(parts[-1]), _MISSING, name)

    def names(self) -> list[str]:
        """All leaf parameter names, sorted (``rosparam list``)."""
        out: list[str] = []
        with self._lock:
            stack: list[tuple[str, Any]] = [("/", self._tree)]
            while stack:
                prefix, node = stack.pop()
                if isinstance(node, dict) and node:
                    stack.extend((join(prefix, key), child) for key, child in node.items())
                elif prefix != "/":
                    out.append(prefix)
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
