"""Gazebo's URDF extensions, SDF models and world files, read into what the simulator loads."""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import SimulationError
from workbench.model import RobotDescription
from workbench.sim import World
from workbench.sim.gazebo_sdf import sim_model_from_sdf
from workbench.sim.gazebo_urdf import GAZEBO_COLOURS, sim_model_from_urdf
from workbench.sim.loading import load_sim_model, sim_model_from_xml
from workbench.sim.server import SERVER_PHYSICS
from workbench.sim.world_file import load_world, shipped_worlds


def _load_quietly(model, caplog) -> World:
    """Load into a fresh world; fail if Drake warned about anything."""
    world = World(**SERVER_PHYSICS)
    with caplog.at_level(logging.WARNING, logger="drake"):
        world.add_model(model, [0.0, 0.0, 1.0])
        world.build()
    drake = [r.getMessage() for r in caplog.records if r.name == "drake"]
    assert drake == []
    return world


def test_simple_box_loads_with_one_warning_that_names_the_inertia_fix(caplog):
    model = load_sim_model("simple_box", name="my_object")
    assert model.name == "my_object" and model.root_link == "my_box"
    assert len(model.warnings) == 1
    assert (
        "link 'my_box': inertia ixx=1 iyy=100 izz=1 breaks the triangle inequality"
        in (model.warnings[0])
    )
    assert "using ixx=50 iyy=100 izz=50" in model.warnings[0]
    assert "<gazebo" not in model.text
    world = _load_quietly(model, caplog)
    body = world.plant.GetBodyByName("my_box")
    inertia = body.default_rotational_inertia().CalcPrincipalMomentsOfInertia()
    # (50, 100, 50) about the centre of mass, which is 2 m along x from the link origin
    np.testing.assert_allclose(sorted(inertia), [50.0, 54.0, 104.0], rtol=1e-6)


def test_gazebo_material_colours_reach_drakes_illustration(caplog):
    world = _load_quietly(load_sim_model("simple_box"), caplog)
    from pydrake.geometry import Role

    inspector = world.scene_graph.model_inspector()
    body = world.plant.GetBodyByName("my_box")
    frame = world.plant.GetBodyFrameIdOrThrow(body.index())
    (geometry,) = inspector.GetGeometries(frame, Role.kIllustration)
    rgba = inspector.GetIllustrationProperties(geometry).GetProperty("phong", "diffuse")
    np.testing.assert_allclose(
        [rgba.r(), rgba.g(), rgba.b(), rgba.a()], GAZEBO_COLOURS["Gazebo/Blue"]
    )


def test_mu_kp_kd_reach_drakes_proximity_properties(caplog):
    text = (Path(__file__).parents[2] / "urdf" / "simple_box.urdf").read_text()
    text = text.replace(
        "<material>Gazebo/Blue</material>",
        "<material>Gazebo/Blue</material><mu1>0.3</mu1><mu2>0.5</mu2><kp>1e6</kp><kd>100</kd>",
    )
    model = sim_model_from_urdf(RobotDescription.from_text(text), "box")
    world = _load_quietly(model, caplog)
    from pydrake.geometry import Role

    inspector = world.scene_graph.model_inspector()
    body = world.plant.GetBodyByName("my_box")
    (geometry,) = [
        g
        for g in inspector.GetGeometries(
            world.plant.GetBodyFrameIdOrThrow(body.index()), Role.kProximity
        )
        if "_corner_" not in inspector.GetName(g)
    ]
    properties = inspector.GetProximityProperties(geometry)
    friction = properties.GetProperty("material", "coulomb_friction")
    assert friction.dynamic_friction() == pytest.approx(0.4)  # mean of mu1 and mu2
    assert properties.GetProperty("material", "point_contact_stiffness") == pytest.approx(1e6)
    # kd / (kp * 1 mm)
    assert properties.GetProperty("material", "hunt_crossley_dissipation") == pytest.approx(0.1)


def test_static_self_collide_gravity_plugins_and_sensors_are_lifted_out():
    text = """<robot name="r">
  <link name="a"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="b"/>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
  <gazebo><static>true</static><selfCollide>true</selfCollide>
    <plugin name="p" filename="model_push.py"><x>1</x></plugin></gazebo>
  <gazebo reference="b"><gravity>0</gravity>
    <sensor type="ray" name="laser"><plugin name="l" filename="libgazebo_ros_laser.so"/></sensor>
  </gazebo>
</robot>"""
    model = sim_model_from_xml(text, name="r2", source="test")
    assert model.name == "r2" and model.static and model.self_collide
    assert model.gravity  # off on one link of two: kept, with a warning
    assert any("gravity" in w and "stays on" in w for w in model.warnings)
    assert [(p.name, p.kind, p.reference) for p in model.plugins] == [
        ("p", "model", None),
        ("l", "sensor", "b"),
    ]
    assert model.sensors[0][0] == "b" and "<sensor" in model.sensors[0][1]
    assert "<gazebo" not in model.text and "<plugin" not in model.text


def test_a_link_without_inertia_in_a_free_model_gets_sdformats_default():
    text = '<robot name="r"><link name="a"><collision><geometry><sphere radius="0.1"/></geometry></collision></link></robot>'
    model = sim_model_from_xml(text, name=None, source="test.urdf")
    assert model.warnings == [
        "test.urdf: link 'a' has no <inertial>; using SDFormat's default (1 kg, 1 kg m^2), "
        "as Gazebo does for SDF"
    ]
    world = World(**SERVER_PHYSICS)
    world.add_model(model, [0, 0, 1])
    world.build()
    world.advance_to(0.2)
    assert world.get_model_pose("r").translation()[2] < 1.0  # it falls


def test_sdf_models_keep_their_pose_static_flag_and_plugins(caplog):
    text = """<sdf version="1.7"><model name="crate"><pose>1 2 0.5 0 0 0</pose><static>true</static>
  <link name="l"><collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision>
    <visual name="v"><geometry><box><size>1 1 1</size></box></geometry></visual></link>
  <plugin name="p" filename="model_push.py"/></model></sdf>"""
    model = sim_model_from_sdf(text, name="shelf", source="crate.sdf")
    assert model.name == "shelf" and model.static
    assert model.pose == (1.0, 2.0, 0.5, 0.0, 0.0, 0.0)
    assert [p.name for p in model.plugins] == ["p"]
    world = _load_quietly(model, caplog)
    world.advance_to(0.3)
    # placed at (0, 0, 1) composed with its own pose, and welded there
    np.testing.assert_allclose(world.get_model_pose("shelf").translation(), [1.0, 2.0, 1.5])


def test_the_shipped_worlds_load_with_their_models_and_plugins():
    assert {"empty", "model_push", "velodyne"} <= set(shipped_worlds())
    empty = load_world("empty")
    assert empty.ground_plane and empty.models == [] and empty.physics.time_step == 0.001
    assert load_world("worlds/empty.world").path == empty.path  # Gazebo's name for it
    velodyne = load_world("velodyne")
    (item,) = velodyne.models
    assert item.model.name == "my_velodyne"
    assert [p.filename for p in item.model.plugins] == ["velocity_controller.py"]


def test_model_uris_resolve_in_gazebo_model_path_with_include_overrides(tmp_path, monkeypatch):
    folder = tmp_path / "models" / "crate"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text(
        "<model><name>crate</name><sdf version='1.6'>crate.sdf</sdf></model>"
    )
    (folder / "crate.sdf").write_text(
        "<sdf version='1.6'><model name='crate'><pose>0 0 5 0 0 0</pose><link name='l'>"
        "<collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>"
        "</link></model></sdf>"
    )
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path / "models"))
    world_path = tmp_path / "w.world"
    world_path.write_text(
        "<sdf version='1.6'><world name='w'><include><uri>model://ground_plane</uri></include>"
        "<include><uri>model://crate</uri><name>box_a</name><pose>1 0 0.1 0 0 0</pose></include>"
        "<include><uri>model://small_box</uri></include>"
        "<physics type='ode'><max_step_size>0.002</max_step_size></physics>"
        "<gravity>0 0 -1.62</gravity></world></sdf>"
    )
    world = load_world(world_path)
    assert [(m.model.name, m.pose[:3]) for m in world.models] == [
        ("box_a", (1.0, 0.0, 0.1)),
        ("small_box", (0.0, 0.0, 0.0)),
    ]
    assert world.models[0].model.pose == (0.0,) * 6  # the include's pose replaces the model's
    assert world.physics.time_step == 0.002 and world.physics.gravity == (0.0, 0.0, -1.62)


@pytest.mark.parametrize(
    "text, message",
    [
        ("this is not xml", "not an XML world file"),
        ("<robot name='r'/>", "not an SDF world: the root is <robot>"),
        (
            "<sdf><world name='w'><include><uri>model://no_such_model</uri></include></world></sdf>",
            "cannot resolve model://no_such_model: no model 'no_such_model'",
        ),
        (
            "<sdf><world name='w'><model name='m'><pose>0 0 nan 0 0 0</pose><link name='l'/></model></world></sdf>",
            "model 'm' <pose>: 0 0 nan 0 0 0 holds nan, which is not a finite number",
        ),
        (
            "<sdf><world name='w'><model name='m'><pose>0 0 0 0 0 0 0</pose><link name='l'/>"
            "</model></world></sdf>",
            "<pose> must be six finite numbers",
        ),
        ("<sdf><world name='w'><model name='empty'/></world></sdf>", "model 'empty' has no <link>"),
    ],
)
def test_bad_world_files_are_one_line_errors_with_file_and_line(tmp_path, text, message):
    path = tmp_path / "bad.world"
    path.write_text(text)
    with pytest.raises(SimulationError) as caught:
        load_world(path)
    line = str(caught.value)
    assert message in line and str(path) in line and "\n" not in line


def test_unknown_world_names_list_the_shipped_ones():
    with pytest.raises(SimulationError, match="unknown world 'nowhere'.*empty"):
        load_world("nowhere")
    with pytest.raises(SimulationError, match="world file 'gone.world' not found"):
        load_world("gone.world")


def test_a_urdf_without_links_and_a_non_model_are_refused():
    with pytest.raises(SimulationError, match="no <link>|at least one link|no links"):
        sim_model_from_xml('<robot name="empty"></robot>', name="x", source="spawn request 'x'")
    with pytest.raises(SimulationError, match="neither URDF"):
        sim_model_from_xml("<html/>", name="x", source="spawn request 'x'")
    with pytest.raises(SimulationError, match="neither URDF"):
        sim_model_from_xml("not xml at all", name="x", source="spawn request 'x'")


def _friction(mu: str) -> str:
    return (
        '<sdf version="1.6"><model name="crate"><link name="body"><inertial><mass>1</mass>'
        "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>"
        '<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry>'
        f"<surface><friction><ode>{mu}</ode></friction></surface></collision>"
        "</link></model></sdf>"
    )


@pytest.mark.parametrize(
    ("mu", "expected"),
    [("<mu>0.8</mu>", 0.8), ("<mu>0.4</mu><mu2>0.8</mu2>", 0.6), ("<mu2>1.5</mu2>", 1.5)],
)
def test_sdf_friction_becomes_the_mean_of_mu_and_mu2(mu, expected):
    from lxml import etree

    model = sim_model_from_sdf(_friction(mu), name=None, source="test")
    ode = etree.fromstring(model.text.encode()).find(".//friction/ode")
    assert float(ode.findtext("mu")) == pytest.approx(expected)
    assert float(ode.findtext("mu2")) == pytest.approx(expected)
    world = World(**SERVER_PHYSICS)
    world.add_model(model)  # Drake refused <mu>0.8</mu> alone: dynamic (1) above static
    world.build()


def test_a_static_model_saved_with_nan_inertia_loads_as_gazebo_loads_it(tmp_path):
    # worlds saved from Gazebo write <ixx>nan</ixx> for massless static walls
    path = tmp_path / "walls.world"
    path.write_text(
        "<sdf version='1.6'><world name='w'><model name='walls'><static>1</static>"
        "<link name='wall'><inertial><mass>0</mass><inertia><ixx>nan</ixx><iyy>nan</iyy>"
        "<izz>nan</izz></inertia></inertial><collision name='c'><geometry><box>"
        "<size>1 0.1 0.5</size></box></geometry></collision></link></model></world></sdf>"
    )
    world = World(**SERVER_PHYSICS)
    for item in load_world(path).models:
        world.add_model(item.model)
    world.build()
    path.write_text(path.read_text().replace("<static>1</static>", ""))
    with pytest.raises(SimulationError, match=r"walls.world:1: link 'wall' .*nan is not a finite"):
        load_world(path)
