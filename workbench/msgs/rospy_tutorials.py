"""The rospy_tutorials types: ``from workbench.msgs.rospy_tutorials import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("rospy_tutorials")
