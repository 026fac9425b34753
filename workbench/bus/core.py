"""``workbench core``: the router, parameter server and registry of a multi-process graph.

It plays roscore's part. Nodes in other processes connect to it at
``WORKBENCH_MASTER_URI`` (default ``tcp/127.0.0.1:11311``); it routes their
Zenoh traffic, answers parameter requests and hosts the liveliness tokens
that make up the graph (so a node that dies disappears from it).
"""

from __future__ import annotations

import json
import sys
import threading
from typing import Any

from workbench.bus.errors import CoreError
from workbench.bus.params import ParameterError, ParameterServer
from workbench.bus.zconfig import parse_uri, port_open, router_config, zenoh_module
from workbench.errors import WorkbenchError
from workbench.limits import MiB, human_bytes

#: Largest parameter request the core reads (a value of at most 16 MiB of text, as JSON).
MAX_REQUEST_BYTES = 32 * MiB

_LOOPBACK = {"127.0.0.1", "localhost", "::1"}


class Core:
    """A running core (close it with :meth:`close`, or use it as a context manager).

    Args:
        uri: Where to listen (``tcp/127.0.0.1:11311``).
        allow_remote: Allow a non-loopback address (other machines can then connect).
        params: Initial parameters (a dict set at ``/``).

    Raises:
        CoreError: The address is malformed, not loopback without ``allow_remote``, or in use.
    """

    def __init__(
        self, uri: str, allow_remote: bool = False, params: dict[str, Any] | None = None
    ) -> None:
        zenoh = zenoh_module()
        proto, host, port = parse_uri(uri)
        if host not in _LOOPBACK and not allow_remote:
            raise CoreError(
                f"refusing to listen on {host}: the core binds to loopback unless told otherwise",
                hint="pass --allow-remote to accept other machines",
            )
        if proto == "tcp" and port_open(host, port, timeout=0.3):
            raise CoreError(
                f"port {port} on {host} is already in use (another core?)",
                hint="stop it, or pick another port with WORKBENCH_MASTER_URI=tcp/127.0.0.1:PORT",
            )
        try:
            self.session = zenoh.open(router_config(uri))
        except zenoh.ZError as error:
            text = str(error)
            if "in use" in text:
                raise CoreError(
                    f"port {port} on {host} is already in use (another core?)",
                    hint="stop it, or pick another port with WORKBENCH_MASTER_URI",
                ) from None
            raise CoreError(f"cannot start a core at {uri}: {text.split(' at /')[0]}") from None
        self.uri = uri
        self.params = ParameterServer()
        if params:
            for key, value in params.items():
                self.params.set("/" + key.lstrip("/"), value)
        self._queryable = self.session.declare_queryable(
            "wb/p/*", zenoh.handlers.Callback(self._on_param, indirect=False)
        )
        self._token = self.session.liveliness().declare_token("wb/core")
        self._closed = threading.Event()

    def _on_param(self, query: Any) -> None:
        """Answer one parameter request; whatever it holds, the core keeps serving."""
        op = str(query.key_expr).rsplit("/", 1)[-1]
        try:
            reply = self._answer(op, query.payload.to_bytes() if query.payload is not None else b"")
            query.reply(query.key_expr, reply)
        except ParameterError as error:
            query.reply_err(json.dumps({"kind": "missing", "message": error.one_line()}))
        except WorkbenchError as error:
            query.reply_err(json.dumps({"kind": "bad", "message": error.one_line()}))
        except (KeyError, ValueError, TypeError, RecursionError, MemoryError) as error:
            message = f"bad parameter request '{op}': {type(error).__name__}: {error}"
            query.reply_err(json.dumps({"kind": "bad", "message": message[:500]}))

    def _answer(self, op: str, payload: bytes) -> str:
        """The JSON reply to parameter operation ``op`` with JSON arguments ``payload``."""
        if len(payload) > MAX_REQUEST_BYTES:
            raise ParameterError(
                f"a parameter request of {human_bytes(len(payload))} is larger than the "
                f"{human_bytes(MAX_REQUEST_BYTES)} the core accepts",
                hint="keep large data in files, not in parameters",
            )
        args = json.loads(payload) if payload else {}
        if not isinstance(args, dict):
            raise ParameterError(f"parameter request '{op}' is not a JSON object")
        params = self.params
        if op == "get":
            return params.get_json(args["name"])
        result: Any
        if op == "set":
            params.set(args["name"], args["value"])
            result = True
        elif op == "has":
            result = params.has(args["name"])
        elif op == "delete":
            params.delete(args["name"])
            result = True
        elif op == "names":
            result = params.names()
        elif op == "search":
            result = params.search(args["namespace"], args["key"])
        else:
            raise ParameterError(f"unknown parameter operation '{op}'")
        return json.dumps(result)

    def nodes(self) -> list[str]:
        """Names of the nodes currently alive on this core."""
        from workbench.bus.keys import parse_token

        names = []
        for reply in self.session.liveliness().get("wb/g/**", timeout=1.0):
            if reply.ok is not None:
                token = parse_token(str(reply.ok.key_expr))
                if token is not None and token.kind == "n":
                    names.append(token.node)
        return sorted(set(names))

    def wait(self) -> None:
        """Block until :meth:`close` (Ctrl-C raises KeyboardInterrupt here)."""
        while not self._closed.wait(0.2):
            pass

    def close(self) -> None:
        if self._closed.is_set():
            return
        self._closed.set()
        for item in (self._queryable, self._token, self.session):
            try:
                item.undeclare() if item is not self.session else item.close()
            except Exception as error:  # closing goes on; say what did not close cleanly
                print(
                    f"[WARN] core: closing {type(item).__name__}: {type(error).__name__}: {error}",
                    file=sys.stderr,
                    flush=True,
                )

    def __enter__(self) -> Core:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
