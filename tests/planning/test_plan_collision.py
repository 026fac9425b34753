from __future__ import annotations

import numpy as np
import pytest
from plan_core_helpers import SCENES, arm3_config, robot_arm_config  # noqa: F401

from workbench.planning.collision import CollisionWorld
from workbench.planning.scene import PlanningScene, load_scene
from workbench.planning.spheres import SphereChecker


def _world(config, scene):
    return CollisionWorld(
        config.robot,
        scene,
        disabled_pairs=[(d.link1, d.link2) for d in config.srdf.disabled_collisions],
    )


@pytest.mark.parametrize(
    ("config_name", "scene_name"),
    [("arm3_config", "arm3_table.yaml"), ("robot_arm_config", "robot_arm_pillars.yaml")],
)
def test_sphere_model_is_conservative_and_its_kinematics_match_drake(
    request, config_name, scene_name
):
    config = request.getfixturevalue(config_name)
    world = _world(config, load_scene(SCENES / scene_name))
    names = config.srdf.group_joints(config.group, world.robot)
    joints = world.joint_map(names)
    spheres = SphereChecker(world, joints)
    lower, upper = world.position_limits()
    rng = np.random.default_rng(0)
    Q = rng.uniform(lower[joints.indices], upper[joints.indices], size=(400, len(names)))
    exact = world.configs_free(joints.full(Q))
    approx = spheres.configs_free(Q)
    # every configuration the spheres accept is free for the exact geometry
    assert not np.any(approx & ~exact)
    assert exact.any() and not exact.all()
    # forward kinematics of the numpy model equals Drake's
    plant = world.plant
    context = plant.CreateDefaultContext()
    X = spheres.body_transforms(Q[:3])
    for k in range(3):
        plant.SetPositions(context, joints.full(Q[k]))
        for body_index in plant.GetBodyIndices(world.instance):
            body = plant.get_body(body_index)
            expected = plant.EvalBodyPoseInWorld(context, body).GetAsMatrix4()
            np.testing.assert_allclose(spheres.body_pose(X, body.name())[k], expected, atol=1e-9)


def test_colliding_pair_names_obstacle(arm3_config):  # noqa: F811
    scene = PlanningScene()
    scene.add_sphere("ball", 0.05, xyz=[0.0, 0.0, 0.5])  # on the raised arm
    world = _world(arm3_config, scene)
    q = world.default_positions()
    assert not world.is_free(q)
    text = world.describe_collision(q)
    assert "'ball'" in text and "penetration" in text
    assert world.colliding_pairs(q)[0][2] < 0


def test_disabled_pairs_are_honoured(robot_arm_config):  # noqa: F811
    plain = CollisionWorld(robot_arm_config.robot)
    pair = ("gripper_finger_link1", "gripper_finger_link2")
    filtered = CollisionWorld(robot_arm_config.robot, disabled_pairs=[pair])
    q = plain.default_positions()
    names = plain.joint_names()
    q[names.index("finger_joint1")] = 0.02  # both fingers meet at y = 0
    q[names.index("finger_joint2")] = -0.02
    assert {a for a, _, _ in plain.colliding_pairs(q)} | {
        b for _, b, _ in plain.colliding_pairs(q)
    } >= set(pair)
    assert not plain.is_free(q)
    assert filtered.is_free(q)
    assert filtered.colliding_pairs(q) == []


def test_mesh_obstacle_is_covered_by_its_box(arm3_config, tmp_path):  # noqa: F811
    import trimesh

    trimesh.creation.icosphere(subdivisions=2, radius=0.08).export(tmp_path / "ball.obj")
    scene = PlanningScene()
    scene.add_mesh("ball", tmp_path / "ball.obj", xyz=[0.3, 0.0, 0.35])
    world = _world(arm3_config, scene)
    joints = world.joint_map(arm3_config.srdf.group_joints(arm3_config.group, world.robot))
    spheres = SphereChecker(world, joints)
    lower, upper = world.position_limits()
    Q = np.random.default_rng(3).uniform(lower[joints.indices], upper[joints.indices], (300, 3))
    exact = world.configs_free(joints.full(Q))
    approx = spheres.configs_free(Q)
    assert not exact.all()  # the mesh is in reach
    assert not np.any(approx & ~exact)
