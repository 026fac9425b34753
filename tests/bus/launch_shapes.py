"""Launch files written for the tests in the shapes of real ROS 1 packages' launch files.

Two package trees, each file written here (not copied from any project):

* an arm in the shape of Universal Robots' ``ur_gazebo``: ``arm5_bringup.launch`` (arguments
  with ``doc``, ``$(dirname)`` and ``$(find)`` defaults) includes ``inc/load_arm5.launch.xml``,
  which includes ``inc/load_arm.launch.xml`` with ``pass_all_args`` and one more argument;
  that one sets ``robot_description`` from a xacro ``command=`` and chooses parameters with
  ``$(eval)``; ``inc/arm_control.launch.xml`` loads the controllers with ``<rosparam file=>``
  (rosparam's ``!degrees``/``deg()`` inside), includes a Gazebo-style ``empty_world.launch``
  when asked to, and starts the spawner nodes;
* a mobile robot in the shape of ROBOTIS' ``turtlebot3_slam``: ``bot_slam.launch`` takes its
  model from the environment, includes ``bot_$(arg slam_methods).launch`` (one file per
  method), and groups RViz under ``if="$(eval ...)"``; with ``<env>``, ``<remap>`` at every
  level, ``<machine>`` (this computer), ``<test>``, ``clear_params``, ``<rosparam
  command="delete|dump" subst_value>``, ``launch-prefix``, ``cwd``, ``respawn_delay``.

:func:`write_packages` writes both under a folder that then goes on ``ROS_PACKAGE_PATH``.
"""

from __future__ import annotations

from pathlib import Path

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.1</version>
<description>test package</description><maintainer email="a@b.c">a</maintainer>
<license>BSD</license><buildtool_depend>catkin</buildtool_depend></package>
"""

ARM = {
    "arm_gazebo/launch/arm5_bringup.launch": """<?xml version="1.0"?>
<launch>
  <arg name="robot_description_file" default="$(dirname)/inc/load_arm5.launch.xml"
       doc="Launch file that sets 'robot_description'."/>
  <arg name="joint_limit_params" default="$(find arm_description)/config/arm5/joint_limits.yaml"/>
  <arg name="kinematics_params" default="$(find arm_description)/config/arm5/kinematics.yaml"/>
  <arg name="controller_config_file" default="$(find arm_gazebo)/config/arm5_controllers.yaml"
       doc="ros_control controllers"/>
  <arg name="controllers" default="joint_state_controller eff_joint_traj_controller"/>
  <arg name="stopped_controllers" default="joint_group_eff_controller"/>
  <arg name="tf_prefix" default="" doc="tf_prefix of the robot"/>
  <arg name="tf_pub_rate" default="125"/>
  <arg name="paused" default="false"/>
  <arg name="gui" default="true"/>

  <include file="$(arg robot_description_file)">
    <arg name="joint_limit_params" value="$(arg joint_limit_params)"/>
    <arg name="kinematics_params" value="$(arg kinematics_params)"/>
  </include>

  <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher">
    <param name="publish_frequency" type="double" value="$(arg tf_pub_rate)"/>
    <param name="tf_prefix" value="$(arg tf_prefix)"/>
  </node>

  <include file="$(dirname)/inc/arm_control.launch.xml">
    <arg name="controller_config_file" value="$(arg controller_config_file)"/>
    <arg name="controllers" value="$(arg controllers)"/>
    <arg name="gui" value="$(arg gui)"/>
    <arg name="paused" value="$(arg paused)"/>
    <arg name="stopped_controllers" value="$(arg stopped_controllers)"/>
  </include>
</launch>
""",
    "arm_gazebo/launch/inc/load_arm5.launch.xml": """<?xml version="1.0"?>
<launch>
  <arg name="joint_limit_params" default="$(find arm_description)/config/arm5/joint_limits.yaml"/>
  <arg name="kinematics_params" default="$(find arm_description)/config/arm5/kinematics.yaml"/>
  <arg name="transmission_hw_interface" default="hardware_interface/EffortJointInterface"/>
  <arg name="safety_limits" default="false" doc="enable the safety controller"/>
  <arg name="safety_pos_margin" default="0.15"/>
  <arg name="safety_k_position" default="20"/>
  <include file="$(dirname)/load_arm.launch.xml" pass_all_args="true">
    <arg name="robot_model" value="arm5"/>
  </include>
</launch>
""",
    "arm_gazebo/launch/inc/load_arm.launch.xml": """<?xml version="1.0"?>
<launch>
  <arg name="robot_model" doc="Type of the arm"/>
  <arg name="joint_limit_params" doc="YAML of the joint limits"/>
  <arg name="kinematics_params"/>
  <arg name="transmission_hw_interface" default="hardware_interface/PositionJointInterface"/>
  <arg name="safety_limits" default="false"/>
  <arg name="safety_pos_margin" default="0.15"/>
  <arg name="safety_k_position" default="20"/>
  <param name="robot_description" command="$(find xacro)/xacro '$(find arm_gazebo)/urdf/arm.xacro'
    robot_model:=$(arg robot_model)
    joint_limit_params:=$(arg joint_limit_params)
    kinematics_params:=$(arg kinematics_params)
    transmission_hw_interface:=$(arg transmission_hw_interface)
    safety_limits:=$(arg safety_limits)
    safety_pos_margin:=$(arg safety_pos_margin)
    safety_k_position:=$(arg safety_k_position)"/>
  <param name="safety_active" value="$(eval safety_limits or safety_k_position > 10)"/>
  <param name="margin_mm" type="int" value="$(eval int(safety_pos_margin * 1000))"/>
  <group if="$(eval arg('robot_model') in ['arm5', 'arm10'] and not safety_limits)">
    <param name="model_family" value="$(eval robot_model.upper() + '_' + str(len(robot_model)))"/>
    <rosparam command="load" file="$(arg joint_limit_params)" ns="limits"/>
  </group>
  <rosparam command="load" file="$(arg kinematics_params)" param="kinematics"/>
</launch>
""",
    "arm_gazebo/launch/inc/arm_control.launch.xml": """<?xml version="1.0"?>
<launch>
  <arg name="controller_config_file" doc="Config file of the ROS-Control controllers."/>
  <arg name="controllers" default="joint_state_controller"/>
  <arg name="stopped_controllers" default="joint_group_eff_controller"/>
  <arg name="gazebo_model_name" default="robot"/>
  <arg name="gazebo_world" default="worlds/empty.world"/>
  <arg name="gui" default="true"/>
  <arg name="paused" default="false"/>
  <arg name="spawn_z" default="0.1"/>
  <arg name="start_gazebo" default="true"/>

  <rosparam file="$(arg controller_config_file)" command="load"/>

  <include file="$(find fake_gazebo_ros)/launch/empty_world.launch" if="$(arg start_gazebo)">
    <arg name="world_name" value="$(arg gazebo_world)"/>
    <arg name="paused" value="$(arg paused)"/>
    <arg name="gui" value="$(arg gui)"/>
  </include>

  <node name="spawn_gazebo_model" pkg="gazebo_ros" type="spawn_model"
    args="
      -urdf
      -param robot_description
      -model $(arg gazebo_model_name)
      -z $(arg spawn_z)"
    output="screen" respawn="false"/>
  <node name="ros_control_controller_spawner" pkg="controller_manager" type="spawner"
    args="$(arg controllers)" output="screen" respawn="false"/>
  <node name="ros_control_stopped_spawner" pkg="controller_manager" type="spawner"
    args="--stopped $(arg stopped_controllers)" output="screen" respawn="false"/>
</launch>
""",
    "arm_gazebo/config/arm5_controllers.yaml": """joint_state_controller:
  type: joint_state_controller/JointStateController
  publish_rate: 125
eff_joint_traj_controller:
  type: effort_controllers/JointTrajectoryController
  joints: [shoulder_pan_joint, shoulder_lift_joint, elbow_joint]
  gains:
    shoulder_pan_joint: {p: 4000, d: 200, i: 1, i_clamp: 1}
    shoulder_lift_joint: {p: 10000, d: 200, i: 1, i_clamp: 1}
  constraints:
    goal_time: 0.6
    stopped_velocity_tolerance: 0.05
  stop_trajectory_duration: 0.5
  state_publish_rate: 125
  action_monitor_rate: 10
joint_group_eff_controller:
  type: effort_controllers/JointGroupEffortController
  joints: [shoulder_pan_joint, shoulder_lift_joint, elbow_joint]
""",
    "arm_gazebo/urdf/arm.xacro": '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro"/>\n',
    "arm_description/config/arm5/joint_limits.yaml": """joint_limits:
  shoulder_pan:
    has_acceleration_limits: false
    has_effort_limits: true
    has_position_limits: true
    has_velocity_limits: true
    max_effort: 150.0
    max_position: !degrees  360.0
    max_velocity: !degrees  180.0
    min_position: !degrees -360.0
  elbow_joint:
    max_effort: 150.0
    max_position: deg(180)
    min_position: deg(-180)
    max_velocity: !radians pi
    soft_limit: rad(pi/2)
""",
    "arm_description/config/arm5/kinematics.yaml": """kinematics:
  shoulder:
    x: 0
    y: 0
    z: 0.089159
    roll: 0
    pitch: 0
    yaw: 0
  hash: calib_1234
""",
    "fake_gazebo_ros/launch/empty_world.launch": """<launch>
  <arg name="paused" default="false"/>
  <arg name="use_sim_time" default="true"/>
  <arg name="gui" default="true"/>
  <arg name="headless" default="false"/>
  <arg name="debug" default="false"/>
  <arg name="physics" default="ode"/>
  <arg name="verbose" default="false"/>
  <arg name="world_name" default="worlds/empty.world"/>
  <arg name="respawn_gazebo" default="false"/>
  <arg name="server_required" default="false"/>

  <arg unless="$(arg paused)" name="command_arg1" value=""/>
  <arg     if="$(arg paused)" name="command_arg1" value="-u"/>
  <arg unless="$(arg debug)" name="script_type" value="gzserver"/>
  <arg     if="$(arg debug)" name="script_type" value="debug"/>

  <param name="/use_sim_time" value="$(arg use_sim_time)"/>
  <env name="GAZEBO_MASTER_URI" value="$(optenv GAZEBO_MASTER_URI http://localhost:11345)"/>

  <node name="gazebo" pkg="gazebo_ros" type="$(arg script_type)" respawn="$(arg respawn_gazebo)"
        output="screen" required="$(arg server_required)"
        args="$(arg command_arg1) -e $(arg physics) $(arg world_name)"
        launch-prefix="$(optenv GAZEBO_PREFIX)"/>
  <group if="$(arg gui)">
    <node name="gazebo_gui" pkg="gazebo_ros" type="gzclient" respawn="false" output="screen"
          args="--verbose" cwd="node"/>
  </group>
</launch>
""",
    "xacro/scripts/xacro": "#!/bin/sh\n",
}

BOT = {
    "bot_slam/launch/bot_slam.launch": """<launch>
  <arg name="model" default="$(env BOT_MODEL)" doc="model type [small, large]"/>
  <arg name="slam_methods" default="gmapping" doc="slam type [gmapping, cartographer, hector]"/>
  <arg name="configuration_basename" default="bot_lds_2d.lua"/>
  <arg name="open_rviz" default="true"/>
  <arg name="multi_robot_name" default=""/>

  <machine name="here" address="localhost" default="true"/>
  <env name="BOT_LOG_LEVEL" value="$(optenv BOT_LOG_LEVEL   info   and more )"/>
  <remap from="scan" to="/base_scan"/>

  <include file="$(find bot_bringup)/launch/bot_remote.launch">
    <arg name="model" value="$(arg model)"/>
    <arg name="multi_robot_name" value="$(arg multi_robot_name)"/>
  </include>

  <include file="$(find bot_slam)/launch/bot_$(arg slam_methods).launch" ns="slam"
           clear_params="true">
    <arg name="model" value="$(arg model)"/>
    <arg name="configuration_basename" value="$(arg configuration_basename)"/>
    <env name="SLAM_THREADS" value="2"/>
  </include>

  <group if="$(eval open_rviz and slam_methods != 'hector')">
    <node pkg="rviz" type="rviz" name="rviz" required="true"
          args="-d $(find bot_slam)/rviz/bot_$(arg slam_methods).rviz"/>
  </group>
  <group unless="$(eval open_rviz)" ns="/headless">
    <param name="~note" value="no rviz"/>
    <node pkg="bot_slam" type="status_node" name="status" respawn="true" respawn_delay="2.5"/>
  </group>

  <test test-name="slam_map_test" pkg="bot_slam" type="map_test.py" time-limit="120.0">
    <param name="min_cells" value="1000"/>
  </test>
</launch>
""",
    "bot_slam/launch/bot_gmapping.launch": """<launch>
  <arg name="model" default="$(env BOT_MODEL)" doc="model type [small, large]"/>
  <arg name="configuration_basename" default="bot_lds_2d.lua"/>
  <arg name="set_base_frame" default="base_footprint"/>
  <arg name="set_odom_frame" default="odom"/>
  <arg name="set_map_frame"  default="map"/>

  <node pkg="gmapping" type="slam_gmapping" name="bot_slam_gmapping" output="screen"
        clear_params="true">
    <param name="base_frame" value="$(arg set_base_frame)"/>
    <param name="odom_frame" value="$(arg set_odom_frame)"/>
    <param name="map_frame"  value="$(arg set_map_frame)"/>
    <rosparam command="load" file="$(find bot_slam)/config/gmapping_params.yaml"/>
    <rosparam subst_value="true">
      model_name: $(arg model)
      scan_topic: scan
      sweep: !degrees 270
    </rosparam>
    <env name="GMAPPING_VERBOSE" value="0"/>
    <remap from="map" to="/map"/>
  </node>
  <rosparam command="delete" param="/old_map"/>
  <rosparam command="dump" file="$(dirname)/params.yaml" param="slam"/>
</launch>
""",
    "bot_slam/launch/bot_cartographer.launch": """<launch>
  <arg name="model" default="$(env BOT_MODEL)"/>
  <arg name="configuration_basename" default="bot_lds_2d.lua"/>
  <node pkg="cartographer_ros" type="cartographer_node" name="cartographer_node"
        args="-configuration_directory $(find bot_slam)/config
              -configuration_basename $(arg configuration_basename)"
        output="screen" launch-prefix="nice -n 5">
    <remap from="/imu" to="/flat_imu"/>
  </node>
  <node pkg="cartographer_ros" type="cartographer_occupancy_grid_node"
        name="cartographer_occupancy_grid_node" args="-resolution 0.05"/>
  <node pkg="bot_slam" type="flat_world_imu_node" name="flat_world_imu_node" output="screen">
    <remap from="imu_in" to="/imu"/>
    <remap from="imu_out" to="/flat_imu"/>
  </node>
</launch>
""",
    "bot_slam/launch/bot_hector.launch": """<launch>
  <arg name="model" default="$(env BOT_MODEL)"/>
  <arg name="configuration_basename" default="bot_lds_2d.lua"/>
  <arg name="base_frame" default="base_footprint"/>
  <arg name="map_size" default="2048"/>
  <node pkg="hector_mapping" type="hector_mapping" name="hector_mapping" output="screen">
    <param name="base_frame" value="$(arg base_frame)"/>
    <param name="map_resolution" value="0.050"/>
    <param name="map_size" value="$(arg map_size)"/>
    <param name="map_start_x" value="0.5"/>
    <param name="use_tf_scan_transformation" value="true"/>
    <param name="laser_z_min_value" value="-1.0"/>
    <param name="scan_subscriber_queue_size" value="5"/>
    <param name="pub_map_scanmatch_transform" value="true"/>
    <param name="tf_map_scanmatch_transform_frame_name" value="scanmatcher_frame"/>
  </node>
</launch>
""",
    "bot_slam/config/gmapping_params.yaml": """map_update_interval: 2.0
maxUrange: 3.0
sigma: 0.05
kernelSize: 1
lstep: 0.05
iterations: 5
linearUpdate: 1.0
angularUpdate: 0.2
temporalUpdate: 0.5
resampleThreshold: 0.5
particles: 100
xmin: -10.0
delta: 0.05
minimumScore: 50
""",
    "bot_bringup/launch/bot_remote.launch": """<launch>
  <arg name="model" default="$(env BOT_MODEL)" doc="model type [small, large]"/>
  <arg name="multi_robot_name" default=""/>
  <include file="$(find bot_bringup)/launch/includes/description.launch.xml">
    <arg name="model" value="$(arg model)"/>
  </include>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher">
    <param name="publish_frequency" type="double" value="50.0"/>
    <param name="tf_prefix" value="$(arg multi_robot_name)"/>
  </node>
</launch>
""",
    "bot_bringup/launch/includes/description.launch.xml": """<launch>
  <arg name="model"/>
  <arg name="urdf_file" default="$(find xacro)/xacro --inorder
       '$(find bot_bringup)/urdf/bot_$(arg model).urdf.xacro'"/>
  <param name="robot_description" command="$(arg urdf_file)"/>
</launch>
""",
}


def write_packages(root: Path) -> dict[str, Path]:
    """Both package trees under ``root``; the launch files by short name."""
    for files in (ARM, BOT):
        for relative, text in files.items():
            path = root / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
            package = root / relative.split("/")[0]
            (package / "package.xml").write_text(PACKAGE_XML.format(name=package.name))
    launch = {
        "arm5_bringup": root / "arm_gazebo/launch/arm5_bringup.launch",
        "bot_slam": root / "bot_slam/launch/bot_slam.launch",
        "empty_world": root / "fake_gazebo_ros/launch/empty_world.launch",
    }
    return launch
