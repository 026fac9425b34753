"""Where a plugin's code comes from, decided before any of it is imported.

A plugin is code the user chose. The ``filename`` of a ``<plugin>`` names one of:

* a Gazebo library workbench provides (``libgazebo_ros_diff_drive.so``, see
  :data:`BUILTIN_PLUGINS`), or a workbench class they map to: workbench's own code,
  always allowed;
* a Python file (``my_plugin.py``, optionally ``my_plugin.py:MyClass``), looked up in
  the folder of the world or model that declares it, then in ``GAZEBO_PLUGIN_PATH``
  and ``WORKBENCH_PLUGIN_PATH``, then in workbench's ``examples/gazebo/plugins``. A
  file name may not climb out with ``..``, and an absolute path must lie in one of
  those folders; anything else is refused before the file is read;
* ``module:Class`` of an installed package that declares it as an entry point of the
  ``workbench.plugins`` group (or that entry point's name). Other modules are never
  imported.

A :class:`~workbench.sim.model_spec.PluginSpec` built by a program (no ``base_dir``:
Python code, the command line) may name a file anywhere: the program chose it. A model
spawned over the bus has no folder of its own (see :mod:`workbench.sim.plugin_trust`).
"""

from __future__ import annotations

import functools
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path, PurePath

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec

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

#: The entry-point group installed packages declare their plugin classes in.
ENTRY_POINT_GROUP = "workbench.plugins"
#: Longest plugin ``name``, characters (it becomes part of the plugin's node name).
MAX_PLUGIN_NAME = 256
#: Longest plugin ``filename``, characters.
MAX_PLUGIN_FILENAME = 1024

#: A dotted module path and a class name: ``package.module:Class``.
_MODULE_CLASS = re.compile(r"[A-Za-z_]\w*(\.[A-Za-z_]\w*)*:[A-Za-z_]\w*", re.ASCII)
_CLASS_NAME = re.compile(r"[A-Za-z_]\w*", re.ASCII)
#: Characters that would break a message's one line (C0 controls, DEL).
_CONTROL = re.compile(r"[\x00-\x1f\x7f]")

#: Where the plugin's code comes from (:attr:`PluginSource.origin`).
WORKBENCH, FILE, ENTRY_POINT = "workbench", "file", "entry point"


class UnavailablePluginError(SimulationError):
    """A Gazebo plugin library workbench does not provide: the model runs without it."""


class PluginRefusedError(SimulationError):
    """A plugin that may not be loaded from where it is named (refused before any import)."""


@dataclass(frozen=True)
class PluginSource:
    """The code a plugin names, found without importing it.

    Attributes:
        origin: :data:`WORKBENCH` (a built-in class or a shipped example file), :data:`FILE`
            (a Python file of the user's) or :data:`ENTRY_POINT` (a declared class).
        class_name: The class to load ("" for a file: its one plugin class).
        path: The Python file (resolved), or None for a module.
        module: The module's dotted name, or "" for a file.
    """

    origin: str
    class_name: str
    path: Path | None = None
    module: str = ""

    @property
    def key(self) -> str:
        """What identifies the code: the file's path or ``module:Class``."""
        return str(self.path) if self.path is not None else f"{self.module}:{self.class_name}"


def plugin_search_path(base_dir: Path | None) -> list[Path]:
    """Folders a plugin file name is looked up in, first match wins."""
    folders = [base_dir] if base_dir is not None else []
    for variable in ("GAZEBO_PLUGIN_PATH", "WORKBENCH_PLUGIN_PATH"):
        folders += [Path(p) for p in os.environ.get(variable, "").split(os.pathsep) if p]
    folders.append(shipped_plugins_dir())
    return folders


def shipped_plugins_dir() -> Path:
    """workbench's example plugins (``examples/gazebo/plugins``)."""
    from workbench.paths import examples_dir

    return examples_dir() / "gazebo" / "plugins"


def locate_plugin(
    spec: PluginSpec, *, spawned: bool = False, anywhere: bool = False
) -> PluginSource:
    """The code ``spec`` names, checked against the rule of this module; nothing is imported.

    Args:
        spec: The plugin.
        spawned: The model came over the bus: it has no folder of its own, so a file
            name is looked up in the plugin path and workbench's examples only.
        anywhere: An absolute file path may lie anywhere (the user or the program chose
            it). Implied for a spec without ``base_dir`` that was not spawned.

    Raises:
        PluginRefusedError: A name or file name too long, a file outside the allowed
            folders, or a ``module:Class`` no package declares.
        UnavailablePluginError: A Gazebo library workbench does not provide.
        SimulationError: A file that is not there, or a file name that is not a plugin.
    """
    where = f" (declared in {spec.source})" if spec.source else ""
    _check_text(spec, where)
    builtin = BUILTIN_PLUGINS.get(PurePath(spec.filename).name)
    if builtin is not None:
        module, _, class_name = builtin.partition(":")
        return PluginSource(WORKBENCH, class_name, module=module)
    if spec.filename in BUILTIN_PLUGINS.values():
        module, _, class_name = spec.filename.partition(":")
        return PluginSource(WORKBENCH, class_name, module=module)
    filename, _, class_name = spec.filename.partition(":")
    if filename.endswith(".py"):
        if class_name and not _CLASS_NAME.fullmatch(class_name):
            raise SimulationError(
                f"plugin '{spec.name}': '{clipped(class_name)}' is not a Python class name{where}"
            )
        base_dir = None if spawned else spec.base_dir
        anywhere = anywhere or (spec.base_dir is None and not spawned)
        path = _find_file(spec, filename, base_dir, anywhere=anywhere, where=where)
        origin = WORKBENCH if _inside(path, shipped_plugins_dir()) else FILE
        return PluginSource(origin, class_name, path=path)
    declared = _entry_point(spec.filename)
    if declared is not None:
        module, _, class_name = declared.partition(":")
        return PluginSource(ENTRY_POINT, class_name, module=module)
    if filename.startswith("lib") and filename.endswith(".so"):
        provided = ", ".join(sorted(BUILTIN_PLUGINS)) or "none"
        raise UnavailablePluginError(
            f"Gazebo plugin '{filename}' ('{spec.name}'{where}) is not provided by workbench; "
            "the model runs without it",
            hint=f"workbench provides {provided}, and Python plugins (README: gazebo_ros plugins)",
        )
    if class_name:
        raise PluginRefusedError(
            f"plugin '{spec.name}'{where}: '{clipped(spec.filename)}' is not a declared plugin "
            f"class; a module:Class plugin loads only when its package declares it as a "
            f"'{ENTRY_POINT_GROUP}' entry point",
            hint="declare it in the package's pyproject.toml, or give a .py file beside the world",
        )
    raise SimulationError(
        f"plugin '{spec.name}': '{clipped(spec.filename)}' is not a Python plugin{where}",
        hint="give a .py file or module:Class (Gazebo's C++ plugins do not run here)",
    )


def _check_text(spec: PluginSpec, where: str) -> None:
    for what, value, most in (
        ("name", spec.name, MAX_PLUGIN_NAME),
        ("filename", spec.filename, MAX_PLUGIN_FILENAME),
    ):
        name = clipped(spec.name, 80) if what == "filename" else clipped(spec.name, 43)
        if len(value) > most:
            raise PluginRefusedError(
                f"plugin '{name}'{where}: its {what} is {len(value):,} characters "
                f"long, more than the {most:,} a plugin {what} may have",
                hint=f"use a shorter {what}",
            )
        if _CONTROL.search(value):
            raise PluginRefusedError(
                f"plugin '{name}'{where}: its {what} '{clipped(value, 80)}' holds control "
                "characters (a line break, tab or NUL)",
                hint=f"write the {what} on one line",
            )


def clipped(text: str, most: int = 256) -> str:
    """``text`` as a message shows it: control characters escaped, at most ``most``
    characters."""
    text = _CONTROL.sub(lambda match: repr(match.group())[1:-1], text)
    return text if len(text) <= most else text[: most - 3] + "..."


def _find_file(
    spec: PluginSpec, filename: str, base_dir: Path | None, *, anywhere: bool, where: str
) -> Path:
    folders = plugin_search_path(base_dir)
    candidate = PurePath(filename)
    allowed = (
        "the world's or model's own folder, GAZEBO_PLUGIN_PATH, WORKBENCH_PLUGIN_PATH "
        "and workbench's examples"
    )
    if ".." in candidate.parts:
        raise PluginRefusedError(
            f"plugin '{spec.name}'{where}: file '{clipped(filename)}' climbs out with '..'; "
            f"plugin files load only from {allowed}",
            hint="copy the file there, or add its folder to GAZEBO_PLUGIN_PATH if you trust it",
        )
    if candidate.is_absolute():
        path = Path(candidate)
        if not anywhere and not any(_inside(path, folder) for folder in folders):
            raise PluginRefusedError(
                f"plugin '{spec.name}'{where}: file '{clipped(filename)}' is outside the "
                f"folders plugin files load from: {allowed}",
                hint="copy the file there, or add its folder to GAZEBO_PLUGIN_PATH if you trust it",
            )
        if _is_file(path):
            return path.resolve()
    else:
        for folder in folders:
            if _is_file(folder / candidate):
                return (folder / candidate).resolve()
    looked = ", ".join(str(p) for p in folders)
    raise SimulationError(
        f"plugin '{spec.name}': file '{clipped(filename)}' not found{where}",
        hint=f"looked in {looked}; add folders to GAZEBO_PLUGIN_PATH",
    )


def _is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except (OSError, ValueError):  # a name too long for the file system, a NUL byte
        return False


def _inside(path: Path, folder: Path) -> bool:
    """Whether ``path`` lies in ``folder`` (both resolved: a link cannot lead out)."""
    try:
        return path.resolve().is_relative_to(folder.resolve())
    except (OSError, ValueError, RuntimeError):
        return False


def _entry_point(filename: str) -> str | None:
    """``module:Class`` of the ``workbench.plugins`` entry point named ``filename`` or whose
    value it is, or None. Reads package metadata only; imports nothing."""
    names, values = _declared(tuple(sys.path))
    wanted = filename.replace(" ", "")
    return names.get(filename) or (wanted if wanted in values else None)


@functools.lru_cache(maxsize=4)
def _declared(search_path: tuple[str, ...]) -> tuple[dict[str, str], frozenset[str]]:
    """The declared plugins (name -> ``module:Class``, and the values) of the packages on
    ``search_path``, read once per search path (a world may name hundreds of plugins)."""
    from importlib.metadata import entry_points

    names: dict[str, str] = {}
    for point in entry_points(group=ENTRY_POINT_GROUP):
        value = f"{point.module}:{point.attr}"
        if _MODULE_CLASS.fullmatch(value):
            names.setdefault(point.name, value)
    return names, frozenset(names.values())
