"""A rosserial TCP host in a thread and a device that connects to it, for the serial tests.

Importable by name from the serial tests (``from tcp_host_helpers import tcp_host``).
"""

from __future__ import annotations

import contextlib
import socket
import threading

from process_helpers import wait_for
from rosserial_bytes import REQUEST_TOPICS

from workbench.bus import Node
from workbench.serial.serial_node import DEFAULT_BIND, serve_tcp

#: Seconds any wait of these tests may take on a loaded machine.
WAIT = 60.0


class Lines:
    """The host's log lines, for the test to look at (they are printed as well)."""

    def __init__(self, logger) -> None:
        self.lines: list[str] = []
        original = logger.log

        def log(level, text, *args):
            self.lines.append(str(text) % args if args else str(text))
            original(level, text, *args)

        logger.log = log

    def having(self, text: str) -> list[str]:
        return [line for line in list(self.lines) if text in line]


@contextlib.contextmanager
def tcp_host(bus, bind: str = DEFAULT_BIND):
    """``serve_tcp`` on a free port in a thread; yields ``(port, log lines)``."""
    node = Node("serial_node", bus=bus)
    lines = Lines(node.get_logger())
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    stop = threading.Event()
    errors: list[BaseException] = []

    def serve() -> None:
        try:
            serve_tcp(node, port, stop, bind)
        except BaseException as error:  # handed to the test below
            errors.append(error)

    thread = threading.Thread(target=serve, name="test-tcp-host", daemon=True)
    thread.start()
    try:
        assert wait_for(lambda: "Waiting for socket connection" in lines.lines or errors, WAIT)
        assert not errors, errors
        yield port, lines
    finally:
        stop.set()
        thread.join(WAIT)
        node.shutdown()
    assert not thread.is_alive()
    assert not errors, errors


def connect(port: int, address: str = "127.0.0.1") -> socket.socket:
    board = socket.create_connection((address, port), timeout=WAIT)
    received = b""
    while REQUEST_TOPICS not in received:
        chunk = board.recv(4096)
        assert chunk, "the host closed the connection"
        received += chunk
    return board
