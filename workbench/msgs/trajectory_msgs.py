"""The trajectory_msgs types: ``from workbench.msgs.trajectory_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("trajectory_msgs")
