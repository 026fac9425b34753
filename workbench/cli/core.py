"""``workbench core``: run the parameter server and registry (roscore)."""

from __future__ import annotations

import argparse
import signal


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
    from workbench.bus.bus import master_uri
    from workbench.bus.core import Core
    from workbench.bus.errors import CoreError

    params = None
    if args.params:
        import yaml

        try:
            with open(args.params) as stream:
                params = yaml.safe_load(stream) or {}
        except (OSError, yaml.YAMLError) as error:
            raise CoreError(f"cannot read parameters: {error}", path=args.params) from None
        if not isinstance(params, dict):
            raise CoreError("the parameter file must hold a YAML mapping", path=args.params)
    uri = args.uri or master_uri()
    core = Core(uri, allow_remote=args.allow_remote, params=params)
    signal.signal(signal.SIGTERM, lambda *_: core.close())
    print(f"started core service [{uri}]", flush=True)
    print(f"nodes find it with WORKBENCH_MASTER_URI={uri} (Ctrl-C to stop)", flush=True)
    try:
        core.wait()
    except KeyboardInterrupt:
        pass
    finally:
        core.close()
        print("shutting down core service", flush=True)
    return 0
