"""The nav_msgs types: ``from workbench.msgs.nav_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("nav_msgs")
