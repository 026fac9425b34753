"""Drop-in modules for the lab's ROS 1 scripts: ``from workbench.compat import rospy, tf``."""
