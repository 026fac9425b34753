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
``examples/gazebo/plugins``) or an entry point ``package.module:Class``. The
file must define exactly one plugin class (a subclass of :class:`Plugin`), or
name it: ``my_plugin.py:MyPlugin``.

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
import os
import sys
import traceback
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lxml import etree

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec

if TYPE_CHECKING:
    from workbench.sim.handles import ModelHandle, WorldHandle

_LOG = logging.getLogger("workbench.sim.plugins")

#: Gazebo's ROS plugins that workbench provides, by their library name: ``module:Class``.
#: A ``<plugin filename="libgazebo_ros_diff_drive.so">`` in a model loads the class here.
BUILTIN_PLUGINS: dict[str, str] = {
    # gazebo_ros drive and state plugins (workbench.sim.gazebo_ros_plugins)
    "libgazebo_ros_diff_drive.so": "workbench.sim.gazebo_ros_plugins.diff_drive:GazeboRosDiffDrive",
    "libgazebo_ros_joint_state_publisher.so": (
        "workbench.sim.gazebo_ros_plugins.joint_state_publisher:GazeboRosJointStatePublisher"
    ),
    "libgazebo_ros_planar_move.so": (
        "workbench.sim.gazebo_ros_plugins.planar_move:GazeboRosPlanarMove"
    ),
    "libgazebo_ros_control.so": "workbench.sim.ros_control.plugin:GazeboRosControl",
    "libgazebo_ros_imu.so": "workbench.sim.gazebo_ros_plugins.imu:GazeboRosImu",
    "libgazebo_ros_p3d.so": "workbench.sim.gazebo_ros_plugins.p3d:GazeboRosP3D",
    "libgazebo_ros_ft_sensor.so": "workbench.sim.gazebo_ros_plugins.ft_sensor:GazeboRosFT",
    # gazebo_ros sensor plugins (workbench.sim.sensors)
    "libgazebo_ros_laser.so": "workbench.sim.sensors.laser_plugin:GazeboRosLaser",
    "libgazebo_ros_gpu_laser.so": "workbench.sim.sensors.laser_plugin:GazeboRosLaser",
    "libgazebo_ros_camera.so": "workbench.sim.sensors.camera_plugin:GazeboRosCamera",
    "libgazebo_ros_openni_kinect.so": "workbench.sim.sensors.camera_plugin:GazeboRosOpenniKinect",
    "libgazebo_ros_depth_camera.so": "workbench.sim.sensors.camera_plugin:GazeboRosDepthCamera",
    "libgazebo_ros_imu_sensor.so": "workbench.sim.sensors.imu_plugin:GazeboRosImuSensor",
    "libgazebo_ros_bumper.so": "workbench.sim.sensors.bumper_plugin:GazeboRosBumper",
    # Gazebo's own model plugins (workbench.sim.gazebo_plugins)
    "libFollowerPlugin.so": "workbench.sim.gazebo_plugins.follower:FollowerPlugin",
}


class UnavailablePluginError(SimulationError):
    """A Gazebo plugin library workbench does not provide: the model runs without it."""


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


def plugin_search_path(base_dir: Path | None) -> list[Path]:
    """Folders a plugin file name is looked up in, first match wins."""
    from workbench.paths import examples_dir

    folders = [base_dir] if base_dir is not None else []
    for variable in ("GAZEBO_PLUGIN_PATH", "WORKBENCH_PLUGIN_PATH"):
        folders += [Path(p) for p in os.environ.get(variable, "").split(os.pathsep) if p]
    folders.append(examples_dir() / "gazebo" / "plugins")
    return folders


def load_plugin_class(spec: PluginSpec) -> type[Plugin]:
    """The plugin class ``spec.filename`` names.

    Raises:
        SimulationError: The file is missing, cannot be imported, or defines no
            (or several) plugin classes; the message names the file.
    """
    filename, _, class_name = spec.filename.partition(":")
    where = f" (declared in {spec.source})" if spec.source else ""
    builtin = BUILTIN_PLUGINS.get(Path(spec.filename).name)
    if builtin is not None:
        module_name, _, class_name = builtin.partition(":")
        return _plugin_class(importlib.import_module(module_name), class_name, spec, builtin)
    if filename.startswith("lib") and filename.endswith(".so"):
        provided = ", ".join(sorted(BUILTIN_PLUGINS)) or "none"
        raise UnavailablePluginError(
            f"Gazebo plugin '{filename}' ('{spec.name}'{where}) is not provided by workbench; "
            "the model runs without it",
            hint=f"workbench provides {provided}, and Python plugins (README: gazebo_ros plugins)",
        )
    if filename.endswith(".py"):
        path = _find_file(filename, spec.base_dir)
        if path is None:
            folders = ", ".join(str(p) for p in plugin_search_path(spec.base_dir))
            raise SimulationError(
                f"plugin '{spec.name}': file '{filename}' not found{where}",
                hint=f"looked in {folders}; add folders to GAZEBO_PLUGIN_PATH",
            )
        module = _import_file(path, spec)
        source = str(path)
    elif class_name:
        try:
            module = importlib.import_module(filename)
        except Exception as error:  # noqa: BLE001 - any import failure is the plugin's
            raise SimulationError(
                f"plugin '{spec.name}': cannot import '{filename}'{where}: {error}"
            ) from None
        source = filename
    else:
        raise SimulationError(
            f"plugin '{spec.name}': '{spec.filename}' is not a Python plugin{where}",
            hint="give a .py file or module:Class (Gazebo's C++ plugins do not run here)",
        )
    return _plugin_class(module, class_name, spec, source)


def _find_file(filename: str, base_dir: Path | None) -> Path | None:
    candidate = Path(filename).expanduser()
    if candidate.is_absolute():
        return candidate if candidate.is_file() else None
    for folder in plugin_search_path(base_dir):
        if (folder / candidate).is_file():
            return (folder / candidate).resolve()
    return None


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
