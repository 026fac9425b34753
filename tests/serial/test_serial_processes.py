"""Experiment 11 as the manual runs it, in separate processes around a private core.

* program A: ``workbench serial virtual hello_world`` (a board on a pseudo-terminal),
  ``workbench run rosserial_python serial_node.py PORT`` prints the manual's lines, and
  ``workbench topic echo chatter`` shows ``data: "hello world!"``;
* program B: the button pressed from the board's terminal is published as ``pushed``;
* the host stops on SIGTERM and SIGINT after sending TX_STOP to a device the test plays
  byte by byte; in ``tcp`` mode it serves a board that connects on a TCP port;
* a port that is missing, busy or not a serial port is one error line naming it.
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import sys
import tty

import pytest
from process_helpers import core_processes, free_port, wait_for
from rosserial_bytes import REQUEST_TOPICS, TX_STOP, frame, string, topic_info

pytestmark = pytest.mark.multiprocess

WAIT = 30.0


@pytest.fixture
def procs(tmp_path):
    with core_processes(tmp_path) as processes:
        yield processes


def messages(text: str) -> list[str]:
    """The text of each ``[LEVEL] [time]: text`` line."""
    return [line.split("]: ", 1)[1] for line in text.splitlines() if "]: " in line]


def test_program_a_hello_world(procs, tmp_path):
    port = tmp_path / "ttyACM0"
    board = procs.start(
        "-m",
        "workbench",
        "serial",
        "virtual",
        "hello_world",
        "--buffer",
        "200",
        "--link",
        str(port),
        name="board",
    )
    procs.wait_output(board, "connect with: workbench serial")
    host = procs.start(
        "-m", "workbench", "run", "rosserial_python", "serial_node.py", str(port), name="host"
    )
    echo = procs.start("-m", "workbench", "topic", "echo", "chatter", name="echo")
    procs.wait_output(echo, 'data: "hello world!"', WAIT)
    out = procs.output(host)
    assert messages(out)[:5] == [
        "ROS Serial Python Node",
        f"Connecting to {port} at 57600 baud",
        "Requesting topics...",
        "Note: publish buffer size is 200 bytes",
        "Setup publisher on chatter [std_msgs/String]",
    ]
    host.send_signal(signal.SIGTERM)
    assert host.wait(WAIT) == 143
    assert "Sending tx stop request" in procs.output(host)


def test_program_b_button_and_motor(procs, tmp_path):
    port = tmp_path / "ttyACM0"
    log = open(tmp_path / "board.log", "wb")  # noqa: SIM115 - closed below
    board = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "workbench",
            "serial",
            "virtual",
            "button_motor",
            "--link",
            str(port),
        ],
        stdin=subprocess.PIPE,
        stdout=log,
        stderr=subprocess.STDOUT,
        env=procs.env(),
    )
    try:
        assert wait_for(lambda: port.is_symlink(), WAIT)
        host = procs.start("-m", "workbench", "serial", str(port), name="host")
        procs.wait_output(host, "Setup publisher on pushed [std_msgs/Bool]", WAIT)
        assert "Note: publish buffer size is 280 bytes" in procs.output(host)
        echo = procs.start("-m", "workbench", "topic", "echo", "pushed", name="echo")
        for expected in ("data: True", "data: False"):
            before = procs.output(echo).count(expected)

            def seen(expected=expected, before=before):
                # Enter presses the button, the next Enter releases it; pressed again if
                # the echo subscribed only after the first message
                board.stdin.write(b"\n")
                board.stdin.flush()
                return wait_for(lambda: procs.output(echo).count(expected) > before, 3)

            assert wait_for(seen, WAIT), procs.output(echo)
        board_out = (tmp_path / "board.log").read_text()
        assert "motor (pin 13): HIGH" in board_out and "motor (pin 13): LOW" in board_out
    finally:
        board.send_signal(signal.SIGINT)
        try:
            board.wait(WAIT)
        finally:
            log.close()


class PtyDevice:
    """The test plays the board: the master side of a pseudo-terminal, raw."""

    def __init__(self) -> None:
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.buffer = b""

    def read_until(self, wanted: bytes, timeout: float = WAIT) -> bytes:
        def more() -> bool:
            ready, _, _ = select.select([self.master], [], [], 0.1)
            if ready:
                self.buffer += os.read(self.master, 4096)
            return wanted in self.buffer

        assert wait_for(more, timeout), self.buffer.hex(" ")
        seen, self.buffer = self.buffer, b""
        return seen

    def write(self, data: bytes) -> None:
        os.write(self.master, data)

    def close(self) -> None:
        os.close(self.master)
        os.close(self.slave)


@pytest.mark.parametrize("signum,status", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_host_sends_tx_stop_when_stopped(procs, signum, status):
    device = PtyDevice()
    try:
        host = procs.start("-m", "workbench", "serial", device.path, name="host")
        device.read_until(REQUEST_TOPICS)
        device.write(frame(0, topic_info(125, "chatter", "std_msgs/String")))
        procs.wait_output(host, "Setup publisher on chatter [std_msgs/String]", WAIT)
        host.send_signal(signum)
        device.read_until(TX_STOP)
        assert host.wait(WAIT) == status
        assert "Traceback" not in procs.output(host)
    finally:
        device.close()


def test_tcp_mode_serves_a_board_on_a_socket(procs):
    import socket

    port = free_port()
    host = procs.start(
        "-m",
        "workbench",
        "run",
        "rosserial_python",
        "serial_node.py",
        "tcp",
        str(port),
        name="host",
    )
    procs.wait_output(host, f"Waiting for socket connections on port {port}", WAIT)
    assert wait_for(lambda: "Waiting for socket connection\n" in procs.output(host), WAIT)
    with socket.create_connection(("127.0.0.1", port), timeout=WAIT) as board:
        received = b""
        while REQUEST_TOPICS not in received:
            received += board.recv(4096)
        board.sendall(
            frame(0, topic_info(125, "chatter", "std_msgs/String"))
            + frame(125, string("over wifi"))
        )
        procs.wait_output(host, "Setup publisher on chatter [std_msgs/String]", WAIT)
        host.send_signal(signal.SIGINT)
        received = b""
        while TX_STOP not in received:
            chunk = board.recv(4096)
            assert chunk, "the host closed without TX_STOP"
            received += chunk
    assert host.wait(WAIT) == 130
    assert "Established a socket connection from 127.0.0.1" in procs.output(host)


def test_bad_ports_are_one_line_each(run_cli, tmp_path):
    serial = pytest.importorskip("serial")
    missing = run_cli("serial", "/dev/ttyACM_nope", env={"WORKBENCH_MASTER_URI": "inproc"})
    assert missing.returncode == 1
    [line] = missing.stderr.strip().splitlines()
    assert "serial port /dev/ttyACM_nope does not exist" in line and "dialout" in line

    device = PtyDevice()
    holder = serial.Serial(device.path, exclusive=True)  # e.g. the IDE's Serial Monitor
    try:
        busy = run_cli("serial", device.path, env={"WORKBENCH_MASTER_URI": "inproc"})
    finally:
        holder.close()
        device.close()
    assert busy.returncode == 1
    [line] = busy.stderr.strip().splitlines()
    assert f"serial port {device.path} is busy" in line and "dialout" in line

    plain = tmp_path / "notes.txt"
    plain.write_text("not a port\n")
    wrong = run_cli("serial", str(plain), env={"WORKBENCH_MASTER_URI": "inproc"})
    assert wrong.returncode == 1
    [line] = wrong.stderr.strip().splitlines()
    assert f"{plain} is not a serial port" in line
