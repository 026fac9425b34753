"""Well-known robots by name from example-robot-data (the ``[robots]`` extra): the Panda."""

from __future__ import annotations

import pytest
from skipping import skip_or_fail

from workbench.errors import ModelError
from workbench.model import load_robot, resolve_robot_path
from workbench.model.robot_library import library_robots, library_root, library_srdf


@pytest.fixture(scope="module")
def library():
    if library_root() is None:
        skip_or_fail("example-robot-data is not installed (pip install -e '.[robots]')")
    return library_root()


def test_panda_is_found_by_name_with_its_srdf(library):
    path = resolve_robot_path("panda")
    assert path == library / "robots" / "panda_description" / "urdf" / "panda.urdf"
    assert library_srdf(path) == library / "robots" / "panda_description" / "srdf" / "panda.srdf"
    assert {"panda", "ur5", "pr2"} <= set(library_robots())


def test_panda_loads_with_its_meshes(library):
    robot = load_robot("panda")
    arm = [j.name for j in robot.movable_joints if j.name.startswith("panda_joint")]
    assert arm == [f"panda_joint{i}" for i in range(1, 8)]
    # the .dae visuals (package://example-robot-data/...) resolve and convert
    assert not [w for w in robot.load_warnings if "safety_controller" not in w]
    link0 = robot.plant.GetBodyByName("panda_link0")
    inspector = robot.scene_graph.model_inspector()
    frame = robot.plant.GetBodyFrameIdOrThrow(link0.index())
    assert inspector.GetGeometries(frame)


def test_setup_keeps_the_shipped_srdf_and_its_named_state(library):
    from workbench.planning.setup import run_setup

    lines: list[str] = []
    config = run_setup("panda", samples=500, seed=0, write=False, log=lines.append)
    assert any("using the SRDF that ships with the description" in line for line in lines)
    assert config.srdf.group_names == ["arm", "hand", "arm_and_hand"]
    # 'default' belongs to arm_and_hand, which includes arm whole: the arm may use it
    assert "default" in config.srdf.group_state_names("arm")
    state = config.srdf.group_state("arm", "default")
    assert state.values["panda_joint4"] == pytest.approx(-2.35619)


def test_an_unknown_name_lists_the_library(library):
    with pytest.raises(ModelError, match="example-robot-data \\(.*panda"):
        resolve_robot_path("no_such_robot_anywhere")
