"""Navigation: costmaps, global and local planners, AMCL and move_base (ROS's navigation stack).

Sits with :mod:`workbench.mapping` in the capability layer and uses its grids and
map files. Nodes: ``amcl amcl``, ``move_base move_base``.
"""
