"""``workbench core``: run the parameter server and registry (roscore)."""

from __future__ import annotations

import argparse
import os
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--uri",
        help="where to listen (default: $WORKBENCH_MASTER_URI or tcp/127.0.0.1:11311)",
    )
    parser.add_argument(
        "--allow-remote",
        action="store_true",
        help="allow a non-loopback address, so other machines can connect",
    )
    parser.add_argument(
        "--params", metavar="YAML", help="load parameters from a YAML file at start"
    )


def run(args: argparse.Namespace) -> int:
    return core(uri=args.uri, allow_remote=args.allow_remote, params_file=args.params)


def read_params(path: str) -> dict[str, Any]:
    """The parameter mapping of a YAML file.

    Raises:
        CoreError: The file cannot be read or does not hold a mapping.
    """
    from workbench.bus.errors import CoreError
    from workbench.limits import load_yaml_file

    if not os.path.exists(path):
        raise CoreError("cannot read parameters: no such file", path=path)
    params = load_yaml_file(path, "parameter file", CoreError) or {}
    if not isinstance(params, dict):
        raise CoreError("the parameter file must hold a YAML mapping", path=path)
    return params


def core(
    *, uri: str | None = None, allow_remote: bool = False, params_file: str | None = None
) -> int:
    """Serve the parameter server and registry until interrupted (SIGINT or SIGTERM).

    Args:
        uri: Where to listen (default: ``$WORKBENCH_MASTER_URI`` or ``tcp/127.0.0.1:11311``).
        allow_remote: Allow a non-loopback address.
        params_file: A YAML file of parameters loaded at start.
    """
    from workbench.bus.bus import master_uri
    from workbench.bus.core import Core

    params = read_params(params_file) if params_file else None
    uri = uri or master_uri()
    server = Core(uri, allow_remote=allow_remote, params=params)
    try:
        print(f"started core service [{uri}]", flush=True)
        print(f"nodes find it with WORKBENCH_MASTER_URI={uri} (Ctrl-C to stop)", flush=True)
        server.wait()
    except KeyboardInterrupt:
        pass
    finally:
        server.close()
        print("shutting down core service", flush=True)
    return 0
