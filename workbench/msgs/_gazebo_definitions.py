"""The ``gazebo_msgs`` types of ROS 1 Noetic, as fields and constants.

Each entry lists a type's constants and fields (type, name, value) in their
original order and nothing else: that is all a ROS 1 md5sum depends on.
Messages come before the types that contain them, so each registers on its own.
"""

from __future__ import annotations

#: "gazebo_msgs/Name" -> .msg fields
MESSAGES: dict[str, str] = {
    "gazebo_msgs/ContactState": """\
string info
string collision1_name
string collision2_name
geometry_msgs/Wrench[] wrenches
geometry_msgs/Wrench total_wrench
geometry_msgs/Vector3[] contact_positions
geometry_msgs/Vector3[] contact_normals
float64[] depths
""",
    "gazebo_msgs/ContactsState": """\
Header header
gazebo_msgs/ContactState[] states
""",
    "gazebo_msgs/LinkState": """\
string link_name
geometry_msgs/Pose pose
geometry_msgs/Twist twist
string reference_frame
""",
    "gazebo_msgs/LinkStates": """\
string[] name
geometry_msgs/Pose[] pose
geometry_msgs/Twist[] twist
""",
    "gazebo_msgs/ModelState": """\
string model_name
geometry_msgs/Pose pose
geometry_msgs/Twist twist
string reference_frame
""",
    "gazebo_msgs/ModelStates": """\
string[] name
geometry_msgs/Pose[] pose
geometry_msgs/Twist[] twist
""",
    "gazebo_msgs/ODEJointProperties": """\
float64[] damping
float64[] hiStop
float64[] loStop
float64[] erp
float64[] cfm
float64[] stop_erp
float64[] stop_cfm
float64[] fudge_factor
float64[] fmax
float64[] vel
""",
    "gazebo_msgs/ODEPhysics": """\
bool auto_disable_bodies
uint32 sor_pgs_precon_iters
uint32 sor_pgs_iters
float64 sor_pgs_w
float64 sor_pgs_rms_error_tol
float64 contact_surface_layer
float64 contact_max_correcting_vel
float64 cfm
float64 erp
uint32 max_contacts
""",
    "gazebo_msgs/SensorPerformanceMetric": """\
string name
float64 sim_update_rate
float64 real_update_rate
float64 fps
""",
    "gazebo_msgs/PerformanceMetrics": """\
Header header
float64 real_time_factor
gazebo_msgs/SensorPerformanceMetric[] sensors
""",
    "gazebo_msgs/WorldState": """\
Header header
string[] name
geometry_msgs/Pose[] pose
geometry_msgs/Twist[] twist
geometry_msgs/Wrench[] wrench
""",
}

_RESULT = """\
---
bool success
string status_message
"""

#: "gazebo_msgs/Name" -> .srv fields (request, ``---``, response)
SERVICES: dict[str, str] = {
    "gazebo_msgs/ApplyBodyWrench": """\
string body_name
string reference_frame
geometry_msgs/Point reference_point
geometry_msgs/Wrench wrench
time start_time
duration duration
"""
    + _RESULT,
    "gazebo_msgs/ApplyJointEffort": """\
string joint_name
float64 effort
time start_time
duration duration
"""
    + _RESULT,
    "gazebo_msgs/BodyRequest": """\
string body_name
---
""",
    "gazebo_msgs/DeleteLight": """\
string light_name
"""
    + _RESULT,
    "gazebo_msgs/DeleteModel": """\
string model_name
"""
    + _RESULT,
    "gazebo_msgs/GetJointProperties": """\
string joint_name
---
uint8 type
uint8 REVOLUTE=0
uint8 CONTINUOUS=1
uint8 PRISMATIC=2
uint8 FIXED=3
uint8 BALL=4
uint8 UNIVERSAL=5
float64[] damping
float64[] position
float64[] rate
bool success
string status_message
""",
    "gazebo_msgs/GetLightProperties": """\
string light_name
---
std_msgs/ColorRGBA diffuse
float64 attenuation_constant
float64 attenuation_linear
float64 attenuation_quadratic
bool success
string status_message
""",
    "gazebo_msgs/GetLinkProperties": """\
string link_name
---
geometry_msgs/Pose com
bool gravity_mode
float64 mass
float64 ixx
float64 ixy
float64 ixz
float64 iyy
float64 iyz
float64 izz
bool success
string status_message
""",
    "gazebo_msgs/GetLinkState": """\
string link_name
string reference_frame
---
gazebo_msgs/LinkState link_state
bool success
string status_message
""",
    "gazebo_msgs/GetModelProperties": """\
string model_name
---
string parent_model_name
string canonical_body_name
string[] body_names
string[] geom_names
string[] joint_names
string[] child_model_names
bool is_static
bool success
string status_message
""",
    "gazebo_msgs/GetModelState": """\
string model_name
string relative_entity_name
---
Header header
geometry_msgs/Pose pose
geometry_msgs/Twist twist
bool success
string status_message
""",
    "gazebo_msgs/GetPhysicsProperties": """\
---
float64 time_step
bool pause
float64 max_update_rate
geometry_msgs/Vector3 gravity
gazebo_msgs/ODEPhysics ode_config
bool success
string status_message
""",
    "gazebo_msgs/GetWorldProperties": """\
---
float64 sim_time
string[] model_names
bool rendering_enabled
bool success
string status_message
""",
    "gazebo_msgs/JointRequest": """\
string joint_name
---
""",
    "gazebo_msgs/SetJointProperties": """\
string joint_name
gazebo_msgs/ODEJointProperties ode_joint_config
"""
    + _RESULT,
    "gazebo_msgs/SetJointTrajectory": """\
string model_name
trajectory_msgs/JointTrajectory joint_trajectory
geometry_msgs/Pose model_pose
bool set_model_pose
bool disable_physics_updates
"""
    + _RESULT,
    "gazebo_msgs/SetLightProperties": """\
string light_name
bool cast_shadows
std_msgs/ColorRGBA diffuse
std_msgs/ColorRGBA specular
float64 attenuation_constant
float64 attenuation_linear
float64 attenuation_quadratic
geometry_msgs/Vector3 direction
geometry_msgs/Pose pose
"""
    + _RESULT,
    "gazebo_msgs/SetLinkProperties": """\
string link_name
geometry_msgs/Pose com
bool gravity_mode
float64 mass
float64 ixx
float64 ixy
float64 ixz
float64 iyy
float64 iyz
float64 izz
"""
    + _RESULT,
    "gazebo_msgs/SetLinkState": """\
gazebo_msgs/LinkState link_state
"""
    + _RESULT,
    "gazebo_msgs/SetModelConfiguration": """\
string model_name
string urdf_param_name
string[] joint_names
float64[] joint_positions
"""
    + _RESULT,
    "gazebo_msgs/SetModelState": """\
gazebo_msgs/ModelState model_state
"""
    + _RESULT,
    "gazebo_msgs/SetPhysicsProperties": """\
float64 time_step
float64 max_update_rate
geometry_msgs/Vector3 gravity
gazebo_msgs/ODEPhysics ode_config
"""
    + _RESULT,
    "gazebo_msgs/SpawnModel": """\
string model_name
string model_xml
string robot_namespace
geometry_msgs/Pose initial_pose
string reference_frame
"""
    + _RESULT,
}
