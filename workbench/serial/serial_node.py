"""``rosserial_python/serial_node.py``: the rosserial host node, on a serial port or TCP.

``workbench run rosserial_python serial_node.py /dev/ttyACM0`` (or ``workbench
serial /dev/ttyACM0``) does what ``rosrun rosserial_python serial_node.py
/dev/ttyACM0`` does, with the same lines::

    [INFO] [1645174909.197952]: ROS Serial Python Node
    [INFO] [1645174909.210192]: Connecting to /dev/ttyACM0 at 57600 baud
    [INFO] [1645174911.318304]: Requesting topics...
    [INFO] [1645174911.852129]: Note: publish buffer size is 280 bytes
    [INFO] [1645174911.855289]: Setup publisher on chatter [std_msgs/String]

Arguments as the original's: the port is the first argument or ``_port:=`` (default
``/dev/ttyUSB0``), the baud rate ``_baud:=`` (57600). The port ``tcp`` listens for
Wi-Fi/Ethernet boards on TCP port 11411 (the second argument, ``_tcp_port:=``, or
``/rosserial_embeddedlinux/tcp_port``), on 127.0.0.1 only unless ``_bind:=ADDRESS``
(``workbench serial tcp --bind ADDRESS``) opens it to the network: rosserial_python's
server listens on every interface, so any machine that reaches it could put a
"device" on the bus. Each device that disconnects takes everything it set up on the
bus with it. A port that cannot be opened at start is one
error line naming it and the fix (the ``dialout`` group); a port that goes away
later (a USB cable pulled) is reopened once it comes back, and the device's topics
are requested again. After opening, the node waits 2.1 s for the board's boot loader
as the original does (0.1 s on a pseudo-terminal, a virtual board, which has none).
Ctrl-C or SIGTERM sends TX_STOP to the device before the node exits.
"""

from __future__ import annotations

import ipaddress
import socket
import threading
from collections.abc import Sequence
from typing import Any

from workbench.errors import SerialError
from workbench.serial.bridge import Bridge
from workbench.serial.links import (
    LinkLost,
    SerialPortError,
    SocketLink,
    is_pseudo_terminal,
    open_serial,
)

#: Seconds to wait after opening a board's port: rosserial_python's 0.1 s "patch for Uno"
#: and its 2 s before requesting topics (an Uno's boot loader runs after the DTR reset).
BOOT_WAIT = 2.1
#: The same for a pseudo-terminal or a socket: nothing boots.
PTY_WAIT = 0.1
#: Seconds between attempts to reopen a port that went away.
RETRY = 1.0
DEFAULT_TCP_PORT = 11411
#: Where ``tcp`` mode listens unless told otherwise: this machine only.
DEFAULT_BIND = "127.0.0.1"


def serve_serial(
    node: Any, port: str, baud: int, stop: threading.Event, bridge: Bridge | None = None
) -> None:
    """Bridge the device on ``port`` until ``stop`` is set (or Ctrl-C), reopening it when lost.

    Raises:
        SerialPortError: The port cannot be opened the first time.
    """
    log = node.get_logger()
    bridge = bridge or Bridge(node)
    link = None
    opened_once = reported = False
    try:
        while not stop.is_set():
            if not reported:
                log.info("Connecting to %s at %d baud", port, baud)
            try:
                link = open_serial(port, baud)
            except SerialPortError as error:
                if not opened_once:
                    raise
                if not reported:
                    log.error("Error opening serial: %s", error.one_line())
                    reported = True
                stop.wait(RETRY)
                continue
            opened_once, reported = True, False
            lost = _bridge(bridge, link, stop, PTY_WAIT if is_pseudo_terminal(port) else BOOT_WAIT)
            if lost is not None:
                log.warn("%s; reconnecting", lost.message)
                link = None
                stop.wait(RETRY)
    finally:
        _finish(node, bridge, link)


def _bridge(bridge: Bridge, link: Any, stop: threading.Event, settle: float) -> LinkLost | None:
    """Wait ``settle`` s for the board to boot, then bridge it until ``stop`` or its loss.

    Returns:
        The loss (the link is closed then and detached from the bridge), or None on stop.
    """
    if stop.wait(settle):
        return None
    bridge.attach(link)
    bridge.request_topics()
    try:
        bridge.serve(stop)
    except LinkLost as error:
        bridge.link = None
        link.close()
        return error
    return None


def _finish(node: Any, bridge: Bridge, link: Any) -> None:
    """Say goodbye to the device (TX_STOP) and release the link."""
    if link is not None:
        bridge.stop_device()
        node.get_logger().info("shutdown hook activated")
    bridge.close()
    if link is not None:
        link.close()


def resolve(bind: str, tcp_port: int = 0) -> tuple[Any, ...]:
    """``(family, type, proto, canonname, address)`` to listen on ``bind`` port ``tcp_port``.

    Raises:
        SerialError: ``bind`` is not an address or a known host name.
    """
    try:
        found = socket.getaddrinfo(bind, tcp_port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except (socket.gaierror, UnicodeError, ValueError) as error:
        reason = error.strerror if isinstance(error, OSError) else "not a host name"
        raise SerialError(
            f"cannot listen on {bind[:100]!r}: {reason}",
            hint="give an address of this machine, e.g. --bind 0.0.0.0 for every interface",
        ) from None
    return found[0]


def listen(bind: str, tcp_port: int) -> socket.socket:
    """A TCP socket listening on ``bind`` (an address or a host name) port ``tcp_port``.

    Raises:
        SerialError: The address is unknown or the port cannot be listened on.
    """
    family, kind, proto, _name, address = resolve(bind, tcp_port)
    server = socket.socket(family, kind, proto)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        server.bind(address)
    except OSError as error:
        server.close()
        raise SerialError(
            f"cannot listen on {bind} TCP port {tcp_port}: {error.strerror}",
            hint="is another serial_node in tcp mode running? give another port as the "
            "second argument",
        ) from None
    server.listen(1)
    server.settimeout(0.2)
    return server


def _is_loopback(server: socket.socket) -> bool:
    try:
        return ipaddress.ip_address(server.getsockname()[0]).is_loopback
    except ValueError:
        return False


def serve_tcp(node: Any, tcp_port: int, stop: threading.Event, bind: str = DEFAULT_BIND) -> None:
    """Accept boards on ``bind`` TCP ``tcp_port`` one at a time until ``stop``.

    Everything a board set up on the bus is removed when it disconnects.

    Raises:
        SerialError: The address or TCP port cannot be listened on.
    """
    log = node.get_logger()
    log.info("Fork_server is: %s", False)
    log.info("Waiting for socket connections on port %d", tcp_port)
    server = listen(bind, tcp_port)
    if _is_loopback(server):
        log.info(
            "Listening on %s only: boards on the network cannot connect (give --bind 0.0.0.0, "
            "or _bind:=0.0.0.0, to let them)",
            bind,
        )
    else:
        log.warn(
            "Listening on %s port %d: any machine that reaches it can connect as a device and "
            "publish, subscribe and call services on the bus",
            bind,
            tcp_port,
        )
    bridge = Bridge(node)
    link = None
    try:
        log.info("Waiting for socket connection")
        while not stop.is_set():
            try:
                connection, address = server.accept()
            except TimeoutError:
                continue
            log.info("Established a socket connection from %s on port %s", *address[:2])
            link = SocketLink(connection, f"{address[0]}:{address[1]}")
            log.info("calling startSerialClient")
            lost = _bridge(bridge, link, stop, PTY_WAIT)
            if lost is not None:
                log.info("%s", lost.message)
                log.info("Client has exited, closing socket.")
                bridge.forget_device()
                bridge.close()
                link = None
                log.info("Waiting for socket connection")
    finally:
        _finish(node, bridge, link)
        bridge.forget_device()
        server.close()
        log.info("Shutting down")
        log.info("All done")


class BackgroundHost:
    """The host node on a port, in a background thread (for notebooks and scripts).

    ``host = BackgroundHost("/dev/ttyACM0", bus=bus)`` bridges the board until
    ``host.stop()`` (which sends TX_STOP). Its lines are printed as the node's.

    Args:
        port: The board's port.
        baud: Bits per second.
        bus: The bus of its node (None: the process's default bus).
        name: The node's name.
    """

    def __init__(self, port: str, baud: int = 57600, bus: Any = None, name: str = "serial_node"):
        from workbench.bus import Node

        self.node = Node(name, bus=bus)
        self.bridge = Bridge(self.node)
        self.error: BaseException | None = None
        self._stop = threading.Event()
        self._thread = threading.Thread(
            target=self._run, args=(port, baud), name="serial-host", daemon=True
        )
        self._thread.start()

    def _run(self, port: str, baud: int) -> None:
        try:
            serve_serial(self.node, port, baud, self._stop, self.bridge)
        except BaseException as error:  # handed to the caller by stop()
            self.error = error

    def is_running(self) -> bool:
        return self._thread.is_alive()

    def stop(self, timeout: float = 10.0) -> None:
        """Stop bridging (TX_STOP to the board) and leave the bus.

        Raises:
            SerialPortError: The port could not be opened (or what else stopped the host).
        """
        self._stop.set()
        self._thread.join(timeout)
        self.node.shutdown()
        if self.error is not None:
            error, self.error = self.error, None
            raise error


def parse_target(node: Any, args: Sequence[str]) -> tuple[str, int, int]:
    """``(port, baud, tcp_port)`` from the arguments and private parameters, as the original.

    Raises:
        SerialError: A baud rate or TCP port that is not a number.
    """
    port = str(node.get_param("~port", "/dev/ttyUSB0"))
    baud_text = node.get_param("~baud", 57600)
    if node.has_param("~tcp_port"):
        tcp_text = node.get_param("~tcp_port")
    else:
        tcp_text = node.get_param("/rosserial_embeddedlinux/tcp_port", DEFAULT_TCP_PORT)
    if len(args) >= 1:
        port = args[0]
    if len(args) == 2:
        tcp_text = args[1]
    if len(args) > 2:
        raise SerialError(
            f"serial_node.py takes a port and, for tcp, a TCP port; got {len(args)} arguments",
            hint="e.g. serial_node.py /dev/ttyACM0, or serial_node.py tcp 11411",
        )
    return (
        port,
        _number(baud_text, "baud rate", "_baud:=57600"),
        _number(tcp_text, "TCP port", "serial_node.py tcp 11411", 65535),
    )


def _number(text: Any, what: str, example: str, most: int = 2**31 - 1) -> int:
    shown = str(text)[:40]
    try:
        value = int(str(text)[:100])
    except ValueError:
        raise SerialError(
            f"the {what} must be a whole number, not {shown!r}", hint=example
        ) from None
    if value <= 0:
        raise SerialError(f"the {what} must be positive, not {shown}", hint=example)
    if value > most:
        raise SerialError(f"the {what} must be at most {most}, not {shown}", hint=example)
    return value


def run(
    argv: Sequence[str],
    stop: threading.Event | None = None,
    baud: int | None = None,
    bind: str | None = None,
) -> int:
    """Run the host node with ``argv`` (ROS arguments included) until stopped; exit status.

    Args:
        argv: ``[PORT [TCP_PORT]]`` plus ``_port:=``, ``_baud:=``, ``_bind:=``, remappings ...
        stop: Set it to stop (Ctrl-C and SIGTERM stop it too, in the main thread).
        baud: Overrides ``~baud`` (``workbench serial --baud``).
        bind: Overrides ``~bind``, where ``tcp`` mode listens (``workbench serial --bind``).

    Raises:
        SerialError: Bad arguments, a port that cannot be opened, ``bind`` without ``tcp``.
    """
    from workbench.bus import Node
    from workbench.bus.names import myargv

    stop = stop or threading.Event()
    if bind is not None:
        resolve(bind)  # before the node joins the bus (and takes over a running serial_node)
    node = Node("serial_node", argv=list(argv))
    try:
        node.get_logger().info("ROS Serial Python Node")
        port, param_baud, tcp_port = parse_target(node, myargv(list(argv)))
        if node.get_param("~fork_server", False):
            node.get_logger().warn("fork_server is not supported: one board at a time")
        address = bind if bind is not None else str(node.get_param("~bind", DEFAULT_BIND))
        if port == "tcp":
            serve_tcp(node, tcp_port, stop, address)
        elif bind is not None:
            raise SerialError(
                "--bind is for tcp mode (a board on the network)",
                hint=f"workbench serial tcp --bind {bind[:100]}",
            )
        else:
            serve_serial(node, port, baud or param_baud, stop)
    finally:
        node.shutdown()
    return 0


def main(argv: Sequence[str] = ()) -> int:
    """``rosserial_python/serial_node.py``: the entry point of ``workbench run``."""
    return run(argv)
