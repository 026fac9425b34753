from __future__ import annotations

import numpy as np
import pytest
from plan_core_helpers import (  # noqa: F401
    arm3_config,
    arm3_planner,
    independent_check,
    robot_arm_config,
    robot_arm_planner,
)

from workbench.planning.errors import (
    GoalError,
    GoalInCollisionError,
    IKError,
    NoPathError,
    StartInCollisionError,
    UnknownPlannerError,
)
from workbench.planning.srdf import SrdfError


@pytest.mark.parametrize("goal", ["home", "random", "q=1.0,0.6,-0.9"])
def test_arm3_plans_pass_an_independent_check(arm3_planner, goal):  # noqa: F811
    start = np.array([-1.2, 0.3, 0.4]) if goal == "home" else None
    result = arm3_planner.plan(goal, start=start, seed=2)
    assert result.recheck_ok and result.recheck_samples > 10
    assert result.peak_velocity <= 1.0 and result.peak_acceleration <= 1.0
    q, _, _ = result.trajectory.sample([0.0, result.duration])
    np.testing.assert_allclose(q[0], result.start, atol=1e-9)
    np.testing.assert_allclose(q[-1], result.goal, atol=1e-9)
    independent_check(arm3_planner, result.trajectory)


def test_robot_arm_random_goal_in_scene(robot_arm_planner):  # noqa: F811
    result = robot_arm_planner.plan("random", seed=4)
    assert len(result.joint_names) == 5
    independent_check(robot_arm_planner, result.trajectory)


def test_point_goal_is_reached_within_a_millimetre(arm3_planner):  # noqa: F811
    target = np.array([0.25, -0.25, 0.35])
    result = arm3_planner.plan(f"xyz={target[0]},{target[1]},{target[2]}", seed=1)
    plant = arm3_planner.world.plant
    context = plant.CreateDefaultContext()
    plant.SetPositions(context, arm3_planner.joints.full(result.goal))
    tip = plant.GetBodyByName(arm3_planner.tip_link())
    reached = plant.EvalBodyPoseInWorld(context, tip).translation()
    assert np.linalg.norm(reached - target) < 1e-3
    independent_check(arm3_planner, result.trajectory)


def test_other_planners_by_name(arm3_planner):  # noqa: F811
    for name in ("PRM", "BITstar"):
        result = arm3_planner.plan("q=1.0,0.6,-0.9", planner=name, time_limit=0.3, seed=0)
        assert result.planner == name
        independent_check(arm3_planner, result.trajectory)


def test_start_in_collision_names_the_bodies(arm3_planner):  # noqa: F811
    # forearm folded down onto the table
    with pytest.raises(StartInCollisionError) as info:
        arm3_planner.plan("home", start=np.array([0.0, 1.2, 2.2]))
    text = info.value.one_line()
    assert "start is in collision" in text and "'table'" in text, text


def test_goal_in_collision_names_the_bodies(arm3_planner):  # noqa: F811
    with pytest.raises(GoalInCollisionError, match="goal is in collision: '.*' and 'table'"):
        arm3_planner.plan("q=0,1.2,2.2")


@pytest.mark.parametrize(
    ("goal", "error", "message"),
    [
        ("q=0,0", GoalError, "has 3 joints .* the goal gives 2 values"),
        ("q=0,3,0", GoalError, "joint 'shoulder_pitch_joint' = 3.0000 is outside its limits"),
        ("nowhere", SrdfError, "no named state 'nowhere'"),
        ("xyz=3,0,0", IKError, "no joint values within the limits put 'tool_link' at"),
    ],
)
def test_bad_goals(arm3_planner, goal, error, message):  # noqa: F811
    with pytest.raises(error, match=message):
        arm3_planner.plan(goal)


def test_unknown_planner_and_group(arm3_planner, arm3_config):  # noqa: F811
    from workbench.planning.pipeline import MotionPlanner

    with pytest.raises(UnknownPlannerError, match="unknown planner 'RRTfoo'"):
        arm3_planner.plan("random", planner="RRTfoo")
    with pytest.raises(SrdfError, match="group 'legs'"):
        MotionPlanner(config=arm3_config, group="legs")


def test_unsatisfiable_time_limit(arm3_config):  # noqa: F811
    from workbench.planning.pipeline import MotionPlanner
    from workbench.planning.scene import PlanningScene

    # the tool starts inside a closed cage: no path out exists, so any limit runs out
    scene = PlanningScene()
    cx, cz = 0.5, 0.18
    scene.add_box("top", [0.24, 0.16, 0.02], xyz=[cx, 0, cz + 0.07])
    scene.add_box("bottom", [0.24, 0.16, 0.02], xyz=[cx, 0, cz - 0.07])
    scene.add_box("left", [0.24, 0.02, 0.16], xyz=[cx, 0.07, cz])
    scene.add_box("right", [0.24, 0.02, 0.16], xyz=[cx, -0.07, cz])
    scene.add_box("end", [0.02, 0.16, 0.16], xyz=[cx + 0.13, 0, cz])
    planner = MotionPlanner(config=arm3_config, scene=scene)
    start = np.array([0.0, 1.5, 0.0])
    with pytest.raises(NoPathError, match="no path within the time limit of 0.1 s"):
        planner.plan("q=0,0,0", start=start, time_limit=0.1)
    with pytest.raises(GoalError, match="time limit must be positive"):
        planner.plan("random", start=start, time_limit=0)


def test_start_inside_the_sphere_margin_is_planned_with_exact_confirmation(arm3_planner):  # noqa: F811
    # find a start the exact checker accepts but the spheres reject (next to an obstacle)
    rng = np.random.default_rng(7)
    candidates = rng.uniform(arm3_planner.lower, arm3_planner.upper, size=(5000, 3))
    in_margin = [
        q for q in candidates if not arm3_planner.spheres.is_free(q) and arm3_planner.is_free(q)
    ]
    assert in_margin, "the sphere model should reject some free states"
    q = in_margin[0]
    result = arm3_planner.plan("q=0.5,0.3,0.5", start=q, seed=1)
    assert result.checks["exact_checks"] > 0
    independent_check(arm3_planner, result.trajectory)


def test_spheres_first_only_where_their_space_is_open(robot_arm_planner, arm3_planner):  # noqa: F811
    planner = robot_arm_planner
    reach = 0.04 * float(np.linalg.norm(planner.upper - planner.lower))
    rng = np.random.default_rng(3)
    states = rng.uniform(planner.lower, planner.upper, size=(4000, len(planner.lower)))
    free = planner.world.configs_free(planner.joints.full(states))
    clear = planner.spheres.configs_free(states)
    # a state clear of the spheres is open
    assert planner._spheres_open(states[np.nonzero(clear & free)[0][0]], reach, 0)
    # the small arm's links nearly touch in most poses: from a free state deep in that
    # margin (no sphere-clear state around it), the spheres' space is closed
    closed = [
        q
        for q in states[free & ~clear][:200]
        if not planner.spheres.configs_free(
            np.clip(
                q + reach * rng.normal(size=(64, len(q))) / np.sqrt(len(q)),
                planner.lower,
                planner.upper,
            )
        ).any()
    ]
    assert closed, "expected free states deep inside the spheres' margin"
    assert not planner._spheres_open(closed[0], reach, 0)
    # and planning from there still succeeds, confirming sphere rejections exactly
    result = planner.plan("random", start=closed[0], seed=2)
    assert result.checks["exact_checks"] > 0
    independent_check(planner, result.trajectory)


def test_sphere_fidelity_decides_where_to_plan_first(robot_arm_planner, arm3_planner):  # noqa: F811
    from workbench.planning.pipeline import MIN_FIDELITY

    # arm3's spheres keep nearly all of its free space; robot_arm's links nearly touch in
    # most poses, so its spheres keep little of it and it plans with exact confirmation
    assert arm3_planner.sphere_fidelity > 0.9
    assert robot_arm_planner.sphere_fidelity < MIN_FIDELITY
    q = robot_arm_planner.default_start()
    result = robot_arm_planner.plan("random", start=q, seed=4)
    assert result.checks["exact_checks"] > 0
    independent_check(robot_arm_planner, result.trajectory)
