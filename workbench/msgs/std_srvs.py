"""The std_srvs types: ``from workbench.msgs.std_srvs import ...``."""

from workbench.msgs._package import package_getattr

__getattr__, __dir__ = package_getattr("std_srvs")
