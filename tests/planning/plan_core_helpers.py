"""Fixtures and an independent checker shared by the planning-core tests.

Test modules import the fixtures they use from here (pytest finds fixtures
in a test module's namespace).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
SCENES = REPO / "planning" / "scenes"
DATA = REPO / "tests" / "data" / "planning_core"


def make_config(robot: str, out_dir: Path):
    from workbench.planning.setup import run_setup

    return run_setup(robot, out_dir=out_dir, samples=1000, seed=0)


@pytest.fixture(scope="session")
def robot_arm_config(tmp_path_factory):
    return make_config("robot_arm", tmp_path_factory.mktemp("robot_arm_config"))


@pytest.fixture(scope="session")
def arm3_config(tmp_path_factory):
    return make_config("arm3", tmp_path_factory.mktemp("arm3_config"))


@pytest.fixture(scope="session")
def arm3_planner(arm3_config):
    from workbench.planning.pipeline import MotionPlanner

    return MotionPlanner(config=arm3_config, scene=SCENES / "arm3_table.yaml")


@pytest.fixture(scope="session")
def robot_arm_planner(robot_arm_config):
    from workbench.planning.pipeline import MotionPlanner

    return MotionPlanner(config=robot_arm_config, scene=SCENES / "robot_arm_pillars.yaml")


def independent_check(planner, trajectory, dt: float = 0.001) -> None:
    """Assert a timed trajectory is free and within every limit, in a freshly built checker.

    The checker is built from the files (robot, SRDF disabled pairs, scene), not
    reused from the planner, and samples every millisecond.
    """
    from workbench.planning.collision import CollisionWorld

    config = planner.config
    world = CollisionWorld(
        config.robot,
        planner.scene,
        disabled_pairs=[(d.link1, d.link2) for d in config.srdf.disabled_collisions],
    )
    joints = world.joint_map(planner.joint_names, base=planner.joints.base)
    t = trajectory.times(dt)
    q, qd, qdd = trajectory.sample(t)
    free = world.configs_free(joints.full(q))
    assert free.all(), f"collision at t={t[~free][0]:.3f} s"
    lower, upper = world.position_limits()
    assert np.all(q >= lower[joints.indices] - 1e-9) and np.all(q <= upper[joints.indices] + 1e-9)
    vlim = np.array(config.velocity_limits(planner.joint_names))
    alim = np.array(config.acceleration_limits(planner.joint_names))
    assert np.all(np.abs(qd) <= vlim + 1e-9), np.abs(qd).max(axis=0) / vlim
    assert np.all(np.abs(qdd) <= alim + 1e-9), np.abs(qdd).max(axis=0) / alim
