"""The Arduino core functions a sketch calls, acting on the virtual board it runs on.

``millis()``, ``delay(ms)``, ``pinMode``, ``digitalWrite``, ``digitalRead`` and the
constants ``HIGH``/``LOW``/``INPUT``/``OUTPUT``/``INPUT_PULLUP``/``LED_BUILTIN``,
named as in the Arduino language so a C++ sketch translates line by line. Each
call goes to the board whose sketch is running in the calling thread (set by
:class:`~workbench.serial.board.Board` while it runs ``setup()`` and ``loop()``).
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

from workbench.errors import SerialError

if TYPE_CHECKING:
    from workbench.serial.board import Board

HIGH = 1
LOW = 0
INPUT = 0
OUTPUT = 1
INPUT_PULLUP = 2
LED_BUILTIN = 13

_local = threading.local()


def current_board() -> Board:
    """The board running the calling thread's sketch.

    Raises:
        SerialError: Called outside a running sketch.
    """
    board = getattr(_local, "board", None)
    if board is None:
        raise SerialError(
            "Arduino functions work only inside a sketch running on a board",
            hint="run the sketch with 'workbench serial virtual SKETCH' "
            "or workbench.serial.virtual.VirtualBoard",
        )
    return board


def set_current_board(board: Board | None) -> None:
    """Make ``board`` the one this thread's Arduino calls act on (None: no board)."""
    _local.board = board


def millis() -> int:
    """Milliseconds since the board started."""
    return current_board().hardware.time()


def delay(ms: float) -> None:
    """Wait ``ms`` milliseconds (the board stops here when asked to)."""
    current_board().delay(ms)


def pinMode(pin: int, mode: int) -> None:  # noqa: N802 - the Arduino name
    current_board().pin_mode(pin, mode)


def digitalWrite(pin: int, value: int | bool) -> None:  # noqa: N802
    current_board().digital_write(pin, int(bool(value)))


def digitalRead(pin: int) -> int:  # noqa: N802
    return current_board().digital_read(pin)
