"""The core's parameter server as a client sees it: requests over Zenoh, JSON both ways.

Each operation is one query to ``wb/p/<op>`` on the core (see
:mod:`workbench.bus.core`). A refusal comes back as a JSON error and becomes a
:class:`~workbench.bus.params.ParameterError`; silence or anything that is not
JSON (Zenoh's own "timeout") becomes one :class:`~workbench.bus.errors.CoreError`
line naming the core's address.
"""

from __future__ import annotations

import json
from typing import Any

from workbench.bus.errors import CoreError
from workbench.bus.params import ParameterError
from workbench.bus.wire import guarded


class RemoteParams:
    """The core's parameter server, with the same methods as :class:`ParameterServer`."""

    def __init__(self, session: Any, uri: str) -> None:
        self._session = session
        self._uri = uri

    @guarded("a parameter request")
    def _ask(self, op: str, timeout: float = 5.0, **args: Any) -> Any:
        """Send parameter request ``op`` to the core and return its JSON answer.

        Raises:
            ParameterError: The core refused the request (no such parameter, a bound).
            CoreError: The core did not answer in ``timeout`` seconds, or not in JSON.
        """
        replies = self._session.get(f"wb/p/{op}", payload=json.dumps(args), timeout=timeout)
        for reply in replies:
            if reply.ok is not None:
                return self._json(reply.ok.payload.to_bytes(), op)
            text = reply.err.payload.to_bytes()
            try:
                error = json.loads(text)
                message = str(error["message"])
            except (ValueError, TypeError, KeyError):  # Zenoh's own error, e.g. a timeout
                raise self._no_answer(op, timeout, text) from None
            raise ParameterError(message)
        raise self._no_answer(op, timeout, b"")

    def _json(self, data: bytes, op: str) -> Any:
        try:
            return json.loads(data)
        except (ValueError, RecursionError):
            raise CoreError(
                f"the core at {self._uri} sent a garbled answer to parameter request '{op}'",
                hint="is it a workbench core of the same version?",
            ) from None

    def _no_answer(self, op: str, timeout: float, detail: bytes) -> CoreError:
        reason = detail.decode("utf-8", "replace").strip()[:80]
        return CoreError(
            f"the core at {self._uri} did not answer parameter request '{op}' within "
            f"{timeout:g} s" + (f" ({reason})" if reason else ""),
            hint="is 'workbench core' still running, and not overloaded?",
        )

    def set(self, name: str, value: Any) -> None:
        from workbench.bus.params import checked_value

        self._ask("set", name=name, value=checked_value(value, name))

    def get(self, name: str) -> Any:
        return self._ask("get", name=name)

    def has(self, name: str) -> bool:
        return bool(self._ask("has", name=name))

    def delete(self, name: str) -> None:
        self._ask("delete", name=name)

    def names(self) -> list[str]:
        return list(self._ask("names"))

    def search(self, namespace: str, key: str) -> str | None:
        return self._ask("search", namespace=namespace, key=key)

    def snapshot(self) -> dict[str, Any]:
        return self._ask("get", name="/")
