"""``workbench run amcl amcl`` as a process on a private core: it asks for ``static_map``
until a map_server process answers (amcl's lines), and stops on SIGTERM or Ctrl-C without a
traceback and with the shell's status for the signal."""

from __future__ import annotations

import signal

import pytest
from amcl_feed import DEMO_ROOMS
from process_helpers import Processes, private_core

pytestmark = pytest.mark.multiprocess


@pytest.fixture
def procs(tmp_path):
    with private_core(tmp_path) as uri:
        processes = Processes(uri, tmp_path)
        yield processes
        processes.stop_all()


def test_amcl_waits_for_the_map_server_then_stops_on_sigterm(procs):
    amcl = procs.start(
        "-m",
        "workbench",
        "run",
        "amcl",
        "amcl",
        "_initial_pose_x:=1.0",
        "_kld_err:=0.02",
        name="amcl",
    )
    procs.wait_output(amcl, "Requesting the map...")
    procs.wait_output(amcl, "Request for map failed; trying again...")
    server = procs.start(
        "-m", "workbench", "run", "map_server", "map_server", str(DEMO_ROOMS), name="server"
    )
    procs.wait_output(amcl, "Received a 203 X 163 map @ 0.050 m/pix")
    procs.wait_output(amcl, "Done initializing likelihood field model.")
    assert amcl.poll() is None
    from workbench.bus import Bus

    bus = Bus.connect(procs.uri)
    try:
        assert bus.params.get("/amcl/initial_pose_x") == 1.0
        assert bus.params.get("/amcl/kld_err") == 0.02
        assert bus.wait_for_service("/global_localization", timeout=30)
    finally:
        bus.shutdown()
    amcl.send_signal(signal.SIGTERM)
    assert amcl.wait(60) == 128 + signal.SIGTERM
    assert "Traceback" not in procs.output(amcl)
    server.send_signal(signal.SIGINT)
    assert server.wait(60) == 128 + signal.SIGINT


def test_amcl_stops_on_ctrl_c_while_it_waits_for_the_map(procs):
    amcl = procs.start("-m", "workbench", "run", "amcl", "amcl", name="amcl")
    procs.wait_output(amcl, "Request for map failed; trying again...")
    amcl.send_signal(signal.SIGINT)
    assert amcl.wait(60) == 128 + signal.SIGINT
    assert "Traceback" not in procs.output(amcl)
