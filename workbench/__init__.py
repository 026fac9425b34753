"""workbench: a ROS-free robotics lab workbench.

Importing this package is cheap: it does not import pydrake, ompl or zenoh.
Capabilities live in subpackages (``workbench.model``, ``workbench.bus``,
``workbench.tf``, ``workbench.planning``, ``workbench.mapping`` ...), each
imported on demand.
"""

from __future__ import annotations

from workbench.errors import WorkbenchError

__version__ = "0.1.0"

__all__ = ["WorkbenchError", "__version__"]
