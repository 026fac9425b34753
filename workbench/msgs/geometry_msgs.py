"""The geometry_msgs types: ``from workbench.msgs.geometry_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("geometry_msgs")
