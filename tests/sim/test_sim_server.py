"""The simulation server: stepping, pausing, plugins (good and failing) and blow-ups."""

from __future__ import annotations

import logging
import threading
import time
from pathlib import Path

import numpy as np
import pytest
from sim_helpers import box_model, plugin_spec, spinner_model

from workbench.bus import Bus, Node
from workbench.errors import SimulationError
from workbench.paths import examples_dir
from workbench.sim import World
from workbench.sim.plugins import UnavailablePluginError, load_plugin_class
from workbench.sim.server import SERVER_PHYSICS, SimServer

PLUGINS = examples_dir() / "gazebo" / "plugins"


def _server(*models, **options) -> SimServer:
    world = World(**SERVER_PHYSICS)
    for model, pose in models:
        world.add_model(model, pose)
    return SimServer(world, real_time_factor=0, **options)


def test_run_until_a_time_then_calls_from_another_thread_are_served_between_steps():
    server = _server((box_model("box"), [0.0, 0.0, 1.0]))
    server.run(until=0.3)
    assert server.world.time == pytest.approx(0.3)
    server.start()
    try:
        names = server.call(lambda: server.world.model_names())
        assert names == ["ground_plane", "box"]
        server.spawn(box_model("other"), [1.0, 0.0, 0.5])
        assert "other" in server.call(server.world.model_names)
        t = server.call(lambda: server.world.time)
        deadline = time.monotonic() + 30
        while server.call(lambda: server.world.time) < t + 0.5 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert server.call(lambda: server.world.time) >= t + 0.5
    finally:
        server.stop()
    assert not server.running


def test_paused_does_not_advance_but_a_step_request_does():
    server = _server((box_model("box"), [0.0, 0.0, 1.0]), paused=True)
    server.start()
    try:
        time.sleep(0.2)
        assert server.call(lambda: server.world.time) == 0.0
        server.request_step(0.05)
        deadline = time.monotonic() + 30
        while server.call(lambda: server.world.time) < 0.05 - 1e-9 and time.monotonic() < deadline:
            time.sleep(0.01)
        time.sleep(0.1)
        assert server.call(lambda: server.world.time) == pytest.approx(0.05)
    finally:
        server.stop()


def test_real_time_pacing_keeps_simulated_time_near_wall_time():
    server = _server((box_model("box"), [0.0, 0.0, 0.05]))
    server.real_time_factor = 1.0
    start = time.perf_counter()
    server.run(until=0.3)
    assert time.perf_counter() - start >= 0.3 * 0.9  # not faster than asked


def test_the_model_push_plugin_slides_its_model_at_the_set_velocity():
    push = plugin_spec(str(PLUGINS / "model_push.py"), "push", "<x>0.3</x>")
    crate = box_model("crate", size=(0.6, 0.6, 0.3), mass=5.0, plugins=[push])
    server = _server((crate, [0.0, 0.0, 0.15]))
    server.load_plugin(push, "crate")
    server.run(until=2.0)
    x = server.world.get_model_pose("crate").translation()[0]
    # set to 0.3 m/s before each 1 ms step, friction (mu g dt = 0.01 m/s) slows it in the step
    assert x == pytest.approx(0.6, abs=0.03)
    v, _ = server.world.get_model_twist("crate")
    assert v[0] == pytest.approx(0.3, abs=0.02)


def test_the_velocity_controller_follows_its_topic():
    bus = Bus()
    spec = plugin_spec(
        str(PLUGINS / "velocity_controller.py"),
        "velodyne_control",
        "<joint>spin</joint><topic>/spinner/vel_cmd</topic><p_gain>0.05</p_gain>",
    )
    world = World(**SERVER_PHYSICS)
    world.add_model(spinner_model("spinner"), [0.0, 0.0, 0.0])
    server = SimServer(world, bus=bus, real_time_factor=0)
    assert server.load_plugin(spec, "spinner") is not None
    from workbench.msgs.std_msgs import Float32

    publisher = Node("commander", bus=bus).create_publisher("/spinner/vel_cmd", Float32)
    publisher.publish(Float32(data=4.0))
    deadline = time.monotonic() + 10
    while server.plugins[0].target != 4.0 and time.monotonic() < deadline:
        time.sleep(0.01)
    server.run(until=1.0)
    spin = world.joint("spinner", "spin")
    context = world.plant.GetMyContextFromRoot(world.context)
    assert world.plant.GetVelocities(context)[spin.velocity_start()] == pytest.approx(4.0, abs=0.1)
    server.stop()
    bus.shutdown()


def _write(tmp_path: Path, name: str, text: str) -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


FAILING_UPDATE = """
from workbench.sim.plugins import ModelPlugin

class Breaks(ModelPlugin):
    def load(self, model, sdf, node):
        self.model = model

    def update(self, info):
        if info.sim_time > 0.1:
            raise ValueError("broken on purpose")
"""


def test_a_plugin_that_raises_in_update_is_reported_with_file_and_line_and_disabled(
    tmp_path, caplog
):
    path = _write(tmp_path, "breaks.py", FAILING_UPDATE)
    server = _server((box_model("box"), [0.0, 0.0, 0.05]))
    server.load_plugin(plugin_spec(path, "breaks"), "box")
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        server.run(until=0.5)
    assert server.world.time == pytest.approx(0.5)  # kept running
    assert server.plugins == []
    messages = [r.getMessage() for r in caplog.records]
    assert any(
        "plugin 'breaks' failed in update" in m and f"{path}:10: ValueError: broken on purpose" in m
        for m in messages
    ), messages


def test_plugin_files_that_are_missing_empty_or_fail_to_load_are_refused(tmp_path, caplog):
    server = _server((box_model("box"), [0.0, 0.0, 0.05]))
    missing = plugin_spec("no_such_plugin.py", "ghost")
    with pytest.raises(SimulationError, match="file 'no_such_plugin.py' not found"):
        load_plugin_class(missing)
    empty = _write(tmp_path, "empty.py", "x = 1\n")
    with pytest.raises(SimulationError, match="defines no plugin class"):
        load_plugin_class(plugin_spec(empty, "empty"))
    syntax = _write(tmp_path, "syntax.py", "def broken(:\n")
    with pytest.raises(SimulationError, match=r"syntax.py:1: SyntaxError"):
        load_plugin_class(plugin_spec(syntax, "syntax"))
    with pytest.raises(UnavailablePluginError, match="'libgazebo_no_such.so'.*not provided"):
        load_plugin_class(plugin_spec("libgazebo_no_such.so", "nothing"))
    raising = _write(
        tmp_path,
        "raising.py",
        "from workbench.sim.plugins import ModelPlugin\n"
        "class R(ModelPlugin):\n"
        "    def load(self, model, sdf, node):\n"
        "        raise RuntimeError('cannot load')\n",
    )
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        assert server.load_plugin(plugin_spec(missing.filename, "ghost"), "box") is None
        assert server.load_plugin(plugin_spec(raising, "raising"), "box") is None
    text = "\n".join(r.getMessage() for r in caplog.records)
    assert f"plugin 'raising' failed in load and is disabled: {raising}:4: RuntimeError" in text
    server.run(until=0.1)
    assert server.world.time == pytest.approx(0.1)


def test_a_simulation_that_blows_up_pauses_with_a_message_and_the_server_lives_on(caplog):
    server = _server((box_model("box"), [0.0, 0.0, 0.05]), (box_model("calm"), [2, 0, 0.05]))
    server.apply_body_wrench("box::body", [0.0, 0.0, 1e305], [0.0, 0.0, 0.0], 0.0, -1.0)
    timer = threading.Timer(120.0, server.stop)  # a guard against a hang, not a time limit
    timer.start()
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        server.start()
        deadline = time.monotonic() + 120
        while not server.paused and time.monotonic() < deadline:
            time.sleep(0.01)
        server.stop()
    timer.cancel()
    assert server.paused
    assert server.error is not None and "t=" in server.error
    assert any("simulation stopped" in r.getMessage() for r in caplog.records)
    server.delete("box")
    server.reset(time_too=True)
    server.paused = False
    server.run(until=0.1)
    assert np.all(np.isfinite(server.world.get_model_pose("calm").translation()))


def test_an_unknown_gazebo_library_is_one_warning_and_the_model_still_spawns(caplog):
    """Gazebo logs a plugin library it cannot load and spawns the model (issue 15)."""
    server = _server()
    unknown = plugin_spec("libgazebo_ros_fancy.so", "fancy")
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        server.spawn(box_model("crate", plugins=[unknown]), [0.0, 0.0, 0.5])
    assert "crate" in server.world.model_names()
    warnings = [r.getMessage() for r in caplog.records if r.levelno == logging.WARNING]
    assert len(warnings) == 1, warnings
    assert "model 'crate'" in warnings[0] and "libgazebo_ros_fancy.so" in warnings[0]
    assert server.plugins == []


def test_a_model_spawned_into_the_ground_is_lifted_to_rest_on_it():
    """spawn_model without -z puts custom_bot's wheels 8.5 cm into the ground; Gazebo pushes
    it out at once, and so does the server (a stiff point contact would hold the wheels)."""
    from workbench.paths import urdf_dir
    from workbench.sim.loading import sim_model_from_xml

    server = _server()
    text = (urdf_dir() / "custom_bot.urdf").read_text()
    robot = sim_model_from_xml(text, name="custom_bot", source="test", base_dir=urdf_dir())
    server.spawn(robot, [0.0, 0.0, 0.0])
    assert server.world.ground_penetration("custom_bot") == 0.0
    assert server.world.get_model_pose("custom_bot").translation()[2] == pytest.approx(
        0.0855, abs=0.002
    )
    server.spawn(box_model("crate"), [1.0, 0.0, 0.5])  # above the ground: left where it is
    assert server.world.get_model_pose("crate").translation()[2] == pytest.approx(0.5)
