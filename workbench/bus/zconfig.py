"""Zenoh session configuration for cores (routers) and nodes (clients).

Multicast scouting is off: a node talks only to the core at its URI, so
several cores (tests, labs) on one machine never mix.
"""

from __future__ import annotations

import json
import re
import socket

from workbench.bus.errors import CoreError
from workbench.optional import require

_URI_RE = re.compile(r"^(tcp|udp|quic|tls)/(\[[0-9a-fA-F:]+\]|[A-Za-z0-9_.\-]+):(\d+)$")


def zenoh_module():
    """Import eclipse-zenoh (the ``zenoh`` extra)."""
    return require("zenoh")


def parse_uri(uri: str) -> tuple[str, str, int]:
    """``tcp/127.0.0.1:11311`` -> (``tcp``, ``127.0.0.1``, 11311).

    Raises:
        CoreError: Not of the form ``proto/host:port``.
    """
    match = _URI_RE.match(uri.strip())
    if not match or not 0 < int(match.group(3)) < 65536:
        raise CoreError(
            f"'{uri}' is not a core address",
            hint="write it as tcp/HOST:PORT, e.g. tcp/127.0.0.1:11311 (WORKBENCH_MASTER_URI)",
        )
    return match.group(1), match.group(2).strip("[]"), int(match.group(3))


def port_open(host: str, port: int, timeout: float = 0.5) -> bool:
    """Whether something accepts TCP connections at ``host:port``."""
    try:
        with socket.create_connection((host, port), timeout=timeout):
            return True
    except OSError:
        return False


#: Microseconds a message that must not be dropped may wait for room in a link's queue
#: before Zenoh gives up and closes the link (losing what is queued). Zenoh's default, 5 s,
#: is shorter than a subscriber on a busy 2-core machine can stall; dead peers are still
#: found by the lease (10 s).
BLOCK_WAIT_BEFORE_CLOSE_US = 120_000_000


def _lossless(config):
    config.insert_json5(
        "transport/link/tx/queue/congestion_control/block/wait_before_close",
        str(BLOCK_WAIT_BEFORE_CLOSE_US),
    )
    return config


def client_config(uri: str):
    zenoh = zenoh_module()
    config = zenoh.Config()
    config.insert_json5("mode", '"client"')
    config.insert_json5("connect/endpoints", json.dumps([uri]))
    config.insert_json5("scouting/multicast/enabled", "false")
    return _lossless(config)


def router_config(uri: str):
    zenoh = zenoh_module()
    config = zenoh.Config()
    config.insert_json5("mode", '"router"')
    config.insert_json5("listen/endpoints", json.dumps([uri]))
    config.insert_json5("connect/endpoints", "[]")
    config.insert_json5("scouting/multicast/enabled", "false")
    config.insert_json5("scouting/gossip/enabled", "false")
    return _lossless(config)
