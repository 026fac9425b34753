"""The builtin_interfaces types: ``from workbench.msgs.builtin_interfaces import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("builtin_interfaces")
