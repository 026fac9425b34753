"""Seeded fuzzing of parameters: mutated YAML files and values, and mutated core requests.

Each mutation goes through what ``workbench param load/set`` and the core do with it; the only
acceptable failure is a one-line WorkbenchError, and the server must still answer afterwards.
"""

from __future__ import annotations

import json
import types

from fuzz_helpers import TEXT_TOKENS, Mutator, WriteWatch, bounded, check_one_line, run_cli_checked

from workbench.bus.core import Core
from workbench.bus.params import ParameterServer
from workbench.errors import WorkbenchError
from workbench.introspect import params as rosparam

SEED_FILE = b"""\
turtlesim:
  background_r: 150
  background_g: 86
  background_b: 255
costmap: &costmap
  obstacle_range: 2.5
  raytrace_range: 3.0
  footprint: [[-0.2, -0.2], [-0.2, 0.2], [0.2, 0.2], [0.2, -0.2]]
  name: "local costmap"
copy: *costmap
flags: [true, false, yes, .nan]
"""

RUNS = 300


def _still_serves(server: ParameterServer) -> None:
    server.set("/probe", 1)
    assert server.get("/probe") == 1
    json.loads(server.get_json("/"))
    rosparam.to_yaml(server.get("/"))


def test_mutated_parameter_files_and_values(tmp_path):
    mutator = Mutator(seed=17, tokens=TEXT_TOKENS)
    watch = WriteWatch(tmp_path)
    outcomes = {"loaded": 0, "refused": 0}
    for run in range(RUNS):
        data = mutator.mutate(SEED_FILE, rounds=1 + run % 2)
        path = tmp_path / f"params{run % 10}.yaml"
        path.write_bytes(data)
        server = ParameterServer()
        with bounded(f"parameter file mutation {run}"):
            try:
                rosparam.load(server, path, "/fuzz")
                outcomes["loaded"] += 1
            except WorkbenchError as error:
                check_one_line(error, f"mutation {run}")
                outcomes["refused"] += 1
            try:
                rosparam.set_text(server, "/value", data.decode("utf-8", "replace"))
            except WorkbenchError as error:
                check_one_line(error, f"value mutation {run}")
            _still_serves(server)
    watch.check()
    # the mutations must exercise both sides, or the fuzzing is not doing its job
    assert outcomes["loaded"] > 20 and outcomes["refused"] > 20, outcomes


def test_mutated_core_requests(tmp_path):
    """What a hostile client could send the core: the request handler answers or refuses."""
    mutator = Mutator(seed=1717, tokens=[b"[" * 2000, b"1e999", b'"', b"{", b"\\ud800", b"null"])
    core = types.SimpleNamespace(params=ParameterServer())
    value = {"x": [1, 2.5, "s", True], "y": {"z": 1}}
    requests = [
        ("set", json.dumps({"name": "/a/b", "value": value})),
        ("get", json.dumps({"name": "/a/b/x"})),
        ("search", json.dumps({"namespace": "/a/b/c", "key": "b"})),
        ("has", json.dumps({"name": "/a/b/y/z"})),
        ("delete", json.dumps({"name": "/a/b/y"})),
        ("names", "{}"),
    ]
    answered = refused = 0
    for run in range(RUNS):
        op, seed = requests[run % len(requests)]
        payload = mutator.mutate(seed.encode(), rounds=1)
        core.params.set("/a/b", value)
        with bounded(f"core request mutation {run}"):
            try:
                json.loads(Core._answer(core, op, payload))
                answered += 1
            except WorkbenchError as error:
                check_one_line(error, f"request {run}")
                refused += 1
            except (KeyError, ValueError, TypeError, RecursionError):
                refused += 1  # the core's callback turns these into a "bad request" reply
            _still_serves(core.params)
    assert answered > 20 and refused > 20, (answered, refused)


def test_mutated_parameter_files_through_the_command_line(tmp_path):
    mutator = Mutator(seed=4242, tokens=TEXT_TOKENS)
    watch = WriteWatch(tmp_path)
    statuses = set()
    for run in range(6):
        path = tmp_path / f"cli{run}.yaml"
        path.write_bytes(mutator.mutate(SEED_FILE))
        done = run_cli_checked(["param", "load", str(path)], cwd=tmp_path)
        statuses.add(done.returncode)
    watch.check()
    assert statuses <= {0, 1}
