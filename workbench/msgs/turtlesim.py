"""The turtlesim types: ``from workbench.msgs.turtlesim import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("turtlesim")
