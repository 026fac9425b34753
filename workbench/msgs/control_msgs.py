"""The control_msgs types: ``from workbench.msgs.control_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("control_msgs")
