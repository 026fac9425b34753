"""ros_control in the simulator: ``libgazebo_ros_control.so``, the controller manager and controllers.

Modules: :mod:`.urdf_info` (transmissions and joint limits), :mod:`.hardware`
(gazebo_ros_control's default robot hardware), :mod:`.pid` (control_toolbox's PID),
:mod:`.controllers` and :mod:`.trajectory_controller` (ros_controllers),
:mod:`.trajectory` (joint trajectories), :mod:`.manager` (the controller manager and its
services), :mod:`.plugin` (the Gazebo plugin) and :mod:`.nodes` (``controller_manager``'s
``spawner`` and ``controller_manager`` nodes).
"""
