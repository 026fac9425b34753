"""The tf2_msgs types: ``from workbench.msgs.tf2_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("tf2_msgs")
