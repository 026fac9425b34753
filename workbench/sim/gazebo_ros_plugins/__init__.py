"""gazebo_plugins' ROS drive and state plugins, for models that name their libraries.

A ``<plugin filename="libgazebo_ros_diff_drive.so">`` in a URDF ``<gazebo>`` block
or an SDF model loads the class registered for it in
:data:`workbench.sim.plugins.BUILTIN_PLUGINS`:

* ``libgazebo_ros_diff_drive.so`` -- :mod:`.diff_drive`
* ``libgazebo_ros_joint_state_publisher.so`` -- :mod:`.joint_state_publisher`
* ``libgazebo_ros_planar_move.so`` -- :mod:`.planar_move`

Their parameters, defaults, topics and frames are those of gazebo_ros_pkgs'
noetic plugins; :mod:`.ros_context` says how namespaces and frames are resolved.
"""
