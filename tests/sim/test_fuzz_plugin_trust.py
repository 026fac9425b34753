"""Seeded fuzzing of plugin names: no mutant of a ``filename`` runs code the world did not choose.

Each mutant of a plugin ``filename`` (absolute and ``..`` paths to a file that leaves a marker
when imported, ``module:Class`` forms, workbench's own names, long and binary names) is
located and loaded as a world's plugin and as a spawned model's: it loads (a file of the
world's folder, workbench's own plugins), or it is refused or missing with one line; the
marker file never appears. A few mutants also go to ``/gazebo/spawn_sdf_model`` on a running
server, which answers each with one status line and keeps stepping.
Campaign: ``WORKBENCH_FUZZ_SEED``/``WORKBENCH_FUZZ_RUNS`` (see ``tests/fuzz_helpers.py``).
"""

from __future__ import annotations

import os
import sys
import time
from xml.sax.saxutils import quoteattr

import pytest
from fuzz_helpers import TEXT_TOKENS, Mutator, bounded, check_one_line, fuzz_runs, fuzz_seed, report

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec
from workbench.sim.plugin_sources import PluginRefusedError
from workbench.sim.plugin_trust import PluginTrust
from workbench.sim.plugins import load_plugin_class

MARKER_PLUGIN = """\
from pathlib import Path
from workbench.sim.plugins import ModelPlugin

Path({marker!r}).write_text("imported")


class Marker(ModelPlugin):
    pass
"""

OWN_PLUGIN = """\
from workbench.sim.plugins import ModelPlugin


class Own(ModelPlugin):
    pass
"""


@pytest.fixture
def layout(tmp_path, monkeypatch):
    """``(world folder, outside plugin, marker)``: the world's folder holds ``own_plugin.py``;
    ``outside/marker_plugin.py`` beside it writes ``marker`` when imported."""
    for variable in ("GAZEBO_PLUGIN_PATH", "WORKBENCH_PLUGIN_PATH"):
        monkeypatch.delenv(variable, raising=False)
    world = tmp_path / "world"
    world.mkdir()
    (world / "own_plugin.py").write_text(OWN_PLUGIN)
    marker = tmp_path / "imported.marker"
    outside = tmp_path / "outside" / "marker_plugin.py"
    outside.parent.mkdir()
    outside.write_text(MARKER_PLUGIN.format(marker=str(marker)))
    yield world, outside, marker
    for name in [n for n in sys.modules if n.startswith("workbench_plugin_")]:
        del sys.modules[name]


def seeds(outside) -> list[bytes]:
    return [
        str(outside).encode(),
        b"../outside/marker_plugin.py",
        b"own_plugin.py",
        b"own_plugin.py:Own",
        b"model_push.py",
        b"this:X",
        b"os:system",
        b"libgazebo_ros_diff_drive.so",
        b"workbench.sim.gazebo_ros_plugins.diff_drive:GazeboRosDiffDrive",
        b"file://" + str(outside).encode(),
    ]


TOKENS = [*TEXT_TOKENS, b"..", b"/", b"../", b":", b".py", b"~", b"\\", b"//", b"./"]


def spec_of(filename: str, base_dir) -> PluginSpec:
    return PluginSpec(
        name="fuzzed",
        filename=filename,
        element="<plugin/>",
        kind="model",
        base_dir=base_dir,
        source="fuzz.world:1",
    )


def test_fuzzed_plugin_filenames_never_run_the_outside_file(layout):
    world, outside, marker = layout
    mutator = Mutator(fuzz_seed(2801), TOKENS)
    originals = seeds(outside)
    runs = fuzz_runs(300)
    outcomes = {"loaded": 0, "refused": 0, "missing_or_bad": 0, "spawn_refused": 0}
    for index in range(runs):
        raw = mutator.mutate(originals[index % len(originals)])
        filename = raw.decode("utf-8", errors="replace")
        what = f"mutant {index} {raw[:80]!r}"
        for spawned in (False, True):
            trust = PluginTrust()
            spec = spec_of(filename, None if spawned else world)
            with bounded(what):
                try:
                    source = trust.admit_spawned(spec) if spawned else trust.admit(spec)
                    load_plugin_class(spec, source)
                    outcomes["loaded"] += 1
                except PluginRefusedError as error:
                    check_one_line(error, what)
                    outcomes["spawn_refused" if spawned else "refused"] += 1
                except SimulationError as error:
                    check_one_line(error, what)
                    outcomes["missing_or_bad"] += 1
            assert not marker.exists(), f"{what} ran the outside file (spawned={spawned})"
    report("plugin filenames", runs, **outcomes)
    assert outcomes["refused"] and outcomes["spawn_refused"]
    if "WORKBENCH_FUZZ_SEED" not in os.environ:  # the suite's mutants also reach a good file
        assert outcomes["loaded"]


def test_fuzzed_spawn_requests_get_one_status_line_and_the_server_steps_on(layout):
    from workbench.bus import Bus, Node
    from workbench.msgs import gazebo_msgs as gm
    from workbench.sim import World
    from workbench.sim.gazebo_ros import GazeboRosApi
    from workbench.sim.server import SERVER_PHYSICS, SimServer

    _, outside, marker = layout
    mutator = Mutator(fuzz_seed(2802), TOKENS)
    originals = seeds(outside)
    bus = Bus()
    server = SimServer(World(**SERVER_PHYSICS), bus=bus, real_time_factor=0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    client = Node("client", bus=bus).create_client("/gazebo/spawn_sdf_model", gm.SpawnModel)
    server.start()
    runs = fuzz_runs(40)
    outcomes = {"spawned": 0, "refused": 0}
    try:
        for index in range(runs):
            raw = mutator.mutate(originals[index % len(originals)])
            filename = raw.decode("utf-8", errors="replace")
            xml = (
                f'<sdf version="1.6"><model name="m{index}"><link name="body">'
                "<inertial><mass>1</mass></inertial></link>"
                f"<plugin name='fuzzed' filename={quoteattr(filename)}/></model></sdf>"
            )
            request = gm.SpawnModel.Request(model_name=f"m{index}", model_xml=xml)
            request.initial_pose.position.z = 0.5
            request.initial_pose.orientation.w = 1.0
            reply = client.call(request, timeout=60)
            assert "\n" not in reply.status_message and reply.status_message
            outcomes["spawned" if reply.success else "refused"] += 1
            if reply.success:  # the world stays one model big: each spawn costs the same
                server.delete(f"m{index}")
            assert not marker.exists(), f"mutant {index} {raw[:80]!r} ran the outside file"
        t0 = server.call(lambda: server.world.time)
        deadline = time.monotonic() + 60
        while server.call(lambda: server.world.time) < t0 + 0.05 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert server.call(lambda: server.world.time) >= t0 + 0.05
    finally:
        api.close()
        server.stop()
        bus.shutdown()
    report("spawn plugin filenames", runs, **outcomes)
