"""actionlib on the bus: goals, cancels, status, feedback and results (ROS 1's action protocol)."""
