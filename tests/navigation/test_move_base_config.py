"""move_base's configuration: parameters, planner names, recoveries and the node's start-up errors.

From ``move_base/src/move_base.cpp`` (Noetic): the defaults, the deprecated bare planner
names ("Planner specifications should now include the package name..."), the default
recovery order with the conservative (3 m) and aggressive (4 x circumscribed radius) reset
distances; from ``clear_costmap_recovery.cpp``: the layer names (``obstacles``) and the
"Wrong value for affected_maps" warning; from ``trajectory_planner_ros.cpp``: the older
parameter names ``pdist_scale``/``gdist_scale``/``max_rotational_vel``.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from move_base_setup import param_node

from workbench.navigation.dwa_planner_ros import velocity_samples
from workbench.navigation.local_planner_params import (
    PlannerParameterError,
    trajectory_planner_params,
)
from workbench.navigation.move_base import quaternion_problem
from workbench.navigation.move_base_params import MoveBaseError, read_params

REPO = Path(__file__).resolve().parents[2]


def test_defaults_and_recovery_order() -> None:
    node = param_node()
    p = read_params(node)
    assert (p.base_global_planner, p.base_local_planner) == (
        "navfn/NavfnROS",
        "base_local_planner/TrajectoryPlannerROS",
    )
    assert (
        p.controller_frequency,
        p.planner_frequency,
        p.planner_patience,
        p.controller_patience,
    ) == (20.0, 0.0, 5.0, 15.0)
    assert (p.oscillation_timeout, p.oscillation_distance, p.max_planning_retries) == (0.0, 0.5, -1)
    assert [n for n, _ in p.recovery_behaviors] == [
        "conservative_reset",
        "rotate_recovery",
        "aggressive_reset",
        "rotate_recovery",
    ]
    assert node.get_param("~conservative_reset/reset_distance") == 3.0
    assert node.get_param("~aggressive_reset/reset_distance") == pytest.approx(4 * 0.46)
    no_rotation = read_params(param_node(clearing_rotation_allowed=False))
    assert [n for n, _ in no_rotation.recovery_behaviors] == [
        "conservative_reset",
        "aggressive_reset",
    ]


def test_bare_planner_name_is_accepted_with_a_warning() -> None:
    node = param_node(base_local_planner="TrajectoryPlannerROS")
    lines = []
    node.create_subscription("/rosout", "rosgraph_msgs/Log", lambda m: lines.append(m.msg), 0)
    assert read_params(node).base_local_planner == "base_local_planner/TrajectoryPlannerROS"
    node.bus.spin_once(0.0)
    assert any(
        "Please switch from TrajectoryPlannerROS to base_local_planner/TrajectoryPlannerROS" in m
        for m in lines
    )


def test_unknown_planner_is_one_line() -> None:
    with pytest.raises(MoveBaseError) as error:
        read_params(param_node(base_local_planner="teb_local_planner/TebLocalPlannerROS"))
    line = error.value.one_line()
    assert (
        "\n" not in line and "/move_base/base_local_planner" in line and "teb_local_planner" in line
    )


def test_wrong_types_name_the_parameter() -> None:
    with pytest.raises(
        PlannerParameterError, match="/move_base/controller_frequency must be positive"
    ):
        read_params(param_node(controller_frequency=0.0))
    with pytest.raises(
        PlannerParameterError, match="/move_base/TrajectoryPlannerROS/max_vel_x must be a number"
    ):
        trajectory_planner_params(
            param_node(**{"TrajectoryPlannerROS/max_vel_x": "fast"}), "~TrajectoryPlannerROS"
        )
    with pytest.raises(MoveBaseError, match=r"recovery_behaviors\[0\]"):
        read_params(param_node(recovery_behaviors=[{"name": "x", "type": "nope/Nope"}]))


def test_old_parameter_names_and_controller_frequency() -> None:
    node = param_node(
        controller_frequency=8.0,
        **{
            "TrajectoryPlannerROS/pdist_scale": 0.9,
            "TrajectoryPlannerROS/gdist_scale": 0.3,
            "TrajectoryPlannerROS/max_rotational_vel": 0.7,
            "TrajectoryPlannerROS/acc_lim_th": 1.5,
        },
    )
    params, host = trajectory_planner_params(node, "~TrajectoryPlannerROS")
    assert (params.path_distance_bias, params.goal_distance_bias) == (0.9, 0.3)
    assert (params.max_vel_theta, params.acc_lim_theta) == (0.7, 1.5)
    assert params.sim_period == pytest.approx(1 / 8.0)
    assert (host["xy_goal_tolerance"], host["yaw_goal_tolerance"]) == (0.10, 0.05)
    assert (
        params.dwa
        and params.holonomic_robot
        and (params.vx_samples, params.vtheta_samples) == (3, 20)
    )


def test_quaternion_checks() -> None:
    from workbench.msgs.geometry_msgs import Quaternion

    assert quaternion_problem(Quaternion(x=0, y=0, z=0, w=1)) is None
    assert "length close to zero" in quaternion_problem(Quaternion(x=0, y=0, z=0, w=0))
    assert "close to vertical" in quaternion_problem(Quaternion(x=1, y=0, z=0, w=0))
    assert "nans or infs" in quaternion_problem(Quaternion(x=float("nan"), y=0, z=0, w=1))


def test_dwa_velocity_samples_include_zero() -> None:
    assert velocity_samples(-1.0, 1.0, 4).tolist() == pytest.approx([-1.0, -1 / 3, 0.0, 1 / 3, 1.0])
    assert velocity_samples(0.1, 0.5, 3).tolist() == pytest.approx([0.1, 0.3, 0.5])
    assert velocity_samples(0.2, 0.2, 1).tolist() == [0.2]
    # VelocityIterator: two samples at least when the ends differ, even if low > high (a
    # window pinned by acc_lim_y 0 while odometry reports vy 4e-6: the TurtleBot3's DWA)
    assert velocity_samples(0.0, 0.3, 1).tolist() == [0.0, 0.3]
    assert velocity_samples(4e-6, 0.0, 1).tolist() == [4e-6, 0.0]
    assert np.all(np.diff(velocity_samples(-0.5, 0.2, 8)) > 0)


def test_node_with_an_unknown_planner_exits_with_one_line() -> None:
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc")
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "workbench",
            "run",
            "move_base",
            "move_base",
            "_base_global_planner:=carrot_planner/CarrotPlanner",
        ],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        cwd=REPO,
    )
    assert result.returncode != 0
    errors = [line for line in result.stderr.splitlines() if "error" in line.lower()]
    assert len(errors) == 1 and "carrot_planner/CarrotPlanner" in errors[0], result.stderr
    assert "Traceback" not in result.stderr
