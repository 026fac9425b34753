"""The diagnostic_msgs types: ``from workbench.msgs.diagnostic_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("diagnostic_msgs")
