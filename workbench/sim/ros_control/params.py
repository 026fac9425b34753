"""A parameter namespace on the bus, read as a ``ros::NodeHandle`` reads it."""

from __future__ import annotations

from typing import Any

from workbench.bus.names import join

_UNSET: Any = object()


class ParamView:
    """The parameters under ``namespace`` (global), e.g. ``/arm_controller``.

    Args:
        params: The bus's parameter server (``node.bus.params``), or None: nothing is set.
        namespace: A global namespace.
    """

    def __init__(self, params: Any, namespace: str) -> None:
        self.params = params
        self.namespace = "/" + namespace.strip("/") if namespace.strip("/") else "/"

    def name(self, key: str) -> str:
        """The global name of ``key`` (a relative name) in this namespace."""
        return join(self.namespace, key.strip("/")) if key.strip("/") else self.namespace

    def has(self, key: str) -> bool:
        return self.params is not None and bool(self.params.has(self.name(key)))

    def get(self, key: str, default: Any = _UNSET) -> Any:
        """The value at ``key``; ``default`` when it is not set (KeyError without a default)."""
        if self.params is None or not self.params.has(self.name(key)):
            if default is _UNSET:
                raise KeyError(self.name(key))
            return default
        return self.params.get(self.name(key))

    def child(self, key: str) -> ParamView:
        """The namespace ``key`` under this one."""
        return ParamView(self.params, self.name(key))

    def search(self, key: str) -> str | None:
        """The global name of the closest ``key`` from this namespace upwards (``searchParam``)."""
        if self.params is None:
            return None
        found = self.params.search(self.namespace, key)
        return str(found) if found is not None else None
