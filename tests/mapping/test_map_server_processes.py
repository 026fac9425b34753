"""map_server and map_saver as processes on a private core (``workbench run map_server ...``).

As ``rosrun map_server map_server map.yaml`` and ``rosrun map_server map_saver -f
NAME`` (ros-planning/navigation, noetic-devel, ``map_server/src/main.cpp`` and
``map_saver.cpp``): the server's latched map reaches a saver started later, which
writes the same files ROS's map_saver wrote and exits; ``static_map`` answers
another process; the server stops on SIGTERM and a saver waiting for a map stops
on Ctrl-C, each without a traceback and with the shell's status for the signal.
"""

from __future__ import annotations

import signal

import numpy as np
import pytest
from process_helpers import Processes, private_core, wait_for

pytestmark = pytest.mark.multiprocess

PGM = b"P5\n# CREATOR: map_saver.cpp 0.100 m/pix\n5 3\n255\n" + bytes(
    [0, 0, 0, 0, 0, 254, 254, 205, 254, 0, 254, 254, 205, 205, 205]
)
YAML = (
    b"image: map.pgm\nresolution: 0.100000\norigin: [-0.500000, 1.000000, 0.785398]\n"
    b"negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
)


@pytest.fixture
def procs(tmp_path):
    with private_core(tmp_path) as uri:
        processes = Processes(uri, tmp_path)
        yield processes
        processes.stop_all()


def _wait(popen, timeout: float = 60.0) -> int:
    return popen.wait(timeout)


def test_server_then_saver_in_other_processes(procs, tmp_path):
    ros = tmp_path / "ros"
    ros.mkdir()
    (ros / "map.pgm").write_bytes(PGM)
    (ros / "map.yaml").write_bytes(YAML)
    server = procs.start(
        "-m", "workbench", "run", "map_server", "map_server", str(ros / "map.yaml"), name="server"
    )
    procs.wait_output(server, "Read a 5 X 3 map @ 0.100 m/cell")

    saver = procs.start("-m", "workbench", "run", "map_server", "map_saver", name="saver")
    assert _wait(saver) == 0, procs.output(saver)
    out = procs.output(saver)
    for line in (
        "Waiting for the map",
        "Received a 5 X 3 map @ 0.100 m/pix",
        "Writing map occupancy data to map.pgm",
        "Writing map occupancy data to map.yaml",
        "Done",
    ):
        assert line in out
    assert (tmp_path / "map.pgm").read_bytes() == PGM
    assert (tmp_path / "map.yaml").read_bytes() == YAML

    from workbench.bus import Bus, Node
    from workbench.msgs.nav_msgs import GetMap

    bus = Bus.connect(procs.uri)
    try:
        node = Node("client", bus=bus, disable_rosout=True)
        bus.wait_for_service("/static_map", timeout=30)
        grid = node.create_client("/static_map", GetMap).call(GetMap.Request(), timeout=30).map
        assert grid.header.frame_id == "map"
        assert (grid.info.width, grid.info.height) == (5, 3)
        top_row = np.asarray(grid.data).reshape(3, 5)[2]
        assert top_row.tolist() == [100] * 5
        assert any(name.startswith("/map_server_") for name in bus.graph().nodes)
    finally:
        bus.shutdown()

    server.send_signal(signal.SIGTERM)
    assert _wait(server) == 128 + signal.SIGTERM
    assert "Traceback" not in procs.output(server)


def test_saver_waits_for_a_map_and_stops_on_ctrl_c(procs, tmp_path):
    saver = procs.start(
        "-m", "workbench", "run", "map_server", "map_saver", "-f", "never", name="saver"
    )
    procs.wait_output(saver, "Waiting for the map")
    from workbench.bus import Bus

    bus = Bus.connect(procs.uri)
    try:

        def subscribed() -> bool:
            node = bus.graph().nodes.get("/map_saver")
            return node is not None and "/map" in node.subscriptions

        assert wait_for(subscribed, timeout=30)
    finally:
        bus.shutdown()
    assert saver.poll() is None
    saver.send_signal(signal.SIGINT)
    assert _wait(saver) == 128 + signal.SIGINT
    assert "Traceback" not in procs.output(saver)
    assert not (tmp_path / "never.pgm").exists()


def test_bad_map_exits_with_one_line(procs, tmp_path):
    (tmp_path / "bad.yaml").write_text("image: m.pgm\nnegate: 0\n")
    server = procs.start(
        "-m", "workbench", "run", "map_server", "map_server", "bad.yaml", name="server"
    )
    assert _wait(server) == 1
    assert procs.output(server).strip().splitlines() == [
        "workbench run: error: bad.yaml: "
        "The map does not contain a resolution tag or it is invalid."
    ]
