"""A virtual Arduino board: digital pins, a millisecond clock and a serial port, running a sketch.

:class:`Board` runs a sketch's ``setup()`` once and then ``loop()`` until stopped,
in the calling thread, with the Arduino functions of :mod:`workbench.serial.arduino`
acting on it. Pins behave as an ATmega's: an output pin reads back what was
written; an input pin reads what drives it from outside (:meth:`Board.set_input`:
a button to ground drives it LOW), else HIGH with its pull-up on (``INPUT_PULLUP``,
or ``digitalWrite(pin, HIGH)`` on an input pin, as the manual's button sketch
does), else LOW. Every change of an output pin is reported to ``on_pin_change``.

Between two ``loop()`` calls the board waits up to a millisecond for serial input,
so a sketch whose loop never delays (the manual's button sketch) runs about a
thousand loops a second instead of taking a whole core.
"""

from __future__ import annotations

import threading
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

from workbench.errors import SerialError
from workbench.serial.arduino import HIGH, INPUT_PULLUP, LOW, OUTPUT, set_current_board
from workbench.serial.protocol import FRAME_OVERHEAD, MAX_PAYLOAD

#: Seconds the board waits for serial input between two ``loop()`` calls.
LOOP_PAUSE = 0.001


@dataclass(frozen=True)
class BoardProfile:
    """What the ros_lib NodeHandle of a board gets (rosserial_arduino's ``ros.h``).

    Attributes:
        name: The board's name.
        mcu: Its microcontroller.
        sizes: ``(MAX_SUBSCRIBERS, MAX_PUBLISHERS, INPUT_SIZE, OUTPUT_SIZE)``.
    """

    name: str
    mcu: str
    sizes: tuple[int, int, int, int]


#: Boards by name, with the buffer sizes rosserial_arduino's ``ros.h`` gives their MCU.
PROFILES = {
    "uno": BoardProfile("uno", "ATmega328P", (25, 25, 280, 280)),
    "nano": BoardProfile("nano", "ATmega328P", (25, 25, 280, 280)),
    "mega": BoardProfile("mega", "ATmega2560", (25, 25, 512, 512)),
    "leonardo": BoardProfile("leonardo", "ATmega32U4", (25, 25, 512, 512)),
    "atmega168": BoardProfile("atmega168", "ATmega168", (6, 6, 150, 150)),
}


#: Largest buffer a virtual board takes: a frame of the largest payload with its overhead.
MAX_BUFFER = MAX_PAYLOAD + FRAME_OVERHEAD


def board_profile(name: str, buffer: int | None = None) -> BoardProfile:
    """The profile of board ``name``, its buffers set to ``buffer`` bytes if given.

    Raises:
        SerialError: Unknown board, or a buffer too small for a frame or beyond any frame.
    """
    profile = PROFILES.get(name.lower())
    if profile is None:
        raise SerialError(f"unknown board '{name}'", hint=f"choose one of: {', '.join(PROFILES)}")
    if buffer is None:
        return profile
    if buffer < 16:
        raise SerialError(
            f"a buffer of {buffer} bytes cannot hold a frame", hint="e.g. --buffer 200"
        )
    if buffer > MAX_BUFFER:
        shown = str(buffer) if len(str(buffer)) <= 20 else f"{str(buffer)[:20]}..."
        raise SerialError(
            f"a buffer of {shown} bytes is more than a frame can use ({MAX_BUFFER:,}: "
            "rosserial's 16-bit length plus its header)",
            hint="boards have a few hundred bytes, e.g. --buffer 512",
        )
    subs, pubs, _, _ = profile.sizes
    return BoardProfile(profile.name, profile.mcu, (subs, pubs, buffer, buffer))


class SketchStopped(BaseException):
    """Raised inside a sketch (by ``delay``) when its board is stopped; not an error."""


class SketchError(SerialError):
    """A sketch raised: its error and the sketch line, in one line."""


class Board:
    """A virtual board.

    Args:
        hardware: Its serial port (:class:`~workbench.serial.device.Hardware`).
        profile: Which board (buffer sizes of its NodeHandle).
        on_pin_change: ``on_pin_change(pin, level)`` after an output pin changed.
    """

    def __init__(
        self,
        hardware: Any,
        profile: BoardProfile = PROFILES["uno"],
        on_pin_change: Callable[[int, int], None] | None = None,
    ) -> None:
        self.hardware = hardware
        self.profile = profile
        self.on_pin_change = on_pin_change
        self.stop_event = threading.Event()
        self.modes: dict[int, int] = {}
        self.levels: dict[int, int] = {}
        self.pullups: set[int] = set()
        self.external: dict[int, int] = {}
        self.loops = 0
        self._lock = threading.Lock()

    # --- pins -------------------------------------------------------------------------------

    def pin_mode(self, pin: int, mode: int) -> None:
        with self._lock:
            self.modes[pin] = mode
            if mode == INPUT_PULLUP:
                self.pullups.add(pin)
            elif mode != OUTPUT:
                self.pullups.discard(pin)

    def digital_write(self, pin: int, level: int) -> None:
        with self._lock:
            if self.modes.get(pin) != OUTPUT:
                # on an input pin, HIGH switches the pull-up on (pre-1.0.1 Arduino idiom)
                if level:
                    self.pullups.add(pin)
                else:
                    self.pullups.discard(pin)
                return
            changed = self.levels.get(pin, LOW) != level
            self.levels[pin] = level
        if changed and self.on_pin_change is not None:
            self.on_pin_change(pin, level)

    def digital_read(self, pin: int) -> int:
        with self._lock:
            if self.modes.get(pin) == OUTPUT:
                return self.levels.get(pin, LOW)
            if pin in self.external:
                return self.external[pin]
            return HIGH if pin in self.pullups else LOW

    def set_input(self, pin: int, level: int | None) -> None:
        """Drive input ``pin`` from outside (``None``: let it float, the pull-up decides)."""
        with self._lock:
            if level is None:
                self.external.pop(pin, None)
            else:
                self.external[pin] = HIGH if level else LOW

    def output(self, pin: int) -> int:
        """The level an output pin is driven to (LOW if never written)."""
        with self._lock:
            return self.levels.get(pin, LOW)

    # --- running ----------------------------------------------------------------------------

    def delay(self, ms: float) -> None:
        """Wait ``ms`` milliseconds; raises :class:`SketchStopped` when the board stops."""
        if self.stop_event.wait(max(ms, 0) / 1000.0):
            raise SketchStopped()

    def stop(self) -> None:
        """Ask the running sketch to stop (at its next ``delay`` or ``loop`` return)."""
        self.stop_event.set()

    def run(self, sketch: ModuleType) -> None:
        """Run ``sketch``'s ``setup()`` then ``loop()`` until :meth:`stop`.

        Raises:
            SketchError: The sketch raised (the message names the sketch line).
        """
        set_current_board(self)
        try:
            sketch.setup()
            while not self.stop_event.is_set():
                sketch.loop()
                self.loops += 1
                self.hardware.wait(LOOP_PAUSE)
        except SketchStopped:
            pass
        except Exception as error:
            raise SketchError(
                f"the sketch stopped: {type(error).__name__}: {error}",
                path=_sketch_frame(error, sketch)[0],
                line=_sketch_frame(error, sketch)[1],
            ) from None
        finally:
            set_current_board(None)


def _sketch_frame(error: BaseException, sketch: ModuleType) -> tuple[str | None, int | None]:
    """The sketch file and line where ``error`` left the sketch's own code."""
    path = getattr(sketch, "__file__", None)
    found: tuple[str | None, int | None] = (path, None)
    for frame in traceback.extract_tb(error.__traceback__):
        if path is not None and Path(frame.filename) == Path(path):
            found = (path, frame.lineno)
    return found
