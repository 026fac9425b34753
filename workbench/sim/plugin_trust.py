"""Which plugins a running simulator may load: the world's choice, and never a bus client's.

The world file, its models and the command line choose the plugins (their files load
as :mod:`workbench.sim.plugin_sources` says). Anything on the bus may ask for a spawn,
so a model spawned with ``/gazebo/spawn_urdf_model`` or ``/gazebo/spawn_sdf_model``
may only use plugins the running world already allowed:

* workbench's own (the ``libgazebo_ros_*.so`` names it maps to its Python plugins, and
  the shipped example files): they are not user code, so always;
* a Python file or a declared ``module:Class`` that the world itself loaded (the same
  resolved file, the same class).

Any other plugin makes the spawn fail before anything of it is read, unless the server
was started with ``allow_spawn_plugins`` (``workbench sim --allow-spawn-plugins``):
then whoever can reach the bus may run their code in the simulator.
"""

from __future__ import annotations

from workbench.sim.model_spec import PluginSpec
from workbench.sim.plugin_sources import (
    WORKBENCH,
    PluginRefusedError,
    PluginSource,
    clipped,
    locate_plugin,
)


class PluginTrust:
    """The plugins one server has allowed, and the rule for spawned models.

    Args:
        allow_spawn_plugins: Let spawned models load any plugin file or declared class.
    """

    def __init__(self, *, allow_spawn_plugins: bool = False) -> None:
        self.allow_spawn_plugins = allow_spawn_plugins
        self._allowed: set[str] = set()

    def admit(self, spec: PluginSpec) -> PluginSource:
        """Where the world's (or the program's) plugin ``spec`` comes from; it is allowed
        from now on for spawned models too.

        Raises:
            PluginRefusedError: The rule of :mod:`workbench.sim.plugin_sources` refuses it.
            SimulationError: Missing, or not a plugin.
        """
        source = locate_plugin(spec)
        if source.origin != WORKBENCH:
            self._allowed.add(source.key)
        return source

    def admit_spawned(self, spec: PluginSpec) -> PluginSource:
        """Where the plugin ``spec`` of a model spawned over the bus comes from.

        Raises:
            PluginRefusedError: Not one the world allowed (and spawned plugins are not
                allowed), or refused by the rule of :mod:`workbench.sim.plugin_sources`.
            SimulationError: Missing, or not a plugin.
        """
        # Where the file is only decides whether it is the world's: nothing of it is read.
        source = locate_plugin(spec, spawned=True, anywhere=True)
        if source.origin == WORKBENCH or self.allow_spawn_plugins:
            return source
        if source.key not in self._allowed:
            raise PluginRefusedError(
                f"plugin '{spec.name}' ({clipped(spec.filename)}) is not one the running world "
                "loaded; a spawned model may only use workbench's plugins and those the world "
                "allows",
                hint="load it from the world file or --plugin, or start the simulator with "
                "--allow-spawn-plugins if everyone on the bus may run code in it",
            )
        return source

    def refusal(self, spec: PluginSpec) -> PluginRefusedError | None:
        """Why a spawned model may not have ``spec``, or None (also None when it is merely
        missing or unavailable: the model is spawned without it, as Gazebo does)."""
        from workbench.errors import SimulationError

        try:
            self.admit_spawned(spec)
        except PluginRefusedError as error:
            return error
        except SimulationError:
            return None
        return None
