"""Worlds as Gazebo writes and reads them: saved worlds, model folders in folders, nesting.

Worlds written here in the shapes of real ones: turtlebot3_gazebo's
``turtlebot3_autorace.world`` (``model://turtlebot3_autorace/traffic_stop``: a model
folder inside a folder; models written without a pose and placed by the world's
``<state>``; a state for a model the world lacks), husky's ``clearpath_playpen.world``
(saved from Gazebo: it declares its own ``ground_plane`` model) and
``turtlebot3_house.world`` (a static model with models nested in it). What is matched
(gazebo 11, physics/World.cc ``World::Load``): the first ``<state>`` is applied after
the models are loaded (model poses, link poses, joint angles); a state naming an
unknown model is skipped; the world's models are those libsdformat lists
(checked with it where it is installed).
"""

from __future__ import annotations

import logging
import math
from pathlib import Path

import numpy as np
import pytest
from gazebo_model_files import model_folder
from sdformat_oracle import run_oracle, session_checker

from workbench.bus import Bus
from workbench.errors import SimulationError
from workbench.sim.gzserver import ServerOptions, build_server
from workbench.sim.world_file import load_world


@pytest.fixture
def sdformat_checker(tmp_path_factory) -> Path:
    """libsdformat's checker (compiled once per session; skips without g++ and libsdformat-dev)."""
    return session_checker(tmp_path_factory)


INERTIAL = (
    "<inertial><mass>1</mass><inertia><ixx>0.01</ixx><ixy>0</ixy><ixz>0</ixz><iyy>0.01</iyy>"
    "<iyz>0</iyz><izz>0.01</izz></inertia></inertial>"
)


def box_link(name: str, pose: str, size: str = "0.2 0.2 0.2", inertial: bool = True) -> str:
    geometry = f"<geometry><box><size>{size}</size></box></geometry>"
    return (
        f"<link name='{name}'><pose frame=''>{pose}</pose>{INERTIAL if inertial else ''}"
        f"<collision name='{name}_collision'>{geometry}<max_contacts>10</max_contacts></collision>"
        f"<visual name='{name}_visual'>{geometry}<material><script>"
        "<uri>file://media/materials/scripts/gazebo.material</uri><name>Gazebo/Wood</name>"
        "</script></material></visual></link>"
    )


def link_state(name: str, pose: str) -> str:
    return (
        f"<link name='{name}'><pose frame=''>{pose}</pose><velocity>0 0 0 0 -0 0</velocity>"
        "<acceleration>0 0 0 0 -0 0</acceleration><wrench>0 0 0 0 -0 0</wrench></link>"
    )


@pytest.fixture
def race_models(tmp_path, monkeypatch) -> Path:
    """``race/course`` and ``race/traffic_stop`` as turtlebot3_autorace's folders hold them."""
    root = tmp_path / "models"
    for name, z in (("course", 0.0), ("traffic_stop", 0.5)):
        model_folder(
            root / "race",
            name,
            f"<?xml version='1.0'?><sdf version='1.5'><model name='{name}'><static>1</static>"
            f"{box_link('link', f'0 0 {z} 0 0 0', '0.3 0.3 0.1')}</model></sdf>",
            versions={"1.5": "model.sdf"},
        )
    model_folder(
        root,
        "sun",
        "<?xml version='1.0'?><sdf version='1.5'><light type='directional' name='sun'>"
        "<cast_shadows>true</cast_shadows><pose>0 0 10 0 0 0</pose>"
        "<diffuse>0.8 0.8 0.8 1</diffuse><direction>-0.5 0.1 -0.9</direction></light></sdf>",
        versions={"1.5": "model.sdf"},
    )
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(root))
    return root


def autorace_world(path: Path) -> Path:
    path.write_text(
        """<sdf version='1.6'>
  <world name='default'>
    <include><uri>model://sun</uri></include>
    <include><uri>model://race/course</uri></include>
    <include><uri>model://race/traffic_stop</uri><pose>3 1 0 0 0 1.5708</pose></include>
    <model name='ground2'><static>1</static>"""
        + box_link("ground", "0 0 -0.05 0 0 0", "10 10 0.1", inertial=False)
        + """</model>
    <model name='tunnel_wall'><static>1</static>"""
        + box_link("Wall_12", "1 0 0.25 0 0 0", "0.1 2 0.5")
        + box_link("Wall_13", "0 1 0.25 0 0 1.5708", "0.1 2 0.5")
        + """</model>
    <model name='arm'>"""
        + box_link("base", "0 0 0.1 0 0 0")
        + box_link("tip", "0 0 0.5 0 0 0")
        + """<joint name='hinge' type='revolute'><parent>base</parent><child>tip</child>
        <axis><xyz>0 1 0</xyz><limit><lower>-2</lower><upper>2</upper></limit></axis></joint>
    </model>
    <state world_name='default'>
      <sim_time>116 345000000</sim_time><real_time>32 693566475</real_time>
      <wall_time>1525097329 747995208</wall_time><iterations>32558</iterations>
      <model name='ground2'><pose frame=''>0 0 0 0 -0 0</pose><scale>1 1 1</scale>"""
        + link_state("ground", "0 0 -0.05 0 -0 0")
        + """</model>
      <model name='tunnel_wall'><pose frame=''>-1.04 -1.13 0 0 -0 0.5</pose><scale>1 1 1</scale>"""
        + link_state("Wall_12", "-0.2 -1.6 0.25 0 -0 0.5")
        + link_state("Wall_13", "-1.5 -0.5 0.25 0 -0 2.0708")
        + """</model>
      <model name='arm'><pose frame=''>2 -2 0 0 0 0</pose>
        <joint name='hinge'><angle axis='0'>0.4</angle></joint></model>
      <model name='unit_box'><pose frame=''>5 5 0.5 0 -0 0</pose></model>
      <light name='sun'><pose frame=''>0 0 10 0 -0 0</pose></light>
    </state>
  </world>
</sdf>
"""
    )
    return path


def test_model_folders_in_folders_and_the_state_of_a_saved_world(race_models, tmp_path, caplog):
    path = autorace_world(tmp_path / "race.world")
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        world, _, _ = build_server(ServerOptions(world=str(path), view=False), Bus())
    world.build()
    assert world.model_names() == ["course", "traffic_stop", "ground2", "tunnel_wall", "arm"]
    assert any(
        "'unit_box', which the world does not have: skipped" in r.getMessage()
        for r in caplog.records
    )
    stop = world.get_model_pose("traffic_stop")
    np.testing.assert_allclose(stop.translation(), [3.0, 1.0, 0.0], atol=1e-12)
    wall = world.get_model_pose("tunnel_wall")
    np.testing.assert_allclose(wall.translation(), [-1.04, -1.13, 0.0], atol=1e-9)
    # link poses in the state are in the world frame and win over the file's own
    for link, xyz in (("Wall_12", [-0.2, -1.6, 0.25]), ("Wall_13", [-1.5, -0.5, 0.25])):
        X = world.plant.EvalBodyPoseInWorld(
            world.plant.GetMyContextFromRoot(world.context), world.body(f"tunnel_wall::{link}")
        )
        np.testing.assert_allclose(X.translation(), xyz, atol=1e-9)
    hinge = world.joint("arm", "hinge")
    q = world.plant.GetPositions(world.plant.GetMyContextFromRoot(world.context))
    assert q[hinge.position_start()] == pytest.approx(0.4)
    np.testing.assert_allclose(world.get_model_pose("arm").translation(), [2, -2, 0], atol=1e-9)


def test_the_world_models_are_those_libsdformat_lists(sdformat_checker, race_models, tmp_path):
    path = autorace_world(tmp_path / "race.world")
    oracle = run_oracle(sdformat_checker, path, str(race_models))
    assert oracle.accepted, oracle.errors
    ours = [m.model.name for m in load_world(path).models]
    assert ours == [m.name for m in oracle.world_models]
    for ours_model, theirs in zip(load_world(path).models, oracle.world_models, strict=True):
        assert sorted(theirs.links) == sorted(
            link.replace("\u2237", "::") for link in _links(ours_model.model.text)
        )


def _links(text: str) -> list[str]:
    from lxml import etree

    return [link.get("name") for link in etree.fromstring(text.encode()).iter("link")]


def playpen_world(path: Path) -> Path:
    plane = "<geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>"
    path.write_text(
        f"""<sdf version='1.6'>
  <world name='default'>
    <light name='sun' type='directional'><pose frame=''>0 0 10 0 -0 0</pose></light>
    <model name='ground_plane'>
      <static>1</static>
      <link name='link'>
        <collision name='collision'>{plane}<surface><friction><ode><mu>100</mu><mu2>50</mu2>
          </ode></friction><bounce/><contact><ode/></contact></surface><max_contacts>10</max_contacts>
        </collision>
        <visual name='visual'><cast_shadows>0</cast_shadows>{plane}</visual>
        <self_collide>0</self_collide><kinematic>0</kinematic><gravity>1</gravity>
      </link>
    </model>
    <physics type='ode'><max_step_size>0.01</max_step_size><real_time_factor>1</real_time_factor>
      <real_time_update_rate>100</real_time_update_rate><gravity>0 0 -9.8</gravity></physics>
    <model name='barrel'>{box_link("link", "0 0 0.3 0 0 0", "0.4 0.4 0.6")}</model>
    <state world_name='default'>
      <sim_time>1298 470000000</sim_time>
      <model name='barrel'><pose frame=''>4.5 -2.2 0 0 0 0.3</pose>{link_state("link", "4.5 -2.2 0.3 0 0 0.3")}</model>
      <model name='ground_plane'><pose frame=''>0 0 0 0 -0 0</pose>{link_state("link", "0 0 0 0 -0 0")}</model>
    </state>
  </world>
</sdf>
"""
    )
    return path


def test_a_world_saved_from_gazebo_declares_its_ground_plane(tmp_path):
    path = playpen_world(tmp_path / "playpen.world")
    read = load_world(path)
    assert read.ground_plane and read.ground_z == 0.0
    assert [m.model.name for m in read.models] == ["barrel"]
    world, server, _ = build_server(ServerOptions(world=str(path), view=False, fast=True), Bus())
    assert world.model_names() == ["ground_plane", "barrel"]
    server.run(until=0.5)
    X = world.get_model_pose("barrel")
    np.testing.assert_allclose(
        X.translation(), [4.5, -2.2, 0.0], atol=2e-3
    )  # resting on the ground
    assert math.atan2(X.rotation().matrix()[1, 0], X.rotation().matrix()[0, 0]) == pytest.approx(
        0.3, abs=1e-3
    )
    server.stop()


def test_a_static_model_with_models_nested_in_it_as_turtlebot3_house(tmp_path):
    path = tmp_path / "house.world"
    furniture = "".join(
        f"<model name='{name}'>{'<static>1</static>' if static else ''}"
        f"{box_link('link', '0 0 0.3 0 0 0', '0.4 0.4 0.6')}<pose frame=''>{x} {y} 0 0 0 0</pose></model>"
        for name, static, x, y in (("Mailbox", False, 0.9, -0.6), ("bookshelf", True, -3, 1.2))
    )
    path.write_text(
        f"""<sdf version='1.6'><world name='default'>
  <include><uri>model://ground_plane</uri></include>
  <model name='house'>{box_link("Wall_101", "0 3.1 1.25 0 0 0", "4.5 0.15 2.5")}{furniture}
    <static>1</static></model>
</world></sdf>"""
    )
    world, server, _ = build_server(ServerOptions(world=str(path), view=False, fast=True), Bus())
    server.run(until=0.3)
    context = world.plant.GetMyContextFromRoot(world.context)
    mailbox = world.body("house::Mailbox::link")
    assert mailbox.is_floating_base_body()  # it has no <static>: it may be pushed
    assert not world.body("house::bookshelf::link").is_floating_base_body()
    np.testing.assert_allclose(
        world.plant.EvalBodyPoseInWorld(context, mailbox).translation(), [0.9, -0.6, 0.3], atol=2e-3
    )
    names = [name for name, _, _ in world.link_states()]
    assert {"house::Wall_101", "house::Mailbox::link", "house::bookshelf::link"} <= set(names)
    server.stop()


def test_population_is_refused_in_one_line(tmp_path):
    path = tmp_path / "population.world"
    path.write_text(
        "<sdf version='1.6'><world name='default'>\n<population name='cans'>"
        "<model name='can'><link name='l'/></model><pose>0 0 0 0 0 0</pose>"
        "<box><size>2 2 0.01</size></box><model_count>5</model_count>"
        "<distribution><type>random</type></distribution></population></world></sdf>"
    )
    with pytest.raises(SimulationError) as caught:
        load_world(path)
    assert str(caught.value).startswith(f"{path}:2: <population> 'cans' is not supported")


def test_check_resolves_model_uris_through_gazebo_model_path_as_sim_does(
    race_models, tmp_path, run_cli, monkeypatch
):
    path = tmp_path / "station.sdf"
    path.write_text(
        "<sdf version='1.6'><model name='station'>"
        + box_link("base", "0 0 0.1 0 0 0")
        + "<include><uri>model://race/traffic_stop</uri><name>sign</name><pose>1 0 0 0 0 0</pose>"
        "</include><joint name='mount' type='fixed'><parent>base</parent><child>sign::link</child>"
        "</joint></model></sdf>"
    )
    checked = run_cli("check", path, env={"GAZEBO_MODEL_PATH": str(race_models)})
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "child(1):  sign::link" in checked.stdout
    lost = run_cli("check", path, env={"GAZEBO_MODEL_PATH": str(tmp_path / "elsewhere")})
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path / "elsewhere"))
    with pytest.raises(SimulationError) as caught:
        from workbench.sim.loading import load_sim_model

        load_sim_model(path)
    assert lost.returncode == 1
    assert "cannot resolve model://race/traffic_stop: no model 'race/traffic_stop'" in lost.stderr
    assert "cannot resolve model://race/traffic_stop: no model 'race/traffic_stop'" in str(
        caught.value
    )
    assert "Traceback" not in lost.stderr and lost.stderr.strip().count("\n") == 0
