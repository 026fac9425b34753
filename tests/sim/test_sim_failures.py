"""The simulator outlives its plugins and stops cleanly when its physics fails.

A plugin that calls ``sys.exit`` (loading, importing or updating) or pushes 1e308 N is
disabled with one line naming it, and the simulation runs on; a run to a time whose
physics fails ends with the failing model named instead of waiting forever.
"""

from __future__ import annotations

import logging
from pathlib import Path

import pytest
from sim_helpers import box_model, plugin_spec

from workbench.sim import World
from workbench.sim.server import SERVER_PHYSICS, SimServer

PLUGINS = {
    "exits_on_import": "import sys\nsys.exit(1)\n",
    "exits_in_load": (
        "import sys\nfrom workbench.sim.plugins import ModelPlugin\n"
        "class P(ModelPlugin):\n    def load(self, model, sdf, node):\n        sys.exit(2)\n"
    ),
    "exits_in_update": (
        "import sys\nfrom workbench.sim.plugins import ModelPlugin\n"
        "class P(ModelPlugin):\n    def update(self, info):\n        raise SystemExit(3)\n"
    ),
    "exits_in_init": (
        "import sys\nfrom workbench.sim.plugins import ModelPlugin\n"
        "class P(ModelPlugin):\n    def __init__(self):\n        sys.exit(4)\n"
    ),
    "pushes_1e308": (
        "from workbench.sim.plugins import ModelPlugin\n"
        "class P(ModelPlugin):\n"
        "    def load(self, model, sdf, node):\n        self.model = model\n"
        "    def update(self, info):\n        self.model.apply_wrench('body', [1e308, 0, 0])\n"
    ),
    "effort_nan": (
        "from workbench.sim.plugins import ModelPlugin\n"
        "class P(ModelPlugin):\n"
        "    def load(self, model, sdf, node):\n        self.model = model\n"
        "    def update(self, info):\n"
        "        self.model._server.set_plugin_effort(self.model._owner, ('box', 'x'), float('nan'))\n"
    ),
}

EXPECTED = {
    "exits_on_import": "plugin 'exits_on_import' ({path}) called sys.exit while loading: not loaded",
    "exits_in_load": "plugin 'exits_in_load' failed in load and is disabled: {path}:5: SystemExit: 2",
    "exits_in_update": "plugin 'exits_in_update' failed in update and is disabled: {path}:5: "
    "SystemExit: 3",
    "exits_in_init": "plugin 'exits_in_init' ({path}) failed while starting: SystemExit: 4",
    "pushes_1e308": "plugin 'pushes_1e308' failed in update and is disabled: {path}:6: "
    "SimulationError: wrench on 'box::body': force.x = 1e+308 is beyond 1e+06 N",
    "effort_nan": "plugin 'effort_nan' failed in update and is disabled: {path}:6: "
    "SimulationError: effort on joint 'x' is not finite",
}


@pytest.mark.parametrize("name", sorted(PLUGINS))
def test_a_plugin_that_exits_or_pushes_too_hard_is_disabled_and_the_sim_runs_on(
    name, tmp_path: Path, caplog
):
    path = tmp_path / f"{name}.py"
    path.write_text(PLUGINS[name])
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("box"), [0.0, 0.0, 0.05])
    server = SimServer(world, real_time_factor=0)
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        server.load_plugin(plugin_spec(str(path), name), "box")
        server.run(until=0.2)
    assert server.world.time == pytest.approx(0.2)
    assert server.error is None and server.plugins == []
    lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.ERROR]
    assert lines == [EXPECTED[name].format(path=path)]


def test_a_run_to_a_time_ends_when_the_physics_fails_and_names_the_model():
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("calm"), [2.0, 0.0, 0.05])
    world.add_model(box_model("spun"), [0.0, 0.0, 0.05])
    server = SimServer(world, real_time_factor=0)
    # within the request bounds, but far more than a 0.1 m box can take
    server.apply_body_wrench("spun::body", [0.0, 0.0, 0.0], [1e6, -1e6, 1e6], 0.0, -1.0)
    server.run(until=30.0)  # returns: it does not wait, paused, for a reset
    assert server.world.time < 30.0
    assert server.error is not None and server.error.startswith("model 'spun': ")
    assert "\n" not in server.error
    server.reset(time_too=True)
    assert not server.paused and server.error is None
    server.run(until=0.1)
    assert server.world.time == pytest.approx(0.1)
