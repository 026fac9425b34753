"""The stereo_msgs types: ``from workbench.msgs.stereo_msgs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("stereo_msgs")
