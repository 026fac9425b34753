"""rosserial's TCP host: where it listens, what one device may set up, and what a device leaves.

* ``tcp`` mode listens on 127.0.0.1 unless ``--bind``/``_bind:=`` opens it to the network
  (rosserial_python's server listens on every interface);
* a device announcing thousands of topics gets 100 publishers and 100 subscribers (one
  line per refusal, naming the device and the topic, up to ten) and the host keeps serving;
* when the device disconnects, everything it set up leaves the bus and the threads it
  caused end: the count returns to what it was before it connected.
"""

from __future__ import annotations

import contextlib
import socket
import threading

import pytest
from process_helpers import joined_bus, private_core, wait_for
from rosserial_bytes import frame, string, topic_info
from tcp_host_helpers import WAIT, Lines, connect, tcp_host

from workbench.bus import Bus, Node
from workbench.errors import SerialError
from workbench.serial.bridge import MAX_PUBLISHERS, MAX_SUBSCRIBERS, REFUSALS_SHOWN
from workbench.serial.serial_node import DEFAULT_BIND, listen


def _local_address() -> str | None:
    """An IPv4 address of this machine that is not loopback (None when it has none)."""
    probe = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        probe.connect(("192.0.2.1", 9))  # TEST-NET-1: nothing is sent, a route is chosen
        address = probe.getsockname()[0]
    except OSError:
        return None
    finally:
        probe.close()
    return None if address.startswith("127.") or address == "0.0.0.0" else address


@pytest.fixture
def bus():
    bus = Bus()
    yield bus
    bus.shutdown()


def test_the_listening_socket_is_loopback_unless_bound_elsewhere():
    assert DEFAULT_BIND == "127.0.0.1"
    with contextlib.closing(listen(DEFAULT_BIND, 0)) as server:
        assert server.getsockname()[0] == "127.0.0.1"
    with contextlib.closing(listen("0.0.0.0", 0)) as server:
        assert server.getsockname()[0] == "0.0.0.0"
    with pytest.raises(SerialError, match="cannot listen on 'no such host'"):
        listen("no such host", 0)


def test_a_board_elsewhere_on_the_network_reaches_the_host_only_with_bind(bus):
    address = _local_address()
    with tcp_host(bus) as (port, lines):
        assert lines.having("Listening on 127.0.0.1 only")
        connect(port).close()  # this machine: served
        if address is not None:
            with pytest.raises(ConnectionRefusedError):
                socket.create_connection((address, port), timeout=WAIT)
    with tcp_host(bus, "0.0.0.0") as (port, lines):
        [warning] = lines.having("any machine that reaches it can connect")
        assert f"0.0.0.0 port {port}" in warning
        connect(port, address or "127.0.0.1").close()


def test_bind_is_refused_without_tcp_before_joining_the_bus(run_cli, tmp_path):
    done = run_cli(
        "serial", "/dev/ttyACM0", "--bind", "0.0.0.0",
        cwd=tmp_path, env={"WORKBENCH_MASTER_URI": "inproc"},
    )  # fmt: skip
    assert done.returncode == 1
    assert done.stderr.strip() == (
        "workbench serial: error: --bind is for tcp mode (a board on the network) "
        "(workbench serial tcp --bind 0.0.0.0)"
    )
    assert "ROS Serial Python Node" not in done.stdout


def _announce(board: socket.socket, count: int) -> None:
    """``count`` publishers and ``count`` subscribers, as one stream of TopicInfo frames."""
    frames = []
    for i in range(count):
        frames.append(frame(0, topic_info(100 + i, f"flood/pub{i}", "std_msgs/String")))
        frames.append(frame(1, topic_info(100 + i, f"flood/sub{i}", "std_msgs/Empty")))
    board.sendall(b"".join(frames))


def _registrations(bus) -> tuple[int, int]:
    graph = bus.graph()
    published = sum(
        1 for name, topic in graph.topics.items() if name.startswith("/flood/") and topic.publishers
    )
    subscribed = sum(
        1
        for name, topic in graph.topics.items()
        if name.startswith("/flood/") and topic.subscribers
    )
    return published, subscribed


def _session(bus, port: int, lines: Lines, count: int) -> tuple[int, list[str]]:
    """A device that announces ``count`` publishers and subscribers, delivers a message on
    one of them, and disconnects; returns the threads counted while it was connected and
    the refusals logged."""
    board = connect(port)
    try:
        _announce(board, count)
        shown = min(max(count - MAX_PUBLISHERS, 0) * 2, REFUSALS_SHOWN)
        assert wait_for(lambda: len(lines.having("Creation of ")) >= shown, WAIT)
        expected = (min(count, MAX_PUBLISHERS), min(count, MAX_SUBSCRIBERS))
        assert wait_for(lambda: _registrations(bus) == expected, WAIT), _registrations(bus)
        # what the device may have, it has: a message still comes through
        got: list = []
        listener = Node("listener", bus=bus, anonymous=True)
        listener.create_subscription("flood/pub3", "std_msgs/String", got.append)

        def sent() -> bool:
            board.sendall(frame(103, string("still here")))
            return bool(got)

        assert wait_for(sent, WAIT, poll=0.2)
        assert got[0].data == "still here"
        listener.shutdown()
        during = threading.active_count()
    finally:
        board.close()
    assert wait_for(lambda: len(lines.having("Client has exited, closing socket.")) >= 1, WAIT)
    assert wait_for(lambda: _registrations(bus) == (0, 0), WAIT), _registrations(bus)
    refusals = lines.having("Creation of ")
    lines.lines.clear()
    return during, refusals


def _flood_and_disconnect(bus) -> None:
    with tcp_host(bus) as (port, lines):
        # a device within the bounds starts what a bus starts once and keeps (the executor,
        # the transport's pool of service threads, at its size)
        _session(bus, port, lines, MAX_SUBSCRIBERS)
        baseline = threading.active_count()
        before = set(threading.enumerate())
        during, refusals = _session(bus, port, lines, 5000)
        assert during <= baseline + MAX_SUBSCRIBERS + 8, (during, baseline)

        def left_behind() -> list[str]:
            # by identity, not by count: other tests' threads in this process may end or
            # start meanwhile; the device's must all have ended. The Zenoh transport's pool
            # of service threads (4 at most) may have grown to its size meanwhile: it is
            # the bus's, bounded, and kept
            return sorted(
                t.name
                for t in threading.enumerate()
                if t not in before and not t.name.startswith("workbench-service_")
            )

        assert wait_for(lambda: not left_behind(), WAIT), left_behind()
    assert len(refusals) == REFUSALS_SHOWN, refusals
    device = refusals[0].split(": ", 1)[1].split(" ", 1)[0]
    assert device.startswith("127.0.0.1:")
    assert refusals[0] in (
        f"Creation of publisher failed: {device} set up {MAX_PUBLISHERS} publishers already, "
        f"the host's limit per device; refusing publisher flood/pub{MAX_PUBLISHERS}",
        f"Creation of subscriber failed: {device} set up {MAX_SUBSCRIBERS} subscribers "
        f"already, the host's limit per device; refusing subscriber flood/sub{MAX_SUBSCRIBERS}",
    )
    assert refusals[-1].endswith(f"; further refusals of {device} are not logged")


def test_5000_registrations_are_bounded_and_torn_down_with_the_device(bus):
    _flood_and_disconnect(bus)


@pytest.mark.multiprocess
def test_over_zenoh_the_device_leaves_no_thread_behind(tmp_path):
    # raw subscriptions on Zenoh have a receiving thread each: the bound caps them and the
    # device's disconnection ends them
    with private_core(tmp_path) as uri:
        bus = joined_bus(uri)
        try:
            _flood_and_disconnect(bus)
        finally:
            bus.shutdown()
