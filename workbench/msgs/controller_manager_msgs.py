"""The controller_manager_msgs types: ``from workbench.msgs.controller_manager_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("controller_manager_msgs")
