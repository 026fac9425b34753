"""The gazebo_msgs types: ``from workbench.msgs.gazebo_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("gazebo_msgs")
