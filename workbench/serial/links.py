"""The byte pipes a rosserial host talks over: a serial port (pyserial) or a TCP socket.

A link reads whatever bytes have arrived (:meth:`SerialLink.read_some`), writes
whole frames, drops unread input, and raises :class:`LinkLost` once the other end
is gone (a USB cable pulled, a virtual board stopped, a socket closed), so the
host can reconnect. :func:`open_serial` opens a port as rosserial_python does,
but says in one line what is wrong with a port that cannot be opened (missing,
busy, not permitted, not a serial port) and what to do.

Opening resets the board the way the Arduino IDE does (DTR low, then high: an
Uno reboots into its sketch); a port without modem-control lines (a pseudo-terminal,
a Bluetooth or USB-CDC bridge that refuses the ioctl) is simply not reset.
"""

from __future__ import annotations

import contextlib
import errno
import os
import socket
import time
from typing import Any

from workbench.errors import SerialError
from workbench.optional import require

#: How long a read waits for the first byte, in seconds (the host's loop checks its
#: stop flag and watchdog this often).
READ_WAIT = 0.05
#: Seconds DTR is held low to reset a board.
RESET_PULSE = 0.05

_DIALOUT = (
    "on Linux, add yourself to the dialout group ('sudo usermod -a -G dialout $USER', "
    "then log out and back in)"
)


class SerialPortError(SerialError):
    """A serial port cannot be opened: missing, busy, not permitted or not a serial port."""


class LinkLost(SerialError):
    """The other end of a link went away (unplugged, closed); the host may reconnect."""


def port_error(port: str, error: BaseException) -> SerialPortError:
    """The one-line error for ``port`` that pyserial (or the OS) refused with ``error``."""
    code = getattr(error, "errno", None)
    text = str(error)
    if code in (errno.ENOENT, errno.ENODEV, errno.ENXIO) or "No such file" in text:
        return SerialPortError(
            f"serial port {port} does not exist",
            hint="is the board plugged in? 'ls /dev/ttyACM* /dev/ttyUSB*' lists the serial "
            f"ports; if it is there but may not be opened: {_DIALOUT}",
        )
    if code in (errno.EACCES, errno.EPERM) or "Permission denied" in text:
        return SerialPortError(f"permission denied on serial port {port}", hint=_DIALOUT)
    if code == errno.EBUSY or "exclusively lock" in text or "busy" in text.lower():
        return SerialPortError(
            f"serial port {port} is busy: another program has it open",
            hint="close the Arduino IDE's Serial Monitor or the other serial node; if you "
            f"may not open it: {_DIALOUT}",
        )
    if code in (errno.ENOTTY, errno.EISDIR) or "configure port" in text:
        return SerialPortError(
            f"{port} is not a serial port",
            hint="give the board's port, e.g. /dev/ttyACM0 or /dev/ttyUSB0",
        )
    reason = os.strerror(code) if isinstance(code, int) else text
    return SerialPortError(f"cannot open serial port {port}: {reason}", hint=_DIALOUT)


class SerialLink:
    """A pyserial port as a link.

    Args:
        port: An open ``serial.Serial`` (or a ``serial_for_url`` port such as ``loop://``)
            whose timeout is the first-byte wait of :meth:`read_some`.
        name: The port's name, for messages.
    """

    def __init__(self, port: Any, name: str) -> None:
        self.port = port
        self.name = name
        self._lost = require("serial").SerialException

    def read_some(self) -> bytes:
        """The bytes that have arrived, waiting up to the port's timeout for the first one.

        Raises:
            LinkLost: The port went away.
        """
        port = self.port
        try:
            waiting = port.in_waiting
            if waiting:
                return bytes(port.read(waiting))
            first = port.read(1)
            if not first:
                return b""
            waiting = port.in_waiting
            return bytes(first) + bytes(port.read(waiting)) if waiting else bytes(first)
        except (self._lost, OSError, TypeError, AttributeError) as error:
            # pyserial reports a vanished device as SerialException or OSError (and a port
            # closed under it as TypeError/AttributeError on its cleared file descriptor)
            raise LinkLost(f"serial port {self.name} went away: {error}") from None

    def write(self, data: bytes) -> None:
        """Write ``data`` entirely (raises :class:`LinkLost` when the port went away)."""
        try:
            self.port.write(data)
        except (self._lost, OSError, TypeError, AttributeError) as error:
            raise LinkLost(f"serial port {self.name} went away: {error}") from None

    def discard_input(self) -> None:
        """Drop the bytes received and not read yet."""
        try:
            self.port.reset_input_buffer()
        except (self._lost, OSError, TypeError, AttributeError) as error:
            raise LinkLost(f"serial port {self.name} went away: {error}") from None

    def close(self) -> None:
        with contextlib.suppress(self._lost, OSError):
            self.port.close()


def open_serial(port: str, baud: int = 57600, reset: bool = True) -> SerialLink:
    """Open ``port`` (a device path or a pyserial URL such as ``loop://``) at ``baud``.

    Args:
        port: ``/dev/ttyACM0``, ``/dev/pts/3``, ``COM3``, ``loop://`` ...
        baud: Bits per second (57600, as ros_lib's ArduinoHardware).
        reset: Pulse DTR to restart the board (skipped on ports that have no DTR).

    Raises:
        SerialPortError: The port is missing, busy, not permitted or not a serial port.
        MissingDependencyError: pyserial is not installed.
    """
    serial = require("serial")
    try:
        if "://" in port:
            handle = serial.serial_for_url(port, baudrate=baud, timeout=READ_WAIT, write_timeout=10)
        else:
            handle = serial.Serial(port, baud, timeout=READ_WAIT, write_timeout=10, exclusive=True)
    except (serial.SerialException, OSError, ValueError, OverflowError) as error:
        raise port_error(port, error) from None
    if reset:
        reset_board(handle)
    return SerialLink(handle, port)


def reset_board(handle: Any) -> bool:
    """Restart a board through DTR, as the Arduino IDE does; False if the port has no DTR."""
    try:
        handle.dtr = False
        time.sleep(RESET_PULSE)
        handle.dtr = True
    except (OSError, ValueError, AttributeError, require("serial").SerialException):
        return False  # a pseudo-terminal or a bridge without modem-control lines
    return True


def is_pseudo_terminal(port: str) -> bool:
    """Whether ``port`` is a pseudo-terminal (a virtual board): no boot loader to wait for."""
    try:
        real = os.path.realpath(port)
    except (OSError, ValueError):
        return False
    return real.startswith("/dev/pts/") or "://" in port


class SocketLink:
    """A connected TCP socket as a link (rosserial's ``tcp`` mode, Wi-Fi boards).

    Args:
        sock: The accepted connection.
        name: ``host:port`` of the board, for messages.
    """

    def __init__(self, sock: socket.socket, name: str) -> None:
        self.sock = sock
        self.name = name
        sock.settimeout(READ_WAIT)
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def read_some(self) -> bytes:
        try:
            data = self.sock.recv(65536)
        except TimeoutError:
            return b""
        except OSError as error:
            raise LinkLost(f"connection from {self.name} broke: {error}") from None
        if not data:
            raise LinkLost(f"connection from {self.name} closed")
        return data

    def write(self, data: bytes) -> None:
        try:
            self.sock.sendall(data)
        except OSError as error:
            raise LinkLost(f"connection from {self.name} broke: {error}") from None

    def discard_input(self) -> None:
        """Drop what has arrived and not been read yet."""
        self.sock.setblocking(False)
        try:
            while self.sock.recv(65536):
                pass
        except OSError:
            pass
        finally:
            self.sock.settimeout(READ_WAIT)

    def close(self) -> None:
        with contextlib.suppress(OSError):
            self.sock.close()
