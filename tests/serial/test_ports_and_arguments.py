"""Opening ports (errors, boards without DTR, a vanished port) and serial_node.py's arguments."""

from __future__ import annotations

import errno
import os
import tty

import pytest

from workbench.bus import Bus, Node
from workbench.errors import SerialError
from workbench.serial.links import LinkLost, open_serial, port_error, reset_board
from workbench.serial.serial_node import parse_target

serial = pytest.importorskip("serial")


@pytest.mark.parametrize(
    "error,expected",
    [
        (
            serial.SerialException(errno.ENOENT, "could not open port"),
            "serial port /dev/ttyACM0 does not exist",
        ),
        (
            serial.SerialException(errno.EACCES, "could not open port"),
            "permission denied on serial port /dev/ttyACM0",
        ),
        (
            serial.SerialException(errno.EBUSY, "could not open port"),
            "serial port /dev/ttyACM0 is busy",
        ),
        (
            serial.SerialException("Could not exclusively lock port /dev/ttyACM0"),
            "serial port /dev/ttyACM0 is busy",
        ),
        (
            serial.SerialException("Could not configure port: (25, 'x')"),
            "/dev/ttyACM0 is not a serial port",
        ),
        (
            serial.SerialException(errno.EIO, "could not open port"),
            "cannot open serial port /dev/ttyACM0: Input/output error",
        ),
    ],
)
def test_each_refusal_is_one_line_with_the_fix(error, expected):
    text = port_error("/dev/ttyACM0", error).one_line()
    assert text.startswith(expected)
    assert "\n" not in text
    if "not a serial port" not in expected:
        assert "sudo usermod -a -G dialout $USER" in text


def test_a_pseudo_terminal_opens_without_dtr_and_its_loss_is_seen():
    master, slave = os.openpty()
    tty.setraw(slave)
    try:
        link = open_serial(os.ttyname(slave))  # resetting through DTR is skipped, not an error
        assert reset_board(link.port) is False
        os.write(master, b"\xff\xfe")
        assert link.read_some() == b"\xff\xfe"
        link.write(b"\x01")
        assert os.read(master, 1) == b"\x01"
    finally:
        os.close(master)
        os.close(slave)
    with pytest.raises(LinkLost, match="went away"):
        for _ in range(100):  # the board is gone: reads fail (at once, or after a timeout)
            link.read_some()
    link.close()


def _target(*argv: str) -> tuple[str, int, int]:
    bus = Bus(threaded=False)
    try:
        node = Node("serial_node", bus=bus, argv=list(argv))
        from workbench.bus.names import myargv

        return parse_target(node, myargv(list(argv)))
    finally:
        bus.shutdown()


def test_arguments_and_private_parameters_as_the_original():
    assert _target() == ("/dev/ttyUSB0", 57600, 11411)
    assert _target("/dev/ttyACM0") == ("/dev/ttyACM0", 57600, 11411)
    assert _target("_port:=/dev/ttyACM1", "_baud:=115200") == ("/dev/ttyACM1", 115200, 11411)
    assert _target("/dev/ttyACM0", "_port:=/dev/ttyACM1") == ("/dev/ttyACM0", 57600, 11411)
    assert _target("tcp", "11412") == ("tcp", 57600, 11412)
    assert _target("tcp", "_tcp_port:=11500") == ("tcp", 57600, 11500)


def test_bad_arguments_are_one_line():
    with pytest.raises(SerialError, match="the baud rate must be a whole number, not 'fast'"):
        _target("/dev/ttyACM0", "_baud:=fast")
    with pytest.raises(SerialError, match="the TCP port must be a whole number"):
        _target("tcp", "eleven")
    with pytest.raises(SerialError, match="takes a port and, for tcp, a TCP port; got 3 arguments"):
        _target("a", "b", "c")
