"""The parameter server stays usable after anything a client can send (issue 17, items 2 and 12)."""

from __future__ import annotations

import json
import signal
from pathlib import Path

import pytest
from process_helpers import Processes, free_port, joined_bus, private_core, wait_for, wait_port

from workbench.bus.errors import CoreError
from workbench.bus.params import VALUE_LIMITS, ParameterError, ParameterServer
from workbench.limits import TreeLimits


def _deep_list(levels: int) -> list:
    value: list = []
    for _ in range(levels):
        value = [value]
    return value


def test_values_past_the_bounds_are_refused_without_recursion():
    params = ParameterServer()
    with pytest.raises(ParameterError, match="parameter /deep is nested more than 32 levels"):
        params.set("/deep", _deep_list(3000))
    with pytest.raises(ParameterError, match="more than 500,000 elements"):
        params.set("/many", list(range(VALUE_LIMITS.max_nodes)))
    with pytest.raises(ParameterError, match="more than 16.0 MiB of text"):
        params.set("/text", "x" * (VALUE_LIMITS.max_bytes + 1))
    shared = ["lol"] * 9
    for _ in range(6):  # a billion-laughs value built in Python: shared lists, 9**7 strings
        shared = [shared] * 9
    with pytest.raises(ParameterError, match="more than 500,000 elements"):
        params.set("/bomb", shared)
    assert params.names() == []
    params.set("/ok", _deep_list(31))  # within the bound
    assert params.get("/ok") == _deep_list(31)


def test_the_server_refuses_to_grow_past_its_total(monkeypatch):
    import workbench.bus.params as module

    monkeypatch.setattr(module, "SERVER_LIMITS", TreeLimits(max_nodes=1000, max_bytes=10_000))
    params = ParameterServer()
    chunk = list(range(298))  # with its list and its key: 300 elements, 2392 bytes
    with pytest.raises(ParameterError, match="would hold more than 1,000 elements"):
        for stored in range(10):  # noqa: B007
            params.set(f"/p{stored}", chunk)
    assert stored == 3 and params.names() == ["/p0", "/p1", "/p2"]
    params.delete("/p2")  # room again once something is deleted
    params.set("/again", chunk)
    params.set("/p0", [1])  # replacing a value frees what it held
    params.set("/p3", chunk)
    with pytest.raises(ParameterError, match="or 9.8 KiB of text"):
        params.set("/text", "x" * 3000)
    params.delete("/")
    params.set("/text", "x" * 3000)


def test_requests_do_not_copy_the_tree(monkeypatch):
    import workbench.bus.params as module

    params = ParameterServer()
    params.set("/big", {f"p{i}": i for i in range(100_000)})

    def no_copy(value, memo=None):
        raise AssertionError("copied the tree")

    monkeypatch.setattr(module.copy, "deepcopy", no_copy)
    assert len(params.names()) == 100_000
    assert json.loads(params.get_json("/"))["big"]["p7"] == 7
    assert params.has("/big/p99999") and not params.has("/big/nope")
    assert params.search("/big/x/y", "p5") == "/big/p5"


def _raw_request(session, op: str, payload: bytes, timeout: float = 20.0):
    """Send a parameter request as any Zenoh client could, bypassing workbench's checks."""
    for reply in session.get(f"wb/p/{op}", payload=payload, timeout=timeout):
        if reply.ok is not None:
            return "ok", reply.ok.payload.to_bytes()
        return "err", reply.err.payload.to_bytes()
    return "none", b""


@pytest.mark.multiprocess
def test_the_core_answers_hostile_requests_and_keeps_serving(tmp_path):
    zenoh = pytest.importorskip("zenoh")
    from workbench.bus.zconfig import client_config

    with private_core(tmp_path) as uri, zenoh.open(client_config(uri)) as session:
        assert wait_for(lambda: _raw_request(session, "has", b'{"name": "/"}')[0] == "ok")
        cases = {
            "not json": b"\xff\xfe{",
            "deep json": b'{"name": "/d", "value": ' + b"[" * 100_000 + b"]" * 100_000 + b"}",
            "many": json.dumps({"name": "/m", "value": list(range(600_000))}).encode(),
            "huge": b'{"name": "/h", "value": "' + b"x" * (33 * 1024 * 1024) + b'"}',
            "not an object": b"[1, 2]",
            "no name": b"{}",
        }
        for what, payload in cases.items():
            kind, body = _raw_request(session, "set", payload)
            assert kind == "err", (what, body[:200])
            message = json.loads(body)["message"]
            assert "\n" not in message and len(message) < 600, (what, message)
        kind, body = _raw_request(session, "set", b"{}")
        assert "bad parameter request 'set'" in json.loads(body)["message"]
        bus = joined_bus(uri)
        try:
            bus.params.set("/still/here", 5)
            assert bus.params.get("/still/here") == 5
            assert bus.params.names() == ["/still/here"]
        finally:
            bus.shutdown()


@pytest.mark.multiprocess
def _stopped(pid: int) -> bool:
    """The process has taken SIGSTOP (state T in /proc)."""
    stat = Path(f"/proc/{pid}/stat").read_text()
    return stat[stat.rindex(")") + 2] == "T"


def test_a_core_that_does_not_answer_is_one_line_naming_it(tmp_path):
    pytest.importorskip("zenoh")

    port = free_port()
    uri = f"tcp/127.0.0.1:{port}"
    processes = Processes(uri, tmp_path)
    core = processes.start("-m", "workbench", "core", name="core")
    try:
        assert wait_port(port), processes.output(core)
        bus = joined_bus(uri)
        try:
            bus.params.set("/x", 1)
            core.send_signal(signal.SIGSTOP)  # a core that hangs (or is swamped)
            assert wait_for(lambda: _stopped(core.pid), 10.0)
            try:
                with pytest.raises(CoreError) as info:
                    bus.params.get("/x")
            finally:
                core.send_signal(signal.SIGCONT)
            line = info.value.one_line()
            assert uri in line and "did not answer parameter request 'get' within 5 s" in line
            assert "\n" not in line
        finally:
            bus.shutdown()
    finally:
        processes.stop_all()


@pytest.mark.multiprocess
def test_param_cli_refuses_hostile_input_in_one_line(tmp_path, run_cli, data_dir):
    with private_core(tmp_path) as uri:
        env = {"WORKBENCH_MASTER_URI": uri}
        laughs = (data_dir / "hostile" / "parameters" / "alias_bomb.yaml").read_text()
        bomb = run_cli("param", "set", "/bomb", laughs, env=env)
        assert bomb.returncode == 1
        assert bomb.stderr.strip().endswith("(is it a YAML 'billion laughs' bomb?)")
        deep = run_cli("param", "set", "/deep", "[" * 3000 + "]" * 3000, env=env)
        assert deep.returncode == 1 and "nested more than" in deep.stderr
        assert len(deep.stderr.strip().splitlines()) == 1
        ok = run_cli("param", "set", "/fine", "[1, 2]", env=env)
        assert ok.returncode == 0, ok.stderr
        got = run_cli("param", "get", "/fine", env=env)
        assert got.stdout.split() == ["-", "1", "-", "2"]
