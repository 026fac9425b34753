"""The live view: buttons, the real-time-factor readout, redraws and the recording."""

from __future__ import annotations

import time

from sim_helpers import box_model

from workbench.sim import World
from workbench.sim.server import SERVER_PHYSICS, SimServer
from workbench.sim.view import LiveView
from workbench.viz.snapshot import snapshot_paths

_KEPT: list = []


def _kept_meshcat(meshcat_class, params_class):
    """One Meshcat for the process's life: Drake's must be destroyed on its own thread."""
    if not _KEPT:
        _KEPT.append(meshcat_class(params_class(host="127.0.0.1")))
    _KEPT[0].Delete()
    return _KEPT[0]


def test_the_view_adds_its_buttons_shows_the_speed_and_records(tmp_path):
    from pydrake.geometry import Meshcat, MeshcatParams

    meshcat = _kept_meshcat(Meshcat, MeshcatParams)
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("crate"), [0.0, 0.0, 1.0])
    view = LiveView(world, meshcat, contacts=True, record=True)
    server = SimServer(world, real_time_factor=1.0)
    view.attach(server)
    assert set(meshcat.GetButtonNames()) >= {"Pause", "Play", "Step"}
    start = time.perf_counter()
    server.run(until=1.2)
    assert time.perf_counter() - start >= 1.0  # paced to real time
    view.update(server)
    assert 0.0 < meshcat.GetRealtimeRate() < 1.5  # shown; paced, never faster (slower when busy)
    out = view.save_html(tmp_path / "run.html")
    assert any("crate" in path for path in snapshot_paths(out))
    view.close()
    assert not set(meshcat.GetButtonNames()) & {"Pause", "Play", "Step"}


def test_a_view_on_a_built_world_is_refused():
    import pytest
    from pydrake.geometry import Meshcat, MeshcatParams

    from workbench.errors import SimulationError

    world = World(**SERVER_PHYSICS)
    world.build()
    with pytest.raises(SimulationError, match="before the world is built"):
        LiveView(world, _kept_meshcat(Meshcat, MeshcatParams))
