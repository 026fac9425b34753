"""libgazebo_ros_control.so, the controller manager, the spawner and ros_controllers' controllers.

What is matched (ros_control and ros_controllers noetic-devel, gazebo_ros_control
noetic-devel): transmissions as TransmissionParser reads them; the controller states
``initialized``/``running``/``stopped`` and claimed resources of list_controllers;
STRICT switching and its resource-conflict refusal; joint_state_controller's joint
order (sorted) and rate; JointTrajectoryController's action results (SUCCESSFUL,
INVALID_JOINTS, INVALID_GOAL, PATH_TOLERANCE_VIOLATED), its ``command`` topic and
goal tolerances from ``constraints``; the forward and PID controllers' command topics;
control_toolbox's PID (integral clamped to 0 without ``i_clamp``); the spline
segments of QuinticSplineSegment.
"""

from __future__ import annotations

import logging
import math

import pytest
from ros_control_helpers import JOINTS, ArmRig, arm_urdf, wait_for

from workbench.msgs.control_msgs import FollowJointTrajectoryGoal, FollowJointTrajectoryResult
from workbench.msgs.controller_manager_msgs import SwitchController
from workbench.msgs.std_msgs import Float64
from workbench.msgs.trajectory_msgs import JointTrajectory, JointTrajectoryPoint
from workbench.sim.ros_control.pid import Pid
from workbench.sim.ros_control.trajectory import (
    JointTolerances,
    Segment,
    State,
    TrajectoryError,
    build_trajectory,
    hold_trajectory,
    sample,
)
from workbench.sim.ros_control.urdf_info import read_robot_info


def _goal(positions, seconds=1.5, names=JOINTS):
    goal = FollowJointTrajectoryGoal()
    goal.trajectory.joint_names = list(names)
    point = JointTrajectoryPoint(positions=list(positions), velocities=[0.0] * len(positions))
    point.time_from_start.secs = int(seconds)
    point.time_from_start.nsecs = int(round((seconds % 1) * 1e9))
    goal.trajectory.points = [point]
    return goal


def _client(rig):
    from workbench.actionlib import SimpleActionClient

    client = SimpleActionClient(
        "/eff_joint_traj_controller/follow_joint_trajectory",
        "control_msgs/FollowJointTrajectoryAction",
        rig.node,
    )
    assert client.wait_for_server(30)
    return client


# --- pure pieces ------------------------------------------------------------------------


def test_transmissions_are_read_as_transmission_parser_reads_them():
    text = arm_urdf().replace(
        '<joint name="elbow_joint">\n      <hardwareInterface>hardware_interface/EffortJointInterface'
        "</hardwareInterface>\n    </joint>",
        '<joint name="elbow_joint"/>',
    )
    info = read_robot_info(text, "arm.urdf")
    assert [t.name for t in info.transmissions] == ["shoulder_trans"]
    assert info.transmissions[0].joints[0].interfaces == (
        "hardware_interface/EffortJointInterface",
    )
    assert any("elbow_joint" in p and "hardwareInterface" in p for p in info.problems)
    limits = info.joints["shoulder_joint"].limits
    assert (limits.min_position, limits.max_position, limits.max_effort) == (-3.0, 3.0, 60.0)


def test_pid_integral_is_clamped_to_zero_without_i_clamp_and_derivative_comes_from_errors():
    pid = Pid.from_params({"p": 2.0, "i": 10.0, "d": 0.5})
    assert pid is not None and (pid.i_min, pid.i_max) == (0.0, 0.0)
    assert pid.command(1.0, 0.0, 0.1) == pytest.approx(2.0)  # the integral term is held at 0
    clamped = Pid.from_params({"p": 0.0, "i": 10.0, "i_clamp": 0.5})
    assert clamped.command(1.0, 0.0, 0.1) == pytest.approx(0.5)
    stepper = Pid.from_params({"p": 0.0, "d": 1.0})
    assert stepper.command_from_error(0.2, 0.1) == pytest.approx(2.0)  # (0.2 - 0) / 0.1
    assert Pid.from_params({"i": 1.0}) is None  # p is required


@pytest.mark.parametrize(
    ("first", "last"),
    [
        (State(0.0), State(1.0)),
        (State(0.0, 0.5), State(1.0, 0.0)),
        (State(0.0, 0.5, 1.0), State(1.0, 0.0, -2.0)),
    ],
)
def test_segments_meet_their_end_states_and_hold_outside(first, last):
    segment = Segment.between(2.0, first, 4.0, last)
    p0, v0, _ = segment.sample(2.0)
    p1, v1, a1 = segment.sample(4.0)
    assert (p0, p1) == pytest.approx((first.position, last.position))
    if first.velocity is not None:
        assert (v0, v1) == pytest.approx((first.velocity, last.velocity))
    if first.acceleration is not None:
        assert a1 == pytest.approx(last.acceleration)
    assert segment.sample(9.0) == pytest.approx((last.position, 0.0, 0.0))


def test_a_trajectory_is_bridged_from_the_current_desired_state_and_past_points_dropped():
    hold = hold_trajectory([0.3], [0.0], 0.0, 0.0)
    message = JointTrajectory(joint_names=["j"])
    points = []
    for seconds, position in ((0, 9.0), (1, 1.0), (2, 2.0)):
        point = JointTrajectoryPoint(positions=[position])
        point.time_from_start.secs = seconds
        points.append(point)
    message.points = points
    trajectory = build_trajectory(
        message, 5.0, ["j"], hold, wraparound=[False], tolerances=[JointTolerances()]
    )
    _, (start, _, _) = sample(trajectory[0], 5.0)
    assert start == pytest.approx(0.3)  # the point at 0 s is dropped: the bridge starts here
    assert sample(trajectory[0], 6.0)[1][0] == pytest.approx(1.0)
    assert sample(trajectory[0], 7.5)[1][0] == pytest.approx(2.0)
    message.points = [points[2], points[1]]
    with pytest.raises(TrajectoryError, match="not strictly increasing"):
        build_trajectory(
            message, 5.0, ["j"], hold, wraparound=[False], tolerances=[JointTolerances()]
        )


# --- the running controller manager -------------------------------------------------------


@pytest.fixture
def rig():
    arm = ArmRig()
    yield arm
    arm.close()


def test_spawner_loads_and_starts_and_list_controllers_reports_states_and_claims(rig):
    rig.spawn("joint_state_controller", "eff_joint_traj_controller")
    rig.spawn("--stopped", "joint_group_eff_controller")
    from workbench.msgs.controller_manager_msgs import ListControllers

    reply = rig.call("list_controllers", ListControllers.Request())
    found = {c.name: c for c in reply.controller}
    assert {n: c.state for n, c in found.items()} == {
        "joint_state_controller": "running",
        "eff_joint_traj_controller": "running",
        "joint_group_eff_controller": "initialized",
    }
    claims = found["eff_joint_traj_controller"].claimed_resources
    assert [(r.hardware_interface, list(r.resources)) for r in claims] == [
        ("hardware_interface::EffortJointInterface", sorted(JOINTS))
    ]
    assert list(found["joint_state_controller"].claimed_resources[0].resources) == []


def test_joint_state_controller_publishes_sorted_joints_at_its_rate(rig):
    states = rig.record("/joint_states", "sensor_msgs/JointState")
    rig.spawn("joint_state_controller")
    wait_for(lambda: len(states) >= 20)
    assert list(states[-1].name) == sorted(JOINTS)
    stamps = [m.header.stamp.to_sec() for m in states[-15:]]
    gaps = [b - a for a, b in zip(stamps, stamps[1:], strict=False)]
    assert sum(gaps) / len(gaps) == pytest.approx(1 / 125, abs=5e-4)


def test_a_follow_joint_trajectory_goal_moves_the_arm_and_succeeds(rig):
    rig.spawn("joint_state_controller", "eff_joint_traj_controller")
    client = _client(rig)
    start = rig.world.time
    client.send_goal(_goal([0.6, -0.8]))
    assert client.wait_for_result(120)
    assert client.get_state() == 3  # SUCCEEDED
    assert client.get_result().error_code == FollowJointTrajectoryResult.SUCCESSFUL
    assert rig.world.time - start == pytest.approx(1.5, abs=0.7)  # within goal_time of the end
    assert rig.positions() == pytest.approx([0.6, -0.8], abs=0.02)


def test_goals_with_wrong_joints_or_times_are_rejected_with_ros_codes(rig):
    rig.spawn("eff_joint_traj_controller")
    client = _client(rig)
    client.send_goal(_goal([0.1], names=["shoulder_joint"]))
    assert client.wait_for_result(30)
    assert client.get_state() == 5  # REJECTED
    assert client.get_result().error_code == FollowJointTrajectoryResult.INVALID_JOINTS
    goal = _goal([0.1, 0.1])
    goal.trajectory.points = goal.trajectory.points * 2  # the same time twice
    client.send_goal(goal)
    assert client.wait_for_result(30)
    assert client.get_result().error_code == FollowJointTrajectoryResult.INVALID_GOAL
    assert "strictly increasing" in client.get_result().error_string


def test_a_path_tolerance_the_arm_cannot_keep_aborts_the_goal(rig):
    rig.spawn("eff_joint_traj_controller")
    client = _client(rig)
    goal = _goal([2.5, -2.0], seconds=0.05)  # far too fast for the effort limits
    client.send_goal(goal)
    assert client.wait_for_result(60)
    assert client.get_state() == 4  # ABORTED
    result = client.get_result()
    assert result.error_code == FollowJointTrajectoryResult.PATH_TOLERANCE_VIOLATED
    assert "path error" in result.error_string


def test_the_command_topic_moves_the_arm(rig):
    rig.spawn("eff_joint_traj_controller")
    publisher = rig.node.create_publisher("/eff_joint_traj_controller/command", JointTrajectory)
    message = JointTrajectory(joint_names=list(reversed(JOINTS)))
    point = JointTrajectoryPoint(positions=[0.4, -0.3])
    point.time_from_start.secs = 1
    message.points = [point]
    wait_for(lambda: publisher.get_num_connections() > 0)
    publisher.publish(message)
    wait_for(lambda: rig.positions() == pytest.approx([-0.3, 0.4], abs=0.02))


def test_strict_switching_refuses_two_controllers_on_one_joint_and_unloading_a_running_one(
    rig, caplog
):
    rig.spawn("eff_joint_traj_controller")
    rig.spawn("--stopped", "joint_group_eff_controller")
    request = SwitchController.Request(
        start_controllers=["joint_group_eff_controller"], strictness=SwitchController.Request.STRICT
    )
    with caplog.at_level(logging.ERROR, logger="workbench.sim.ros_control"):
        assert not rig.call("switch_controller", request).ok
        from workbench.msgs.controller_manager_msgs import UnloadController

        assert not rig.call(
            "unload_controller", UnloadController.Request(name="eff_joint_traj_controller")
        ).ok
    assert "resource conflict" in caplog.text and "still running" in caplog.text
    swap = SwitchController.Request(
        start_controllers=["joint_group_eff_controller"],
        stop_controllers=["eff_joint_traj_controller"],
        strictness=SwitchController.Request.STRICT,
    )
    assert rig.call("switch_controller", swap).ok
    assert rig.states()["joint_group_eff_controller"] == "running"
    assert rig.states()["eff_joint_traj_controller"] == "stopped"


def test_loading_an_unknown_type_or_a_controller_without_parameters_fails_in_one_line(caplog):
    arm = ArmRig(params={"/diff": {"type": "diff_drive_controller/DiffDriveController"}})
    from workbench.msgs.controller_manager_msgs import LoadController

    try:
        with caplog.at_level(logging.ERROR, logger="workbench.sim.ros_control"):
            assert not arm.call("load_controller", LoadController.Request(name="diff")).ok
            assert not arm.call("load_controller", LoadController.Request(name="nothing")).ok
    finally:
        arm.close()
    assert (
        "controller type 'diff_drive_controller/DiffDriveController' does not exist" in caplog.text
    )
    assert "the type was not specified" in caplog.text


def test_position_interface_puts_the_joint_at_the_command():
    params = {
        "/arm_position": {
            "type": "position_controllers/JointPositionController",
            "joint": "elbow_joint",
        }
    }
    arm = ArmRig(urdf=arm_urdf("hardware_interface/PositionJointInterface"), params=params)
    try:
        arm.spawn("arm_position")
        publisher = arm.node.create_publisher("/arm_position/command", Float64)
        wait_for(lambda: publisher.get_num_connections() > 0)
        publisher.publish(Float64(data=1.2))
        # the velocity limit (3 rad/s) saturates the step; then the joint sits at the command
        wait_for(lambda: abs(arm.positions()[1] - 1.2) < 1e-3)
    finally:
        arm.close()


def test_velocity_interface_holds_the_commanded_velocity():
    params = {
        "/wheel": {
            "type": "velocity_controllers/JointVelocityController",
            "joint": "shoulder_joint",
        }
    }
    arm = ArmRig(urdf=arm_urdf("hardware_interface/VelocityJointInterface"), params=params)
    try:
        arm.spawn("wheel")
        publisher = arm.node.create_publisher("/wheel/command", Float64)
        wait_for(lambda: publisher.get_num_connections() > 0)
        publisher.publish(Float64(data=0.5))
        plant = arm.world.plant

        def speed() -> float:
            context = plant.GetMyContextFromRoot(arm.world.context)
            return float(
                plant.GetVelocities(context)[plant.GetJointByName(JOINTS[0]).velocity_start()]
            )

        wait_for(lambda: abs(speed() - 0.5) < 0.01)
    finally:
        arm.close()


def test_effort_position_controller_reaches_the_command_with_its_pid():
    params = {
        "/elbow": {
            "type": "effort_controllers/JointPositionController",
            "joint": "elbow_joint",
            "pid": {"p": 200.0, "d": 10.0, "i": 20.0, "i_clamp": 5.0},
        }
    }
    arm = ArmRig(params=params)
    try:
        states = arm.record("/elbow/state", "control_msgs/JointControllerState")
        arm.spawn("elbow")
        publisher = arm.node.create_publisher("/elbow/command", Float64)
        wait_for(lambda: publisher.get_num_connections() > 0)
        publisher.publish(Float64(data=-0.7))
        wait_for(lambda: abs(arm.positions()[1] + 0.7) < 0.01)
        wait_for(lambda: states and states[-1].set_point == pytest.approx(-0.7))
        assert states[-1].p == 200.0
    finally:
        arm.close()


def test_another_robot_sim_type_is_refused_in_one_line(caplog):
    plugin = "<robotSimType>my_pkg/MyRobotHWSim</robotSimType>"
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        arm = ArmRig(urdf=arm_urdf(plugin=plugin), start=False)
        arm.close()
    lines = [r.getMessage() for r in caplog.records if "MyRobotHWSim" in r.getMessage()]
    assert len(lines) == 1 and "is not provided" in lines[0] and "'robot'" in lines[0]


def test_without_the_description_parameter_the_models_own_urdf_is_used():
    arm = ArmRig(description=False)
    try:
        arm.spawn("eff_joint_traj_controller")
        assert arm.states() == {"eff_joint_traj_controller": "running"}
    finally:
        arm.close()


def test_controller_manager_command_lists_as_the_ros_tool_prints(rig, capsys):
    from workbench.sim.ros_control.nodes import _command

    rig.spawn("joint_state_controller", "eff_joint_traj_controller")
    assert _command(rig.node, "list", []) == 0
    printed = capsys.readouterr().out.splitlines()
    assert (
        "'eff_joint_traj_controller' - 'hardware_interface::EffortJointInterface' ( running )"
        in printed
    )
    assert _command(rig.node, "kill", ["eff_joint_traj_controller"]) == 0
    assert "eff_joint_traj_controller" not in rig.states()
    assert math.isfinite(rig.positions()[0])


def test_after_a_world_reset_the_controllers_hold_and_follow_goals_again(rig):
    rig.spawn("eff_joint_traj_controller")
    client = _client(rig)
    client.send_goal(_goal([0.6, -0.8]))
    assert client.wait_for_result(120) and client.get_state() == 3
    rig.server.reset(time_too=True)  # /gazebo/reset_simulation: time back to 0
    assert rig.states() == {"eff_joint_traj_controller": "running"}
    client.send_goal(_goal([0.3, 0.2]))
    assert client.wait_for_result(120)
    assert client.get_result().error_code == FollowJointTrajectoryResult.SUCCESSFUL
    assert rig.positions() == pytest.approx([0.3, 0.2], abs=0.02)
