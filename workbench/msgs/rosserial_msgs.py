"""The rosserial_msgs types: ``from workbench.msgs.rosserial_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("rosserial_msgs")
