"""The beginner_tutorials types: ``from workbench.msgs.beginner_tutorials import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("beginner_tutorials")
