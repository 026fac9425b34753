"""The std_msgs types: ``from workbench.msgs.std_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("std_msgs")
