"""Reading single key presses from a real terminal (raw mode, no echo)."""

from __future__ import annotations

import os
import select
import sys
from collections.abc import Callable, Sequence
from typing import Any, TextIO

from workbench.errors import WorkbenchError


class NotATerminalError(WorkbenchError):
    """Keyboard teleop was started without a terminal to read keys from."""


class RawTerminal:
    """Put a terminal in raw mode for the ``with`` block and read keys from it.

    Args:
        stream: The terminal (standard input by default).
        raw: Read Ctrl-C as the character ``\x03`` instead of a signal, for the whole block
            (teleop_twist_keyboard reads in raw mode only while waiting for a key, so
            printing stays normal).

    Raises:
        NotATerminalError: ``stream`` is not a terminal (a pipe or a file).
    """

    def __init__(self, stream: TextIO | None = None, *, raw: bool = False) -> None:
        self.stream = stream or sys.stdin
        self.raw = raw
        self.fd = self.stream.fileno()
        if not os.isatty(self.fd):
            raise NotATerminalError(
                "keyboard teleop needs a terminal, but standard input is not one",
                hint="run it in a terminal window, not through a pipe",
            )
        self._saved: list[Any] | None = None

    def __enter__(self) -> RawTerminal:
        import termios
        import tty

        self._saved = termios.tcgetattr(self.fd)
        # no line buffering, no echo; keys typed early are kept
        tty.setcbreak(self.fd, termios.TCSANOW)
        if self.raw:
            # Ctrl-C is a key for the whole block, not only while a read waits: typed while
            # the node prints or publishes, it would otherwise be a signal (exit 130)
            # instead of the key that ends the node (exit 0)
            attributes = termios.tcgetattr(self.fd)
            attributes[3] &= ~termios.ISIG
            termios.tcsetattr(self.fd, termios.TCSANOW, attributes)
        return self

    def __exit__(self, *exc: object) -> None:
        import termios

        if self._saved is not None:
            termios.tcsetattr(self.fd, termios.TCSADRAIN, self._saved)

    def read(self, timeout: float | None) -> str:
        """Characters available within ``timeout`` seconds ("" if none; None waits)."""
        if self.raw:
            import termios
            import tty

            cooked = termios.tcgetattr(self.fd)
            tty.setraw(self.fd, termios.TCSANOW)
            try:
                return self._read(timeout)
            finally:
                termios.tcsetattr(self.fd, termios.TCSADRAIN, cooked)
        return self._read(timeout)

    def _read(self, timeout: float | None) -> str:
        ready, _, _ = select.select([self.fd], [], [], timeout)
        if not ready:
            return ""
        data = os.read(self.fd, 64)
        if not data:
            raise EOFError("the terminal was closed")
        return data.decode(errors="replace")


def run_keyboard_node(
    name: str, argv: Sequence[str] | None, loop: Callable[[Any, RawTerminal], int]
) -> int:
    """Run a keyboard node: the terminal first (no terminal: one clear error before joining
    the bus), then ``loop(node, terminal)``; Ctrl-C is a normal end (exit 0)."""
    from workbench.bus import Node

    terminal = RawTerminal(raw=True)
    node = Node(name, argv=list(argv or []))
    try:
        return loop(node, terminal)
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown()
