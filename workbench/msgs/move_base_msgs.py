"""The move_base_msgs types: ``from workbench.msgs.move_base_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("move_base_msgs")
