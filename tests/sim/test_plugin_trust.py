"""Spawn requests over the bus load only the plugins the running world allowed.

A bus client asks ``/gazebo/spawn_urdf_model`` and ``/gazebo/spawn_sdf_model`` for models
whose plugins name a file by absolute path or a ``module:Class``: the server answers
``success: false`` with Gazebo's status style, nothing of the plugin is read (a marker the
file would write at import never appears), and the server keeps stepping and answering.
Started with ``allow_spawn_plugins`` (``--allow-spawn-plugins``), the same plugin loads.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest
from hostile_corpus import cases, run_case
from sim_helpers import box_model

from workbench.bus import Bus, Node
from workbench.msgs import gazebo_msgs as gm
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.gzserver import ServerOptions, build_server, options_from
from workbench.sim.model_spec import PluginSpec
from workbench.sim.plugin_sources import ENTRY_POINT_GROUP
from workbench.sim.server import SERVER_PHYSICS, SimServer

#: A plugin file that leaves a marker as soon as it is imported, and then counts updates.
MARKER_PLUGIN = """\
from pathlib import Path
from workbench.sim.plugins import ModelPlugin

Path({marker!r}).write_text("imported")


class Marker(ModelPlugin):
    def load(self, model, sdf, node):
        self.updates = 0

    def update(self, info):
        self.updates += 1
"""


def box_urdf(name: str, plugin_filename: str) -> str:
    return f"""<robot name="{name}"><link name="body">
  <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
  </inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  <visual><geometry><box size="0.2 0.2 0.2"/></geometry></visual></link>
  <gazebo><plugin name="marker" filename="{plugin_filename}"/></gazebo></robot>"""


def box_sdf(name: str, plugin_filename: str) -> str:
    return f"""<sdf version="1.6"><model name="{name}"><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia>
  </inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
  </link><plugin name="marker" filename="{plugin_filename}"/></model></sdf>"""


@pytest.fixture
def marker_plugin(tmp_path):
    """``(plugin file, marker file)``: the file writes the marker when it is imported."""
    marker = tmp_path / "imported.marker"
    plugin = tmp_path / "outside" / "marker_plugin.py"
    plugin.parent.mkdir()
    plugin.write_text(MARKER_PLUGIN.format(marker=str(marker)))
    return plugin, marker


@pytest.fixture
def start_gazebo():
    started = []

    def start(allow_spawn_plugins: bool = False):
        bus = Bus()
        server = SimServer(
            World(**SERVER_PHYSICS),
            bus=bus,
            real_time_factor=0,
            allow_spawn_plugins=allow_spawn_plugins,
        )
        api = GazeboRosApi(server, Node("gazebo", bus=bus))
        client = Node("client", bus=bus)
        server.start()
        started.append((api, server, bus))
        return server, client

    yield start
    for api, server, bus in started:
        api.close()
        server.stop()
        bus.shutdown()


def spawn(client, name, xml, service):
    request = gm.SpawnModel.Request(model_name=name, model_xml=xml)
    request.initial_pose.position.z = 0.5
    request.initial_pose.orientation.w = 1.0
    return client.create_client(f"/gazebo/{service}", gm.SpawnModel).call(request, timeout=60)


def assert_still_serving(server, client):
    """The server steps on and answers a service after the refusal."""
    t0 = server.call(lambda: server.world.time)
    deadline = time.monotonic() + 60
    while server.call(lambda: server.world.time) < t0 + 0.05 and time.monotonic() < deadline:
        time.sleep(0.01)
    assert server.call(lambda: server.world.time) >= t0 + 0.05
    reply = client.create_client("/gazebo/get_world_properties", gm.GetWorldProperties).call(
        gm.GetWorldProperties.Request(), timeout=60
    )
    assert reply.success
    return reply.model_names


@pytest.mark.parametrize(
    ("service", "model"), [("spawn_urdf_model", box_urdf), ("spawn_sdf_model", box_sdf)]
)
def test_a_spawned_plugin_file_by_absolute_path_is_refused_unread(
    start_gazebo, marker_plugin, service, model
):
    server, client = start_gazebo()
    plugin, marker = marker_plugin
    reply = spawn(client, "intruder", model("intruder", str(plugin)), service)
    assert not reply.success
    assert reply.status_message.startswith(
        "SpawnModel: Failure - plugin 'marker' (" + str(plugin) + ") is not one the running "
        "world loaded"
    ), reply.status_message
    assert "--allow-spawn-plugins" in reply.status_message
    assert "\n" not in reply.status_message
    assert not marker.exists()
    assert "intruder" not in assert_still_serving(server, client)


@pytest.mark.parametrize("target", ["this:X", "json:JSONDecoder", "os:system"])
def test_a_spawned_module_class_that_no_package_declares_is_refused_unimported(
    start_gazebo, capfd, target
):
    server, client = start_gazebo()
    already = "this" in sys.modules
    reply = spawn(client, "zen", box_sdf("zen", target), "spawn_sdf_model")
    assert not reply.success
    assert f"'{target}' is not a declared plugin class" in reply.status_message
    assert f"'{ENTRY_POINT_GROUP}' entry point" in reply.status_message
    assert "zen" not in assert_still_serving(server, client)
    assert ("this" in sys.modules) == already
    assert "Beautiful is better than ugly" not in capfd.readouterr().out


def test_allow_spawn_plugins_lets_the_same_spawned_plugin_load(start_gazebo, marker_plugin):
    server, client = start_gazebo(allow_spawn_plugins=True)
    plugin, marker = marker_plugin
    reply = spawn(client, "guest", box_urdf("guest", str(plugin)), "spawn_urdf_model")
    assert (reply.success, reply.status_message) == (
        True,
        "SpawnModel: Successfully spawned entity",
    )
    assert marker.read_text() == "imported"
    assert any(label.startswith("marker (") for label in server.plugin_labels())
    assert "guest" in assert_still_serving(server, client)


def test_a_plugin_the_world_loaded_may_be_spawned_again(start_gazebo, marker_plugin):
    server, client = start_gazebo()
    plugin, marker = marker_plugin
    world_spec = PluginSpec(
        name="marker",
        filename="marker_plugin.py",
        element='<plugin name="marker" filename="marker_plugin.py"/>',
        kind="model",
        base_dir=plugin.parent,  # the world's folder: it may load its own plugin files
        source="test.world:3",
    )
    server.spawn(box_model("resident", plugins=[world_spec]), [0.0, 0.0, 0.5])
    assert marker.exists()
    reply = spawn(client, "visitor", box_urdf("visitor", str(plugin)), "spawn_urdf_model")
    assert reply.success, reply.status_message
    assert sum(label.startswith("marker (") for label in server.plugin_labels()) == 2


def test_workbench_plugins_load_in_spawned_models_without_permission(start_gazebo):
    """The gazebo_ros library names workbench maps to its own plugins and the shipped example
    files are workbench's code, not the user's: a spawned model may always use them."""
    server, client = start_gazebo()
    push = spawn(client, "push_box", (urdf_dir() / "push_box.urdf").read_text(), "spawn_urdf_model")
    assert push.success, push.status_message
    bot = spawn(client, "bot", (urdf_dir() / "custom_bot.urdf").read_text(), "spawn_urdf_model")
    assert bot.success, bot.status_message
    labels = server.plugin_labels()
    assert any("model_push.py" in label for label in labels), labels
    assert any("libgazebo_ros_diff_drive.so" in label for label in labels), labels


@pytest.fixture
def declared_plugins(tmp_path, monkeypatch):
    """An installed distribution declaring ``wbtest_declared:Declared`` as a plugin, and an
    undeclared module beside it; both write a marker when imported."""
    site = tmp_path / "site"
    info = site / "wbtest_plugins-0.1.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: wbtest-plugins\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(
        f"[{ENTRY_POINT_GROUP}]\nwbtest_declared = wbtest_declared:Declared\n"
    )
    markers = {}
    for module, cls in (("wbtest_declared", "Declared"), ("wbtest_undeclared", "Undeclared")):
        markers[module] = tmp_path / f"{module}.marker"
        text = MARKER_PLUGIN.format(marker=str(markers[module])).replace("Marker", cls)
        (site / f"{module}.py").write_text(text)
    monkeypatch.syspath_prepend(str(site))
    yield markers
    for module in markers:
        sys.modules.pop(module, None)


def test_declared_entry_points_load_in_worlds_and_then_in_spawns(start_gazebo, declared_plugins):
    server, client = start_gazebo()
    undeclared = spawn(client, "a", box_sdf("a", "wbtest_undeclared:Undeclared"), "spawn_sdf_model")
    assert not undeclared.success and "not a declared plugin class" in undeclared.status_message
    declared = spawn(client, "b", box_sdf("b", "wbtest_declared:Declared"), "spawn_sdf_model")
    assert not declared.success and "not one the running world" in declared.status_message
    assert not any(marker.exists() for marker in declared_plugins.values())
    world_spec = PluginSpec(
        name="declared",
        filename="wbtest_declared",  # the entry point's name
        element='<plugin name="declared" filename="wbtest_declared"/>',
        kind="model",
        base_dir=Path("/nonexistent-world-folder"),
        source="test.world:4",
    )
    server.spawn(box_model("resident", plugins=[world_spec]), [0.0, 0.0, 0.5])
    assert declared_plugins["wbtest_declared"].exists()
    again = spawn(client, "c", box_sdf("c", "wbtest_declared:Declared"), "spawn_sdf_model")
    assert again.success, again.status_message
    assert not declared_plugins["wbtest_undeclared"].exists()
    assert "c" in assert_still_serving(server, client)


def test_the_command_line_flag_reaches_the_server():
    import argparse

    from workbench.sim.gzserver import add_arguments

    parser = argparse.ArgumentParser()
    add_arguments(parser)
    assert options_from(parser.parse_args([])).allow_spawn_plugins is False
    options = options_from(parser.parse_args(["--allow-spawn-plugins", "--headless"]))
    assert options.allow_spawn_plugins is True
    _, server, _ = build_server(options)
    try:
        assert server.plugin_trust.allow_spawn_plugins is True
    finally:
        server.stop()
    _, server, _ = build_server(ServerOptions(view=False))
    try:
        assert server.plugin_trust.allow_spawn_plugins is False
    finally:
        server.stop()


@pytest.mark.parametrize(
    "case",
    [c for c in cases("plugins") if "this:X" in c["name"]],
    ids=lambda case: case["name"],
)
def test_this_is_never_imported_from_a_world_or_the_command_line(case, tmp_path):
    """``this:X`` would print the Zen of Python when imported: it is refused unimported."""
    already = "this" in sys.modules
    result = run_case(case, "plugins", tmp_path)
    assert "is not a declared plugin class" in result["stderr"]
    assert "Beautiful is better than ugly" not in result["stdout"]
    assert ("this" in sys.modules) == already
