"""ros_control through ``workbench launch``, in separate processes, as ur_gazebo starts a UR.

The package written here has the shape of ur_gazebo: a launch file like
``inc/ur_control.launch.xml`` (``<rosparam command="load">`` of the controllers file,
gazebo_ros's ``empty_world.launch``, ``spawn_model -urdf -param robot_description``, a
``controller_manager spawner`` that starts two controllers and one ``--stopped`` that
only loads the third), the two-link arm's URDF with its transmissions and
gazebo_ros_control block, and controllers.yaml in the shape of ur5_controllers.yaml.
"""

from __future__ import annotations

import shutil

import pytest
from process_helpers import launched, private_core, wait_for
from ros_control_helpers import ARM, CONTROLLERS, JOINTS

from workbench.bus import Bus, Node

LAUNCH = """<?xml version="1.0"?>
<launch>
  <arg name="controller_config_file" default="$(find arm_gazebo)/config/arm_controllers.yaml"/>
  <arg name="controllers" default="joint_state_controller eff_joint_traj_controller"/>
  <arg name="stopped_controllers" default="joint_group_eff_controller"/>
  <arg name="gazebo_model_name" default="robot"/>
  <arg name="gui" default="false"/>
  <arg name="paused" default="false"/>
  <arg name="spawn_z" default="0.1"/>

  <param name="robot_description" textfile="$(find arm_gazebo)/urdf/arm.urdf"/>
  <rosparam file="$(arg controller_config_file)" command="load"/>

  <include file="$(find gazebo_ros)/launch/empty_world.launch">
    <arg name="world_name" value="worlds/empty.world"/>
    <arg name="paused" value="$(arg paused)"/>
    <arg name="gui" value="$(arg gui)"/>
  </include>

  <node name="spawn_gazebo_model" pkg="gazebo_ros" type="spawn_model"
    args="-urdf -param robot_description -model $(arg gazebo_model_name) -z $(arg spawn_z)"
    output="screen" respawn="false"/>

  <node name="ros_control_controller_spawner" pkg="controller_manager" type="spawner"
    args="$(arg controllers)" output="screen" respawn="false"/>

  <node name="ros_control_stopped_spawner" pkg="controller_manager" type="spawner"
    args="--stopped $(arg stopped_controllers)" output="screen" respawn="false"/>
</launch>
"""

PACKAGE = """<?xml version="1.0"?>
<package format="2">
  <name>arm_gazebo</name>
  <version>0.0.1</version>
  <description>A two-link arm in the simulator with ros_control.</description>
  <maintainer email="lab@example.com">lab</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""


@pytest.mark.multiprocess
@pytest.mark.slow
def test_a_ur_gazebo_shaped_launch_spawns_controllers_and_follows_a_goal(tmp_path):
    package = tmp_path / "arm_gazebo"
    for folder in ("launch", "config", "urdf"):
        (package / folder).mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE)
    (package / "launch" / "arm_control.launch").write_text(LAUNCH)
    shutil.copy(CONTROLLERS, package / "config" / "arm_controllers.yaml")
    shutil.copy(ARM, package / "urdf" / "arm.urdf")
    log_path = package / "launch.log"
    with (
        private_core(tmp_path) as uri,
        launched(uri, log_path, "launch/arm_control.launch"),
        Bus.connect(uri) as bus,
    ):
        from workbench.actionlib import SimpleActionClient
        from workbench.msgs import controller_manager_msgs as cm
        from workbench.msgs.control_msgs import FollowJointTrajectoryGoal
        from workbench.msgs.trajectory_msgs import JointTrajectoryPoint

        node = Node("arm_check", bus=bus)
        log = lambda: log_path.read_text(errors="replace")  # noqa: E731
        listing = node.create_client("/controller_manager/list_controllers", cm.ListControllers)

        def states() -> dict[str, str]:
            if not listing.service_is_ready():
                return {}
            reply = listing.call(cm.ListControllers.Request(), timeout=30)
            return {c.name: c.state for c in reply.controller}

        expected = {
            "joint_state_controller": "running",
            "eff_joint_traj_controller": "running",
            "joint_group_eff_controller": "initialized",
        }
        assert wait_for(lambda: states() == expected, timeout=180), log()
        client = SimpleActionClient(
            "/eff_joint_traj_controller/follow_joint_trajectory",
            "control_msgs/FollowJointTrajectoryAction",
            node,
        )
        assert client.wait_for_server(60), log()
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = list(JOINTS)
        point = JointTrajectoryPoint(positions=[0.5, -0.6], velocities=[0.0, 0.0])
        point.time_from_start.secs = 2
        goal.trajectory.points = [point]
        states_seen: list = []
        node.create_subscription("/joint_states", "sensor_msgs/JointState", states_seen.append)
        client.send_goal(goal)
        assert client.wait_for_result(120), log()
        assert client.get_result().error_code == 0, (client.get_result(), log())
        assert wait_for(lambda: states_seen, timeout=30), log()
        last = dict(zip(states_seen[-1].name, states_seen[-1].position, strict=True))
        assert [last[j] for j in JOINTS] == pytest.approx([0.5, -0.6], abs=0.05)
