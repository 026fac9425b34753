"""The rosgraph_msgs types: ``from workbench.msgs.rosgraph_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("rosgraph_msgs")
