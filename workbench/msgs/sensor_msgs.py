"""The sensor_msgs types: ``from workbench.msgs.sensor_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("sensor_msgs")
