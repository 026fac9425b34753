"""The compiled sphere kernel against the numpy reference: never more permissive, nearly equal."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from plan_core_helpers import SCENES, arm3_config, robot_arm_config  # noqa: F401

from workbench.planning.collision import CollisionWorld
from workbench.planning.scene import PlanningScene, load_scene
from workbench.planning.spheres import SphereChecker

#: The Panda of the planning benchmark, when its resources have been fetched on this machine.
PANDA = (
    Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache"))
    / "workbench"
    / "vamp-planner-0.6.4"
    / "panda"
)
CASES = [("arm3_config", "arm3_table.yaml"), ("robot_arm_config", "robot_arm_pillars.yaml")]
if (PANDA / "panda.urdf").is_file() and (PANDA / "panda.srdf").is_file():
    CASES.append(("panda", "box"))


def _panda(tmp_path: Path):
    from workbench.planning.setup import run_setup

    urdf = tmp_path / "panda_abs.urdf"
    text = (PANDA / "panda.urdf").read_text()
    urdf.write_text(text.replace("package://meshes/", f"{(PANDA / 'meshes').resolve()}/"))
    config = run_setup(str(urdf), srdf=PANDA / "panda.srdf", samples=0, write=False)
    scene = PlanningScene()
    scene.add_box("table", [1.0, 1.2, 0.04], xyz=[0.6, 0.0, 0.3])
    scene.add_box("shelf", [0.3, 0.8, 0.02], xyz=[0.5, 0.0, 0.7], rpy=[0.0, 0.2, 0.3])
    scene.add_cylinder("post", 0.05, 0.8, xyz=[0.3, 0.4, 0.4], rpy=[0.4, 0.0, 0.0])
    scene.add_sphere("ball", 0.08, xyz=[0.2, -0.4, 0.6])
    return config, scene


@pytest.fixture
def checker(request, tmp_path):
    config_name, scene_name = request.param
    if config_name == "panda":
        config, scene = _panda(tmp_path)
    else:
        config, scene = request.getfixturevalue(config_name), load_scene(SCENES / scene_name)
    world = CollisionWorld(
        config.robot,
        scene,
        disabled_pairs=[(d.link1, d.link2) for d in config.srdf.disabled_collisions],
    )
    joints = world.joint_map(config.srdf.group_joints(config.group, world.robot))
    lower, upper = world.position_limits()
    return SphereChecker(world, joints), lower[joints.indices], upper[joints.indices]


@pytest.mark.parametrize("checker", CASES, indirect=True, ids=[c[0] for c in CASES])
def test_compiled_states_match_numpy_reference(checker):
    spheres, lower, upper = checker
    Q = np.random.default_rng(7).uniform(lower, upper, size=(3000, len(lower)))
    reference = spheres.configs_free_reference(Q)
    compiled = spheres.configs_free(Q)
    single = np.array([spheres.is_free(q) for q in Q[:300]])
    assert 0.05 < reference.mean() < 0.95  # both answers occur
    assert not np.any(compiled & ~reference)  # never accepts what the reference rejects
    assert np.sum(reference & ~compiled) <= 3  # conservative only within rounding
    np.testing.assert_array_equal(single, compiled[:300])


@pytest.mark.parametrize("checker", CASES, indirect=True, ids=[c[0] for c in CASES])
def test_compiled_motions_match_numpy_reference(checker):
    spheres, lower, upper = checker
    rng = np.random.default_rng(11)
    step = 0.05
    seen = set()
    for k in range(400):
        qa = rng.uniform(lower, upper)
        qb = rng.uniform(lower, upper)  # long motions and short ones
        if k % 2:
            qb = np.clip(qa + rng.uniform(-0.6, 0.6, len(qa)), lower, upper)
        status, checked = spheres.motion_status(qa, qb, step)
        samples = spheres.edge_samples(qa, qb, step)
        free = spheres.configs_free_reference(samples)
        assert 1 <= checked <= len(samples)
        if not (free[0] and free[1]):
            assert status == -1
        elif free.all():
            assert status == 1
        else:  # the ends are free, a sample between them is not
            assert status == 0
        seen.add(status)
    assert seen == {-1, 0, 1}
