"""ROS 1's ``interactive_markers`` Python package for the lab's scripts (one prefix added).

``from workbench.compat.interactive_markers.interactive_marker_server import *`` and
``from workbench.compat.interactive_markers.menu_handler import *``.
"""
