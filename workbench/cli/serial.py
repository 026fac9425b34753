"""``workbench serial``: rosserial, an Arduino on the bus (Experiment 11).

* ``workbench serial [PORT] [--baud 57600]``: the host node, as ``rosrun
  rosserial_python serial_node.py PORT`` (``_port:=``/``_baud:=`` work too);
* ``workbench serial tcp [TCP_PORT] [--bind ADDRESS]``: the host for Wi-Fi/Ethernet boards
  (11411, on 127.0.0.1 unless ``--bind`` opens it to the network);
* ``workbench serial virtual SKETCH``: a virtual board on a pseudo-terminal;
* ``workbench serial make-libraries DIR``: ros_lib's message headers for the Arduino IDE.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence


def configure(parser: argparse.ArgumentParser) -> None:
    parser.usage = (
        "workbench serial [PORT | tcp [TCP_PORT] [--bind ADDRESS]] [--baud BAUD] "
        "[NAME:=VALUE ...]\n"
        "       workbench serial virtual SKETCH [--board BOARD] [--buffer BYTES] [--link PATH]\n"
        "       workbench serial make-libraries DIR"
    )
    parser.add_argument(
        "target",
        nargs="?",
        help="the board's port (/dev/ttyACM0, default ~port or /dev/ttyUSB0), 'tcp', "
        "'virtual' or 'make-libraries'",
    )
    parser.add_argument(
        "rest",
        nargs="*",
        metavar="ARG",
        help="tcp: the TCP port; virtual: the sketch; make-libraries: the folder; "
        "and ROS arguments (_baud:=115200, chatter:=/x)",
    )
    parser.add_argument("--baud", type=int, help="bits per second (default ~baud or 57600)")
    parser.add_argument(
        "--bind",
        metavar="ADDRESS",
        help="tcp: the address to listen on (default ~bind or 127.0.0.1, this machine only); "
        "0.0.0.0 lets any machine on the network connect as a device and use the bus",
    )
    virtual = parser.add_argument_group("virtual board")
    virtual.add_argument("--board", default="uno", help="uno (280-byte buffers), mega (512) ...")
    virtual.add_argument("--buffer", type=int, help="input and output buffer size in bytes")
    virtual.add_argument("--link", help="also make this path a symlink to the board's port")
    virtual.add_argument("--name", default="virtual_arduino", help="its node on the bus")
    virtual.add_argument(
        "--no-bus", action="store_true", help="do not put the board's button and pins on the bus"
    )
    virtual.add_argument("--list", action="store_true", help="list the shipped sketches")
    parser.epilog = (
        "Ctrl-C or SIGTERM stops the host (which sends TX_STOP to the board) or the virtual board."
    )


def run(args: argparse.Namespace) -> int:
    if args.list:
        from workbench.serial.sketch import list_sketches

        print("\n".join(list_sketches()))
        return 0
    if args.target == "virtual":
        return virtual(
            args.rest,
            board=args.board,
            buffer=args.buffer,
            link=args.link,
            name=args.name,
            use_bus=not args.no_bus,
        )
    if args.target == "make-libraries":
        return make_libraries(args.rest)
    argv = ([args.target] if args.target else []) + list(args.rest)
    return host(argv, baud=args.baud, bind=args.bind)


def host(argv: Sequence[str], baud: int | None = None, bind: str | None = None) -> int:
    """Run the rosserial host node (``serial_node.py``) with ``argv`` until interrupted."""
    from workbench.errors import SerialError
    from workbench.serial.serial_node import run as run_node

    if baud is not None and not 0 < baud < 2**31:
        raise SerialError(
            f"--baud must be a positive 32-bit number, not {str(baud)[:40]}",
            hint="e.g. --baud 57600",
        )
    if bind is not None and (not argv or argv[0] != "tcp"):
        raise SerialError(
            "--bind is for tcp mode (a board on the network)",
            hint=f"workbench serial tcp --bind {bind[:100]}",
        )
    return run_node(list(argv), baud=baud, bind=bind)


def make_libraries(argv: Sequence[str]) -> int:
    """``rosrun rosserial_arduino make_libraries.py DIR``: write ros_lib for the Arduino IDE."""
    import importlib
    import importlib.util

    from workbench.errors import SerialError

    if importlib.util.find_spec("workbench.serial.make_libraries") is None:
        raise SerialError(
            "make-libraries is not part of this installation",
            hint="update workbench; the Arduino IDE's Library Manager also has 'Rosserial Arduino Library'",
        )
    module = importlib.import_module("workbench.serial.make_libraries")
    return int(module.main(list(argv)) or 0)


def virtual(
    argv: Sequence[str],
    board: str = "uno",
    buffer: int | None = None,
    link: str | None = None,
    name: str = "virtual_arduino",
    use_bus: bool = True,
) -> int:
    """Run a sketch on a virtual board until interrupted; print its port for the host.

    Raises:
        SerialError: No sketch, several, an unknown one, or one that fails.
    """
    import time

    from workbench.errors import SerialError
    from workbench.serial.virtual import VirtualBoard, watch_terminal

    if len(argv) != 1:
        raise SerialError(
            "give one sketch to run",
            hint="e.g. workbench serial virtual hello_world ('--list' lists the sketches)",
        )
    bus = None
    if use_bus:
        from workbench.bus import Bus

        bus = Bus.auto(quiet=True)

    def say(line: str) -> None:
        print(line, flush=True)

    board_ = VirtualBoard(argv[0], board, buffer, link, bus, name, report=say)
    profile = board_.profile
    say(
        f"virtual {profile.name} ({profile.mcu}, {profile.sizes[2]}-byte buffers) running "
        f"{board_.sketch_name} on {board_.hardware.path}"
    )
    say(f"connect with: workbench serial {board_.path}")
    if board_.buttons():
        topic = f"/{name}/{board_.buttons()[0]}" if use_bus else None
        say(
            f"press Enter to press or release the {board_.buttons()[0]}"
            + (f" (or publish std_msgs/Bool on {topic})" if topic else "")
        )
    board_.start()
    if board_.buttons():
        watch_terminal(board_, sys.stdin)
    try:
        while board_.is_running():
            time.sleep(0.1)
    finally:
        board_.stop()
        if bus is not None:
            bus.shutdown()
    if board_.error is not None:
        raise board_.error
    return 0
