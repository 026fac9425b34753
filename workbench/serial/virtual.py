"""A virtual Arduino on a pseudo-terminal: ``workbench serial virtual SKETCH``.

:class:`VirtualBoard` runs a sketch on a :class:`~workbench.serial.board.Board`
whose serial port is the master side of a pseudo-terminal; the other side
(``/dev/pts/N``, printed, or a symlink of your choice with ``--link``) is what a
real board's ``/dev/ttyACM0`` is, so ``workbench serial /dev/pts/N`` talks to it
byte for byte as to the board. Like a UART nobody listens to, the board drops what
it sends while no host reads.

The parts the sketch wires (its ``WIRING``) are there too: a button is pressed and
released from the terminal (Enter) or by publishing ``std_msgs/Bool`` on
``/virtual_arduino/<button>``; every change of an output pin (the motor, the LED)
is printed and published on ``/diagnostics`` (``diagnostic_msgs/DiagnosticArray``,
one status named ``virtual_arduino``, a value per wired part).
"""

from __future__ import annotations

import contextlib
import os
import select
import threading
import time
import tty
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

from workbench.errors import SerialError
from workbench.serial.arduino import HIGH, LOW
from workbench.serial.board import Board, SketchError, board_profile
from workbench.serial.sketch import is_button, load_sketch, wiring

#: Seconds the board's UART waits for a host that does not read before dropping bytes.
WRITE_PATIENCE = 0.05


class PtyHardware:
    """The board's serial port: the master side of a new pseudo-terminal in raw mode."""

    def __init__(self) -> None:
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        os.set_blocking(self.master, False)
        self.path = os.ttyname(self.slave)
        self.dropped = 0
        self._start = time.monotonic()
        self._closed = False

    def read_available(self) -> bytes:
        try:
            return os.read(self.master, 65536)
        except (BlockingIOError, OSError):
            return b""

    def write(self, data: bytes) -> None:
        view = memoryview(data)
        deadline = time.monotonic() + WRITE_PATIENCE
        while view:
            try:
                view = view[os.write(self.master, view) :]
            except BlockingIOError:
                if time.monotonic() > deadline:
                    break
                select.select([], [self.master], [], 0.005)
            except OSError:
                break
        self.dropped += len(view)

    def time(self) -> int:
        """Milliseconds since the board started."""
        return int((time.monotonic() - self._start) * 1000)

    def wait(self, seconds: float) -> None:
        if not self._closed:
            with contextlib.suppress(OSError, ValueError):
                select.select([self.master], [], [], seconds)

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            for fd in (self.master, self.slave):
                with contextlib.suppress(OSError):
                    os.close(fd)


class VirtualBoard:
    """A sketch running on a virtual board behind a pseudo-terminal.

    Args:
        sketch: A shipped sketch's name, a ``.py`` file, or a loaded sketch module.
        board: The board (``uno``, ``mega`` ... : its NodeHandle's buffer sizes).
        buffer: Input and output buffer size in bytes, instead of the board's.
        link: Also make this path a symlink to the pseudo-terminal (``/tmp/ttyACM0``).
        bus: Put the board's parts on this bus (a ``virtual_arduino`` node); None: no node.
        name: The node's name.
        report: Called with a line for every change of a wired part (``print``).

    Raises:
        SerialError: Unknown sketch or board, a sketch that does not load, a bad link path.
    """

    def __init__(
        self,
        sketch: str | ModuleType,
        board: str = "uno",
        buffer: int | None = None,
        link: str | os.PathLike[str] | None = None,
        bus: Any = None,
        name: str = "virtual_arduino",
        report: Callable[[str], None] | None = None,
    ) -> None:
        self.sketch = load_sketch(sketch) if isinstance(sketch, str) else sketch
        self.sketch_name = Path(getattr(self.sketch, "__file__", "sketch")).stem
        self.wiring = wiring(self.sketch)
        self.labels = {pin: part for part, pin in self.wiring.items()}
        self.profile = board_profile(board, buffer)
        self.report = report
        self.hardware = PtyHardware()
        self.board = Board(self.hardware, self.profile, self._pin_changed)
        self.error: SketchError | None = None
        self.link = Path(link) if link is not None else None
        self._thread: threading.Thread | None = None
        self.node: Any = None
        self._diagnostics: Any = None
        try:
            if self.link is not None:
                self._make_link(self.link)
            if bus is not None:
                self._join(bus, name)
        except BaseException:
            self.close()
            raise

    @property
    def path(self) -> str:
        """The port a host opens: the link if one was asked for, else ``/dev/pts/N``."""
        return str(self.link) if self.link is not None else self.hardware.path

    def buttons(self) -> list[str]:
        """The names of the wired buttons."""
        return [part for part in self.wiring if is_button(part)]

    # --- lifetime ---------------------------------------------------------------------------

    def start(self) -> VirtualBoard:
        """Power the board on: run the sketch in a background thread."""
        self._thread = threading.Thread(
            target=self._run, name=f"board-{self.sketch_name}", daemon=True
        )
        self._thread.start()
        return self

    def _run(self) -> None:
        try:
            self.board.run(self.sketch)
        except SketchError as error:
            self.error = error
            if self.report is not None:
                self.report(error.one_line())

    def is_running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def stop(self, timeout: float = 5.0) -> None:
        """Power the board off: stop the sketch, close the pseudo-terminal (the host sees it go)."""
        self.board.stop()
        if self._thread is not None:
            self._thread.join(timeout)
        self.close()

    def close(self) -> None:
        self.hardware.close()
        if self.link is not None and self.link.is_symlink():
            with contextlib.suppress(OSError):
                self.link.unlink()
        if self.node is not None:
            self.node.shutdown()
            self.node = None

    def __enter__(self) -> VirtualBoard:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    # --- the wired parts ----------------------------------------------------------------------

    def press(self, button: str | None = None, pressed: bool = True) -> None:
        """Press (or release) a wired button: it connects its pin to ground.

        Raises:
            SerialError: The sketch wires no button of that name.
        """
        part = self._button(button)
        self.board.set_input(self.wiring[part], LOW if pressed else None)
        if self.report is not None:
            self.report(f"{part} (pin {self.wiring[part]}): {'pressed' if pressed else 'released'}")

    def release(self, button: str | None = None) -> None:
        self.press(button, pressed=False)

    def is_pressed(self, button: str | None = None) -> bool:
        return self.wiring[self._button(button)] in self.board.external

    def toggle(self, button: str | None = None) -> None:
        self.press(button, pressed=not self.is_pressed(button))

    def level(self, part: str | int) -> int:
        """The level of a wired part (``"motor"``) or pin number: HIGH (1) or LOW (0)."""
        pin = self.wiring[part] if isinstance(part, str) else part
        return self.board.output(pin)

    def _button(self, button: str | None) -> str:
        buttons = self.buttons()
        if button is None and buttons:
            return buttons[0]
        if button in buttons:
            return button
        raise SerialError(
            f"the sketch {self.sketch_name} wires no button '{button}'",
            hint=f"its buttons: {', '.join(buttons) or 'none'}",
        )

    def _pin_changed(self, pin: int, level: int) -> None:
        label = self.labels.get(pin, f"pin {pin}")
        if self.report is not None:
            self.report(f"{label} (pin {pin}): {'HIGH' if level == HIGH else 'LOW'}")
        if self._diagnostics is not None:
            self._publish_state()

    # --- on the bus -------------------------------------------------------------------------

    def _join(self, bus: Any, name: str) -> None:
        from workbench.bus import Node
        from workbench.msgs.std_msgs import Bool

        self.node = Node(name, bus=bus)
        self._diagnostics = self.node.create_publisher(
            "/diagnostics", "diagnostic_msgs/DiagnosticArray", queue_size=10
        )
        for part in self.buttons():
            self.node.create_subscription(
                f"~{part}", Bool, lambda msg, part=part: self.press(part, bool(msg.data))
            )

    def _publish_state(self) -> None:
        from workbench.msgs import get_type

        pair = get_type("diagnostic_msgs/KeyValue")
        values = [
            pair(key=f"{part} (pin {pin})", value="HIGH" if self.board.digital_read(pin) else "LOW")
            for part, pin in self.wiring.items()
        ]
        status = get_type("diagnostic_msgs/DiagnosticStatus")(
            level=0,
            name=self.node.base_name,
            message=f"{self.profile.name} running {self.sketch_name}",
            hardware_id=self.hardware.path,
            values=values,
        )
        array = get_type("diagnostic_msgs/DiagnosticArray")(status=[status])
        array.header.stamp = self.node.now()
        self._diagnostics.publish(array)

    def _make_link(self, link: Path) -> None:
        if link.is_symlink():
            link.unlink()  # left by a board that was killed
        elif link.exists():
            raise SerialError(
                f"{link} exists and is not a symlink", hint="choose another --link path"
            )
        try:
            link.symlink_to(self.hardware.path)
        except OSError as error:
            raise SerialError(f"cannot create the link {link}: {error.strerror}") from None


def watch_terminal(board: VirtualBoard, stream: Any) -> threading.Thread:
    """Toggle a button for each line read from ``stream`` (an empty line: the first button).

    Runs in a daemon thread until the stream ends.
    """

    def read() -> None:
        for line in stream:
            word = line.strip()
            try:
                board.toggle(word or None)
            except SerialError as error:
                print(error.one_line(), flush=True)

    thread = threading.Thread(target=read, name="board-terminal", daemon=True)
    thread.start()
    return thread
