"""SDF models and worlds as libsdformat reads them, and as workbench loads them.

libsdformat 12 (Debian's libsdformat12, the library behind Gazebo's SDFormat) loads
each file through a small C++ program (``sdformat/sdformat_check.cc``, built at test
time) and decides whether it is valid; workbench loads the same file into Drake the
way ``workbench sim`` does. Files written in the shapes of real ones (gazebo_models'
``turtlebot``, ``simple_arm_gripper``, ``drc_practice_ball_valve_wall`` and
``create``; turtlebot3_gazebo's ``turtlebot3_house``, ``turtlebot3_autorace`` and
``clearpath_playpen``) and 40 models from a seeded generator are compared on:

* validity: libsdformat reports no error exactly when workbench loads the file
  (a refusal is one line naming the file);
* names: the models, and every link and joint, nested models' ones named
  ``NESTED::NAME`` as Gazebo names the links of an included model; a joint named
  like a link keeps its name in workbench (Gazebo's physics reads the element
  tree) where libsdformat's DOM calls it ``NAME_joint`` with a warning;
* geometry: each link's pose in its model (nested models' poses composed) and each
  joint's axis in the model frame (``use_parent_model_frame``, SDFormat 1.4's
  model-frame axes and ``expressed_in`` resolved), to 1e-9.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from gazebo_model_files import model_folder
from sdformat_oracle import OracleModel, run_oracle, session_checker

from workbench.errors import SimulationError
from workbench.model.sdf_names import shown_name
from workbench.sim import World
from workbench.sim.loading import load_sim_model
from workbench.sim.server import SERVER_PHYSICS
from workbench.spatial import pose_matrix


@pytest.fixture
def sdformat_checker(tmp_path_factory) -> Path:
    """libsdformat's checker (compiled once per session; skips without g++ and libsdformat-dev)."""
    return session_checker(tmp_path_factory)


RANDOM_CASES = 40
_INERTIAL = (
    "<inertial><mass>1</mass><inertia><ixx>0.01</ixx><ixy>0</ixy><ixz>0</ixz><iyy>0.01</iyy>"
    "<iyz>0</iyz><izz>0.01</izz></inertia></inertial>"
)
_ONE_DOF = {"revolute", "prismatic", "continuous"}


def link(name: str, pose: str = "0 0 0 0 0 0") -> str:
    return (
        f"<link name='{name}'><pose>{pose}</pose>{_INERTIAL}"
        "<collision name='c'><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>"
        "</link>"
    )


def joint(name: str, kind: str, parent: str, child: str, axis: str = "") -> str:
    return (
        f"<joint name='{name}' type='{kind}'><parent>{parent}</parent><child>{child}</child>"
        f"{axis}</joint>"
    )


def axis_xml(xyz: str, version: str, in_model: bool) -> str:
    """An axis with finite limits; ``in_model``: given in the model frame as ``version`` writes it."""
    limit = "<limit><lower>-1</lower><upper>1</upper></limit>"
    if not in_model or version == "1.4":  # 1.4 axes are in the model frame anyway
        return f"<axis><xyz>{xyz}</xyz>{limit}</axis>"
    if version in ("1.5", "1.6"):
        return f"<axis><xyz>{xyz}</xyz><use_parent_model_frame>true</use_parent_model_frame>{limit}</axis>"
    return f"<axis><xyz expressed_in='__model__'>{xyz}</xyz>{limit}</axis>"


def sdf(version: str, body: str) -> str:
    return f"<?xml version='1.0'?>\n<sdf version='{version}'>\n{body}\n</sdf>\n"


# --- workbench's side ------------------------------------------------------------------


def workbench_model(path: Path) -> OracleModel:
    """What workbench loads: links (pose in the model frame) and joints, by Gazebo name."""
    model = load_sim_model(path)
    world = World(**SERVER_PHYSICS, ground=False)
    world.add_model(model)
    world.build()
    plant = world.plant
    context = plant.GetMyContextFromRoot(world.context)
    instance = world.model_instance(model.name)
    X_MW = np.linalg.inv(pose_matrix(model.pose[:3], rpy=model.pose[3:]))
    result = OracleModel(model.name)
    for index in plant.GetBodyIndices(instance):
        body = plant.get_body(index)
        X_WB = plant.EvalBodyPoseInWorld(context, body).GetAsMatrix4()
        result.links[shown_name(body.name())] = X_MW @ X_WB
    for index in plant.GetJointIndices(instance):
        item = plant.get_joint(index)
        kind = item.type_name()
        if kind in ("quaternion_floating", "rpy_floating") or item.name().startswith(
            "world_welds_to_"
        ):
            continue  # how the simulator frees or welds a model's roots, not the file's joints
        axis = None
        if kind in ("revolute", "prismatic"):
            local = item.revolute_axis() if kind == "revolute" else item.translation_axis()
            R_WF = item.frame_on_parent().CalcPoseInWorld(context).rotation().matrix()
            axis = X_MW[:3, :3] @ R_WF @ np.asarray(local)
        parent = item.parent_body()
        parent_name = "world" if parent.index() == plant.world_body().index() else parent.name()
        result.joints[shown_name(item.name())] = (
            shown_name(parent_name),
            shown_name(item.child_body().name()),
            axis,
        )
    return result


def assert_same(oracle: OracleModel, ours: OracleModel) -> None:
    assert ours.name == oracle.name
    assert sorted(ours.links) == sorted(oracle.links)
    for name, X in oracle.links.items():
        np.testing.assert_allclose(ours.links[name], X, atol=1e-9, err_msg=f"link {name}")
    assert sorted(ours.joints) == sorted(oracle.joints)
    for name, (parent, child, axis) in oracle.joints.items():
        our_parent, our_child, our_axis = ours.joints[name]
        assert (our_parent, our_child) == (parent, child), name
        if axis is not None and our_axis is not None:
            np.testing.assert_allclose(
                our_axis, axis / np.linalg.norm(axis), atol=1e-9, err_msg=f"axis of {name}"
            )


def compare(checker: Path, path: Path, models: Path | None = None) -> OracleModel:
    oracle = run_oracle(checker, path, str(models or ""))
    assert oracle.accepted, oracle.errors
    assert oracle.model is not None
    assert_same(oracle.model, workbench_model(path))
    return oracle.model


# --- files in the shapes of real ones -------------------------------------------------------


@pytest.fixture
def models(tmp_path, monkeypatch) -> Path:
    """A GAZEBO_MODEL_PATH folder with models in the shapes of gazebo_models' create and kinect."""
    root = tmp_path / "models"
    wheels = "".join(
        link(f"{side}_wheel", f"0 {y} 0.032 0 1.5707 1.5707")
        + joint(
            f"{side}_wheel", "revolute", "base", f"{side}_wheel", axis_xml("0 1 0", "1.5", True)
        )
        for side, y in (("left", 0.13), ("right", -0.13))
    )
    model_folder(
        root,
        "create",
        sdf("1.5", f"<model name='create'>{link('base', '0 0 0.0614 0 0 0')}{wheels}</model>"),
        versions={"1.5": "model.sdf"},
    )
    model_folder(
        root,
        "kinect",
        sdf("1.4", f"<model name='kinect'><pose>0 0 0.036 0 0 0</pose>{link('link')}</model>"),
        versions={"1.4": "model.sdf"},
    )
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(root))
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))
    return root


def test_a_robot_made_of_included_models_as_gazebo_models_turtlebot(
    sdformat_checker, models, tmp_path
):
    path = tmp_path / "turtlebot.sdf"
    path.write_text(
        sdf(
            "1.5",
            "<model name='turtlebot'>"
            "<include><uri>model://create</uri></include>"
            + link("rack", "0.001 0 0.03 0 0 0")
            + "<include><uri>model://kinect</uri><pose>-0.087 -0.0125 0.287 0 0 0</pose></include>"
            + joint(
                "create_rack", "revolute", "create::base", "rack", axis_xml("0 0 1", "1.5", True)
            )
            + joint(
                "kinect_rack", "revolute", "kinect::link", "rack", axis_xml("0 0 1", "1.5", True)
            )
            + "</model>",
        )
    )
    oracle = run_oracle(sdformat_checker, path, str(models))
    # libsdformat calls a joint named like a link NAME_joint, with a warning; Gazebo keeps the name
    assert any("changing joint name to [left_wheel_joint]" in w for w in oracle.warnings)
    model = compare(sdformat_checker, path, models)
    assert "create::left_wheel" in model.joints and "create::left_wheel" in model.links
    assert "kinect::link" in model.links


def test_a_model_of_only_includes_joined_by_a_joint_as_simple_arm_gripper(
    sdformat_checker, models, tmp_path
):
    path = tmp_path / "arm_gripper.sdf"
    path.write_text(
        sdf(
            "1.6",
            "<model name='arm_gripper'>"
            "<include><uri>model://kinect</uri><name>arm</name></include>"
            "<include><uri>model://create</uri><pose>1.8 0 1 0 0 0.3</pose></include>"
            "<plugin name='p' filename='libJointTrajectoryPlugin.so'/>"
            + joint(
                "arm_gripper_joint",
                "revolute",
                "arm::link",
                "create::base",
                axis_xml("0 0 1", "1.6", True),
            )
            + "</model>",
        )
    )
    compare(sdformat_checker, path, models)
    model = load_sim_model(path)
    assert model.root_link is not None and shown_name(model.root_link) == "arm::link"
    assert [p.name for p in model.plugins] == ["p"]


def test_a_wall_included_and_jointed_to_the_world_as_drc_practice_valve_walls(
    sdformat_checker, models, tmp_path
):
    path = tmp_path / "valve_wall.sdf"
    path.write_text(
        sdf(
            "1.5",
            "<model name='ball_valve_wall'>"
            "<include><uri>model://kinect</uri><name>wall</name><static>false</static></include>"
            + joint("wall-joint", "revolute", "world", "wall::link", axis_xml("0 0 1", "1.5", True))
            + "".join(
                f"<include><uri>model://kinect</uri><name>valve_{k}</name>"
                f"<pose>0.9 -0.0092 {0.285 + 0.6 * k} 0 0 0</pose></include>"
                for k in range(3)
            )
            + "</model>",
        )
    )
    compare(sdformat_checker, path, models)


def test_models_nested_inline_with_their_own_static_as_turtlebot3_house(
    sdformat_checker, models, tmp_path
):
    furniture = "".join(
        f"<model name='{name}'>{'<static>1</static>' if static else ''}{link('link', pose)}"
        f"<pose frame=''>{where}</pose></model>"
        for name, static, pose, where in (
            ("Mailbox", False, "0 0 0 0 0 0", "0.883462 -0.576236 0 0 0 -3.14159"),
            ("bookshelf", True, "0 0.005 0.6 0 -0 0", "-7.18363 1.24799 0 0 0 -1.5708"),
            ("table", False, "0 0 0.4 0 0 0", "-2.65728 2.42376 0 0 -0 0"),
        )
    )
    path = tmp_path / "house.sdf"
    path.write_text(
        sdf(
            "1.6",
            "<model name='house'>"
            + link("Wall_101", "-0.05 3.1 0 0 0 -1.5708")
            + link("Wall_104", "4 0 0 0 0 0")
            + furniture
            + "<static>1</static><allow_auto_disable>1</allow_auto_disable></model>",
        )
    )
    compare(sdformat_checker, path, models)
    model = load_sim_model(path)
    # the house is static, its furniture moves unless it says <static>
    assert model.static
    assert {shown_name(k): v for k, v in model.static_links.items()} == {
        "Mailbox::link": False,
        "table::link": False,
    }


def test_revolute2_wheels_move_as_universal_joints_as_utility_cart(sdformat_checker, tmp_path):
    path = tmp_path / "cart.sdf"
    steer = (
        "<axis><xyz>0 0 1</xyz><limit><lower>-0.8727</lower><upper>0.8727</upper></limit>"
        "<use_parent_model_frame>true</use_parent_model_frame></axis>"
        "<axis2><xyz>0 1 0</xyz><use_parent_model_frame>true</use_parent_model_frame></axis2>"
    )
    path.write_text(
        sdf(
            "1.5",
            "<model name='car'>"
            + link("chassis", "0 0 0.6 0 0 0")
            + link("front_left_wheel", "1.2 0.6 0.3 0 1.5707 1.5707")
            + "<joint type='revolute2' name='front_left_joint'><parent>chassis</parent>"
            "<child>front_left_wheel</child>" + steer + "<physics><ode><suspension><cfm>0.3"
            "</cfm><erp>0.4</erp></suspension></ode></physics></joint></model>",
        )
    )
    compare(sdformat_checker, path)
    model = load_sim_model(path)
    assert any("'front_left_joint' moves as a universal joint" in w for w in model.warnings)
    world = World(**SERVER_PHYSICS)
    world.add_model(model)
    world.build()
    joint = world.joint("car", "front_left_joint")
    assert joint.type_name() == "universal" and joint.num_positions() == 2


def test_xml_that_libsdformat_forgives_is_read_and_broken_xml_refused(sdformat_checker, tmp_path):
    path = tmp_path / "pit.sdf"
    path.write_text(
        "\n<?xml version='1.0' ?>\n<sdf version='1.5'>\n<model name='pit'><static>true</static>\n"
        "<!-- Mass computed using density of aluminum foil (2700Kg/m3)\n"
        "<!-- divided by 4 because the door is probably not solid. -->\n"
        + link("link")
        + "</model></sdf>\n"
    )
    compare(sdformat_checker, path)
    broken = tmp_path / "broken.sdf"
    broken.write_text("<sdf version='1.5'><model name=m><link name='l'/></model></sdf>")
    assert not run_oracle(sdformat_checker, broken).accepted
    with pytest.raises(SimulationError, match="not valid XML"):
        workbench_model(broken)


# --- generated models -------------------------------------------------------------------


def _pose_text(rng: np.random.Generator) -> str:
    xyz = rng.uniform(-1.0, 1.0, 3)
    rpy = rng.uniform(-math.pi, math.pi, 3) * rng.choice([0.0, 1.0])
    return " ".join(f"{v:.6f}" for v in (*xyz, *rpy))


def _axis(rng: np.random.Generator) -> str:
    vector = rng.normal(size=3) if rng.random() < 0.5 else np.eye(3)[rng.integers(3)]
    return " ".join(f"{v:.6f}" for v in vector / np.linalg.norm(vector))


def _model_body(
    rng: np.random.Generator, version: str, prefix: str, count: int
) -> tuple[str, list[str]]:
    """Links ``{prefix}l0..`` in a random tree of joints (some named like their child link)."""
    names = [f"{prefix}l{k}" for k in range(count)]
    body = "".join(link(n, _pose_text(rng)) for n in names)
    for k in range(1, count):
        kind = str(rng.choice(["revolute", "prismatic", "fixed"]))
        clash = version in ("1.4", "1.5", "1.6") and rng.random() < 0.3
        name = names[k] if clash else f"{prefix}j{k}"
        axis = "" if kind == "fixed" else axis_xml(_axis(rng), version, bool(rng.random() < 0.4))
        body += joint(name, kind, names[int(rng.integers(k))], names[k], axis)
    return body, names


def generated_case(seed: int, root: Path) -> tuple[Path, Path]:
    """A random model with nested models and includes (model folders written under ``root``)."""
    rng = np.random.default_rng(seed)
    version = str(rng.choice(["1.4", "1.5", "1.6", "1.7"]))
    models = root / "models"
    body, names = _model_body(rng, version, "", int(rng.integers(1, 4)))
    if version != "1.4":
        for j in range(int(rng.integers(0, 3))):
            inner, inner_names = _model_body(rng, version, "", int(rng.integers(1, 3)))
            body += f"<model name='n{j}'><pose>{_pose_text(rng)}</pose>{inner}</model>"
            if rng.random() < 0.6:
                axis = axis_xml(_axis(rng), version, bool(rng.random() < 0.4))
                body += joint(f"to_n{j}", "revolute", names[0], f"n{j}::{inner_names[0]}", axis)
    for j in range(int(rng.integers(0, 3))):
        inner_version = str(rng.choice(["1.4", "1.5", "1.6", "1.7"]))
        inner, inner_names = _model_body(rng, inner_version, "", int(rng.integers(1, 3)))
        folder = f"part_{seed}_{j}"
        pose = f"<pose>{_pose_text(rng)}</pose>" if rng.random() < 0.7 else ""
        model_folder(
            models,
            folder,
            sdf(inner_version, f"<model name='{folder}'>{pose}{inner}</model>"),
            versions={inner_version: "model.sdf"},
        )
        name = f"inc{j}" if rng.random() < 0.5 else folder
        override = f"<pose>{_pose_text(rng)}</pose>" if rng.random() < 0.5 else ""
        body += f"<include><uri>model://{folder}</uri><name>{name}</name>{override}</include>"
        if rng.random() < 0.6:
            body += joint(f"to_inc{j}", "fixed", names[0], f"{name}::{inner_names[0]}")
    path = root / f"generated_{seed}.sdf"
    path.write_text(
        sdf(version, f"<model name='g{seed}'><pose>{_pose_text(rng)}</pose>{body}</model>")
    )
    return path, models


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(RANDOM_CASES))
def test_generated_models_load_as_libsdformat_reads_them(
    sdformat_checker, tmp_path, monkeypatch, seed
):
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))
    path, models = generated_case(seed, tmp_path)
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(models))
    compare(sdformat_checker, path, models)


# --- files libsdformat refuses -------------------------------------------------------------


@pytest.mark.parametrize(
    "version, body, message",
    [
        (
            "1.6",
            link("a") + joint("j", "revolute", "a", "nowhere", axis_xml("0 0 1", "1.6", False)),
            "nowhere",
        ),
        ("1.6", link("a") + link("a"), "a"),
        ("1.7", link("a") + link("b") + joint("b", "fixed", "a", "b"), "joint 'b'"),
        ("1.6", link("a") + "<include><uri>model://no_such_model</uri></include>", "no_such_model"),
        (
            "1.6",
            "<include><uri>model://kinect</uri></include><include><uri>model://kinect</uri></include>",
            "kinect",
        ),
    ],
)
def test_models_libsdformat_refuses_are_refused_in_one_line(
    sdformat_checker, models, tmp_path, version, body, message
):
    path = tmp_path / "bad.sdf"
    path.write_text(sdf(version, f"<model name='bad'>{body}</model>"))
    oracle = run_oracle(sdformat_checker, path, str(models))
    assert not oracle.accepted
    with pytest.raises(SimulationError) as caught:
        workbench_model(path)
    text = str(caught.value)
    assert message in text and "\n" not in text


def test_an_include_cycle_is_refused_in_one_line(models, tmp_path):
    model_folder(
        models,
        "loop",
        sdf("1.6", "<model name='loop'><include><uri>model://loop</uri></include></model>"),
    )
    path = models / "loop" / "model.sdf"
    with pytest.raises(SimulationError, match="includes itself"):
        load_sim_model(path)
