"""Simulator plugins written in Python: Gazebo's world, model and sensor plugins.

A plugin is a class with ``load(...)`` and ``update(info)``::

    from workbench.sim.plugins import ModelPlugin

    class ModelPush(ModelPlugin):
        def load(self, model, sdf, node):
            self.model = model
            self.speed = sdf.get("velocity", 0.3)

        def update(self, info):
            self.model.set_linear_velocity([self.speed, 0.0, 0.0])

It is attached with ``<plugin name="push" filename="model_push.py"/>`` in an SDF
model or world, in a URDF ``<gazebo>`` block, or with ``workbench sim --plugin``.
``filename`` is a Python file (looked up beside the file that declares it, then
in ``GAZEBO_PLUGIN_PATH`` and ``WORKBENCH_PLUGIN_PATH``, then in workbench's
``examples/gazebo/plugins``) or a class an installed package declares as a
``workbench.plugins`` entry point (``package.module:Class``). Nothing else is
imported: :mod:`workbench.sim.plugin_sources` has the rule. The file must define
exactly one plugin class (a subclass of :class:`Plugin`), or name it:
``my_plugin.py:MyPlugin``.

``update`` runs before every physics step, or every ``1 / update_rate`` seconds
of simulated time when the class (or the ``<update_rate>`` parameter) sets one.
A plugin may also set ``self.update_rate`` in ``load`` (a sensor plugin takes its
sensor's ``<update_rate>``); it is skipped while its ``active()`` says False. Joint efforts and link wrenches a plugin applies
last until its next update.
A plugin that raises is reported with its file and line and disabled; the
simulation keeps running.
"""

from __future__ import annotations

import importlib
import importlib.util
import logging
import sys
import traceback
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lxml import etree

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec
from workbench.sim.plugin_sources import (
    BUILTIN_PLUGINS,
    PluginRefusedError,
    PluginSource,
    UnavailablePluginError,
    locate_plugin,
    plugin_search_path,
)

__all__ = [
    "BUILTIN_PLUGINS",
    "ModelPlugin",
    "Plugin",
    "PluginRefusedError",
    "PluginSetupError",
    "SdfElement",
    "SensorPlugin",
    "UnavailablePluginError",
    "UpdateInfo",
    "WorldPlugin",
    "describe_failure",
    "load_plugin_class",
    "plugin_search_path",
]

if TYPE_CHECKING:
    from workbench.sim.handles import ModelHandle, WorldHandle

_LOG = logging.getLogger("workbench.sim.plugins")


class PluginSetupError(SimulationError):
    """A plugin refuses what it was given in ``load`` (one line; the model runs without it)."""


@dataclass(frozen=True)
class UpdateInfo:
    """What an update is told: simulated time and the time since the last update, s."""

    sim_time: float
    dt: float


class SdfElement:
    """The ``<plugin>`` element's parameters, read like Gazebo's ``sdf::Element``."""

    def __init__(self, xml: str, sensor: str = "", reference: str | None = None) -> None:
        self.element = etree.fromstring(xml.encode()) if xml.strip() else etree.Element("plugin")
        #: The enclosing ``<sensor>`` element of a sensor plugin (lxml), else None.
        self.sensor = etree.fromstring(sensor.encode()) if sensor.strip() else None
        #: The link a sensor plugin's sensor is on (``PluginSpec.reference``), else None.
        self.reference = reference

    @property
    def name(self) -> str:
        return str(self.element.get("name", ""))

    def has(self, key: str) -> bool:
        """True when a child element ``key`` exists."""
        return self.element.find(key) is not None

    def get(self, key: str, default: Any = None) -> Any:
        """The child ``key``'s text, converted to ``default``'s type (or to a number if it is one)."""
        child = self.element.find(key)
        if child is None or child.text is None:
            return default
        text = child.text.strip()
        if isinstance(default, bool):
            return text.lower() in ("1", "true", "yes", "on")
        if isinstance(default, (int, float)) and not isinstance(default, bool):
            try:
                return type(default)(float(text)) if isinstance(default, int) else float(text)
            except ValueError:
                raise SimulationError(
                    f"plugin '{self.name}': <{key}> must be a number, got '{text}'"
                ) from None
        try:
            return float(text) if default is None and _is_number(text) else text
        except ValueError:
            return text


class Plugin:
    """Base of every plugin. Override :meth:`update` (and ``load``); set ``update_rate`` (Hz)."""

    kind = "model"
    update_rate: float = 0.0

    def update(self, info: UpdateInfo) -> None:
        """Called before physics steps (see the module docstring)."""

    def active(self) -> bool:
        """Whether :meth:`update` is wanted now. An idle plugin is skipped and does not cut
        the physics into its update periods (a sensor plugin nobody listens to, as
        gazebo_ros's plugins check ``getNumSubscribers()`` before they compute)."""
        return True

    def reset(self) -> None:
        """Called when the world or simulation is reset."""

    def close(self) -> None:
        """Called when the plugin's model is deleted or the server stops."""


class WorldPlugin(Plugin):
    """A plugin of the world: ``load(world, sdf, node)``."""

    kind = "world"

    def load(self, world: WorldHandle, sdf: SdfElement, node: Any) -> None:
        """Set up; ``world`` gives models and time, ``node`` is this plugin's bus node."""


class ModelPlugin(Plugin):
    """A plugin of one model: ``load(model, sdf, node)``."""

    kind = "model"

    def load(self, model: ModelHandle, sdf: SdfElement, node: Any) -> None:
        """Set up; ``model`` reads and moves the model, ``node`` is this plugin's bus node."""


class SensorPlugin(ModelPlugin):
    """A plugin of a sensor on a link (``reference`` names the link)."""

    kind = "sensor"


def load_plugin_class(spec: PluginSpec, source: PluginSource | None = None) -> type[Plugin]:
    """The plugin class ``spec.filename`` names.

    Args:
        spec: The plugin.
        source: Where its code is, as :func:`~workbench.sim.plugin_sources.locate_plugin`
            found it (None: found here, by the rule for a world's plugins).

    Raises:
        PluginRefusedError: A file or class the rule does not allow (nothing was read).
        UnavailablePluginError: A Gazebo library workbench does not provide.
        SimulationError: The file is missing, cannot be imported, or defines no
            (or several) plugin classes; the message names the file.
    """
    source = source if source is not None else locate_plugin(spec)
    if source.path is not None:
        return _plugin_class(
            _import_file(source.path, spec), source.class_name, spec, str(source.path)
        )
    where = f" (declared in {spec.source})" if spec.source else ""
    try:
        module = importlib.import_module(source.module)
    except Exception as error:  # noqa: BLE001 - any import failure is the plugin's
        raise SimulationError(
            f"plugin '{spec.name}': cannot import '{source.module}'{where}: {error}"
        ) from None
    return _plugin_class(module, source.class_name, spec, source.key)


def _import_file(path: Path, spec: PluginSpec) -> Any:
    name = f"workbench_plugin_{abs(hash(str(path))):x}"
    loader_spec = importlib.util.spec_from_file_location(name, path)
    if loader_spec is None or loader_spec.loader is None:
        raise SimulationError(f"plugin '{spec.name}': cannot load {path}")
    module = importlib.util.module_from_spec(loader_spec)
    sys.modules[name] = module
    try:
        loader_spec.loader.exec_module(module)
    except Exception as error:  # noqa: BLE001 - report the plugin's own failure
        del sys.modules[name]
        raise SimulationError(
            f"plugin '{spec.name}': {_where(error, path)}: {type(error).__name__}: {error}"
        ) from None
    return module


def _plugin_class(module: Any, class_name: str, spec: PluginSpec, source: str) -> type[Plugin]:
    if class_name:
        found = getattr(module, class_name, None)
        if not (isinstance(found, type) and issubclass(found, Plugin)):
            raise SimulationError(
                f"plugin '{spec.name}': {source} has no plugin class '{class_name}'",
                hint="subclass workbench.sim.plugins.ModelPlugin or WorldPlugin",
            )
        return found
    classes = [
        value
        for value in vars(module).values()
        if isinstance(value, type)
        and issubclass(value, Plugin)
        and value.__module__ == module.__name__
    ]
    if len(classes) != 1:
        problem = "defines no plugin class" if not classes else "defines several plugin classes"
        raise SimulationError(
            f"plugin '{spec.name}': {source} {problem}",
            hint="subclass workbench.sim.plugins.ModelPlugin or WorldPlugin, or name the "
            "class: file.py:ClassName",
        )
    return classes[0]


def describe_failure(error: BaseException, plugin: Any) -> str:
    """``file:line: Type: message`` of the innermost frame in the plugin's own file."""
    module = sys.modules.get(type(plugin).__module__)
    path = getattr(module, "__file__", None)
    return f"{_where(error, Path(path) if path else None)}: {type(error).__name__}: {error}"


def _where(error: BaseException, path: Path | None) -> str:
    frames = traceback.extract_tb(error.__traceback__)
    if isinstance(error, SyntaxError) and error.filename:
        return f"{error.filename}:{error.lineno}"
    mine = [f for f in frames if path is not None and Path(f.filename) == path]
    frame = mine[-1] if mine else (frames[-1] if frames else None)
    return f"{frame.filename}:{frame.lineno}" if frame is not None else str(path or "?")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
