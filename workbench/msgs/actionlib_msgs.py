"""The actionlib_msgs types: ``from workbench.msgs.actionlib_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("actionlib_msgs")
