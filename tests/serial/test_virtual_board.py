"""The shipped sketches on virtual boards (pseudo-terminals), bridged by the host node in a thread."""

from __future__ import annotations

import pytest
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.errors import SerialError
from workbench.msgs.std_msgs import Bool, Empty, String
from workbench.msgs.std_srvs import SetBool
from workbench.serial.board import SketchError
from workbench.serial.serial_node import BackgroundHost
from workbench.serial.virtual import VirtualBoard

WAIT = 20.0


@pytest.fixture
def bus():
    bus = Bus()
    yield bus
    bus.shutdown()


@pytest.fixture
def start(bus):
    started: list = []

    def _start(sketch: str, **options):
        board = VirtualBoard(sketch, bus=bus, **options).start()
        host = BackgroundHost(board.path, bus=bus)
        started.append((host, board))
        return board, host

    yield _start
    for host, board in reversed(started):
        host.stop()
        board.stop()


def collect(bus, topic, msg_type):
    got: list = []
    Node(f"echo_{topic.strip('/').replace('/', '_')}", bus=bus).create_subscription(
        topic, msg_type, got.append
    )
    return got


def test_hello_world_prints_the_manuals_lines(bus, start, capsys):
    chatter = collect(bus, "chatter", String)
    board, _ = start("hello_world", buffer=200)
    assert wait_for(lambda: len(chatter) >= 2, WAIT)
    assert {m.data for m in chatter} == {"hello world!"}
    out = capsys.readouterr().out
    lines = [line.split("]: ", 1)[1] for line in out.splitlines() if "]: " in line]
    assert lines[:4] == [
        f"Connecting to {board.path} at 57600 baud",
        "Requesting topics...",
        "Note: publish buffer size is 200 bytes",
        "Setup publisher on chatter [std_msgs/String]",
    ]


def test_button_drives_the_motor_and_is_published(bus, start, capsys):
    pushed = collect(bus, "pushed", Bool)
    diagnostics = collect(bus, "/diagnostics", "diagnostic_msgs/DiagnosticArray")
    board, _ = start("button_motor", report=print)
    assert wait_for(
        lambda: "Setup publisher on pushed [std_msgs/Bool]" in capsys.readouterr().out, WAIT
    )
    board.press()
    assert wait_for(lambda: [m.data for m in pushed] == [True], WAIT)
    assert board.level("motor") == 1
    # the button from a topic, as `workbench topic pub /virtual_arduino/button ...`
    Node("finger", bus=bus).create_publisher("/virtual_arduino/button", Bool).publish(data=False)
    assert wait_for(lambda: [m.data for m in pushed] == [True, False], WAIT)
    assert board.level("motor") == 0
    out = capsys.readouterr().out
    assert "motor (pin 13): HIGH" in out and "motor (pin 13): LOW" in out
    states = [
        {v.key: v.value for v in s.values}
        for a in diagnostics
        for s in a.status
        if s.name == "virtual_arduino"
    ]
    assert {"button (pin 7)": "LOW", "motor (pin 13)": "HIGH"} in states
    assert states[-1] == {"button (pin 7)": "HIGH", "motor (pin 13)": "LOW"}


def test_subscriber_toggles_the_led(bus, start, capsys):
    board, _ = start("toggle_led")
    assert wait_for(lambda: "Setup subscriber on toggle_led" in capsys.readouterr().out, WAIT)
    pub = Node("me", bus=bus).create_publisher("toggle_led", Empty)
    pub.publish()
    assert wait_for(lambda: board.level("led") == 1, WAIT)
    pub.publish()
    assert wait_for(lambda: board.level("led") == 0, WAIT)


def test_services_both_ways_and_a_parameter(bus, start, capsys):
    me = Node("me", bus=bus)
    me.set_param("/serial_node/greeting_period", 100)
    me.create_service(
        "greeting", "std_srvs/Trigger", lambda req: {"success": True, "message": "hi"}
    )
    greetings = collect(bus, "greetings", String)
    board, _ = start("service_param")
    led = me.create_client("led", SetBool)
    led.wait_for_service(WAIT)
    assert wait_for(lambda: len(greetings) >= 3, WAIT)
    assert {m.data for m in greetings} == {"hi"}
    answer = led.call(SetBool.Request(data=True), timeout=WAIT)
    assert answer.success and answer.message == "LED on"
    assert board.level("led") == 1
    out = capsys.readouterr().out
    assert "Setup service server on led [std_srvs/SetBool]" in out
    assert "Setup service client on greeting [std_srvs/Trigger]" in out
    assert "greeting every 2000 ms" not in out  # the parameter was found


def test_the_host_reconnects_when_the_board_comes_back(bus, tmp_path, capsys):
    link = tmp_path / "ttyACM0"
    chatter = collect(bus, "chatter", String)
    first = VirtualBoard("hello_world", link=link).start()
    host = BackgroundHost(str(link), bus=bus)
    try:
        assert wait_for(lambda: chatter, WAIT)
        first.stop()  # the USB cable is pulled
        assert wait_for(lambda: "reconnecting" in capsys.readouterr().err, WAIT)
        count = len(chatter)
        second = VirtualBoard("hello_world", link=link).start()  # and plugged in again
        try:
            assert wait_for(lambda: len(chatter) > count, WAIT)
        finally:
            host.stop()
            second.stop()
    finally:
        first.stop()
    out = capsys.readouterr().out
    assert "Setup publisher on chatter [std_msgs/String]" in out


def test_sketch_mistakes_are_one_line_errors(tmp_path):
    with pytest.raises(SerialError, match="no sketch 'hello_wrld'.*hello_world"):
        VirtualBoard("hello_wrld")
    with pytest.raises(SerialError, match="unknown board 'uno3'"):
        VirtualBoard("hello_world", board="uno3")
    no_loop = tmp_path / "no_loop.py"
    no_loop.write_text("def setup():\n    pass\n")
    with pytest.raises(SerialError, match=r"no_loop.py: the sketch has no loop\(\) function"):
        VirtualBoard(str(no_loop))
    broken = tmp_path / "broken.py"
    broken.write_text("def setup():\n    pass\n\n\ndef loop():\n    1 / 0\n")
    board = VirtualBoard(str(broken)).start()
    assert wait_for(lambda: not board.is_running(), WAIT)
    board.stop()
    assert isinstance(board.error, SketchError)
    assert board.error.one_line() == (
        f"{broken}:6: the sketch stopped: ZeroDivisionError: division by zero"
    )
