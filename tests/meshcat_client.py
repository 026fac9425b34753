"""A stand-in for the browser showing a Meshcat page: it joins the page's websocket and sends
what the control panel sends when a slider moves or a button is pressed (MessagePack maps, as
Meshcat's JavaScript writes them), so a test can press RViz's "2D Nav Goal" in another process.

Importable by name from any test folder (``from meshcat_client import MeshcatPanel``).
"""

from __future__ import annotations

import base64
import contextlib
import os
import socket
import struct
import threading
from urllib.parse import urlparse


def msgpack(value) -> bytes:
    """MessagePack of a dict of short strings and floats (what Meshcat's browser sends)."""
    if isinstance(value, dict):
        return bytes([0x80 | len(value)]) + b"".join(
            msgpack(k) + msgpack(v) for k, v in value.items()
        )
    if isinstance(value, str):
        data = value.encode()
        return (bytes([0xA0 | len(data)]) if len(data) < 32 else bytes([0xD9, len(data)])) + data
    return b"\xcb" + struct.pack(">d", float(value))


class MeshcatPanel:
    """Meshcat's control panel seen from a browser at ``url`` (``http://127.0.0.1:7000``).

    What the server sends (the scene) is read and dropped by a thread, as a browser would
    read it, so the server never waits on this client.
    """

    def __init__(self, url: str, timeout: float = 10.0) -> None:
        parsed = urlparse(url)
        self._sock = socket.create_connection((parsed.hostname, parsed.port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        self._sock.sendall(
            (
                f"GET / HTTP/1.1\r\nHost: {parsed.hostname}:{parsed.port}\r\n"
                "Upgrade: websocket\r\nConnection: Upgrade\r\n"
                f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n"
            ).encode()
        )
        reply = b""
        while b"\r\n\r\n" not in reply:
            chunk = self._sock.recv(4096)
            if not chunk:
                break
            reply += chunk
        if b" 101 " not in reply.split(b"\r\n", 1)[0]:
            raise ConnectionError(f"no websocket at {url}: {reply[:80]!r}")
        self._sock.settimeout(None)
        self._reader = threading.Thread(target=self._drain, daemon=True)
        self._reader.start()

    def _drain(self) -> None:
        try:
            while self._sock.recv(1 << 16):
                pass
        except OSError:
            pass

    def _send(self, payload: bytes) -> None:
        """One masked binary frame, as a browser sends it (RFC 6455)."""
        mask = os.urandom(4)
        size = len(payload)
        if size < 126:
            header = bytes([0x82, 0x80 | size])
        elif size < 1 << 16:
            header = bytes([0x82, 0x80 | 126]) + struct.pack(">H", size)
        else:
            header = bytes([0x82, 0x80 | 127]) + struct.pack(">Q", size)
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
        self._sock.sendall(header + mask + masked)

    def set_slider(self, name: str, value: float) -> None:
        """Move slider ``name`` to ``value``."""
        self._send(msgpack({"type": "slider", "name": name, "value": value}))

    def press(self, name: str) -> None:
        """Press button ``name``."""
        self._send(msgpack({"type": "button", "name": name}))

    def close(self) -> None:
        with contextlib.suppress(OSError):
            self._sock.sendall(bytes([0x88, 0x80]) + os.urandom(4))  # close frame, masked
        self._sock.close()

    def __enter__(self) -> MeshcatPanel:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
