"""The shape_msgs types: ``from workbench.msgs.shape_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("shape_msgs")
