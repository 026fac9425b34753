"""Gazebo's own model plugins (not the ROS ones), for models that name their libraries.

A ``<plugin filename="libFollowerPlugin.so">`` in a model loads the class
registered for it in :data:`workbench.sim.plugins.BUILTIN_PLUGINS`:

* ``libFollowerPlugin.so`` -- :mod:`.follower` (Experiment 6: a two-wheeled robot
  that drives towards the nearest thing its depth camera sees)

Their parameters and behaviour are those of Gazebo 11's ``plugins/`` folder.
"""
