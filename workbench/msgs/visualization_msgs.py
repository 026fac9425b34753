"""The visualization_msgs types: ``from workbench.msgs.visualization_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("visualization_msgs")
