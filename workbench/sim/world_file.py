"""SDF world files as Gazebo users write them, and the worlds workbench ships.

A world is an SDF file with one ``<world>`` (``.world`` or ``.sdf``), or the
name of a shipped world in ``mapping/worlds`` (``empty``; Gazebo's
``worlds/empty.world`` means the same). Read from it:

* ``<include><uri>model://NAME</uri></include>`` with optional ``<name>``,
  ``<pose>`` and ``<static>``: ``ground_plane`` and ``sun`` are built in (the
  ground and, ignored, the light); other names are looked up as
  :mod:`workbench.sim.model_paths` says. An include's ``<pose>`` replaces the
  model's own, as in Gazebo.
* ``<model>`` elements written in the world.
* ``<plugin>`` elements of the world (world plugins).
* ``<physics><max_step_size>`` and ``<real_time_factor>``, and ``<gravity>``.

Everything else (lights, scene, GUI camera) is not simulated and is skipped.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec, SimModel

Pose = tuple[float, float, float, float, float, float]


@dataclass
class Physics:
    """A world's physics settings (None: the server's defaults)."""

    time_step: float | None = None
    real_time_factor: float | None = None
    gravity: tuple[float, float, float] | None = None


@dataclass
class WorldModel:
    """A model of the world file and where it goes (x, y, z, roll, pitch, yaw; m, rad)."""

    model: SimModel
    pose: Pose = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@dataclass
class WorldFile:
    """What a world file holds."""

    name: str
    path: Path | None
    physics: Physics = field(default_factory=Physics)
    ground_plane: bool = False
    models: list[WorldModel] = field(default_factory=list)
    plugins: list[PluginSpec] = field(default_factory=list)


def shipped_worlds() -> dict[str, Path]:
    """Shipped world names -> files (``mapping/worlds/*.world``)."""
    from workbench.paths import mapping_dir

    folder = mapping_dir() / "worlds"
    return {p.stem: p for p in sorted(folder.glob("*.world"))} if folder.is_dir() else {}


def find_world(name_or_path: str | os.PathLike[str]) -> Path:
    """The file of a world given by path or shipped name.

    Raises:
        SimulationError: Neither a file nor a shipped name (the message lists them).
    """
    text = os.fspath(name_or_path)
    path = Path(text).expanduser()
    if path.is_file():
        return path.resolve()
    shipped = shipped_worlds()
    key = text.removeprefix("worlds/").removesuffix(".world")
    if key in shipped:
        return shipped[key]
    if path.suffix in (".world", ".sdf") or os.sep in text:
        raise SimulationError(f"world file '{text}' not found")
    raise SimulationError(
        f"unknown world '{text}'",
        hint="give a .world/.sdf file or one of: " + ", ".join(shipped),
    )


def load_world(name_or_path: str | os.PathLike[str]) -> WorldFile:
    """Read a world (file or shipped name) and every model it includes.

    Raises:
        SimulationError: Not XML, no ``<world>``, an unresolvable ``model://``, a
            malformed number or pose, or a model that cannot be read; one line
            naming the file and line.
    """
    path = find_world(name_or_path)
    try:
        root = etree.parse(str(path)).getroot()
    except etree.XMLSyntaxError as error:
        raise SimulationError(
            f"not an XML world file: {error.msg}", path=path, line=error.lineno
        ) from None
    except OSError as error:
        raise SimulationError(f"cannot read the world file: {error.strerror}", path=path) from None
    world = root.find("world") if root.tag == "sdf" else (root if root.tag == "world" else None)
    if world is None:
        raise SimulationError(
            f"not an SDF world: the root is <{root.tag}> without a <world>",
            path=path,
            hint="a world file is <sdf><world>...</world></sdf>",
        )
    result = WorldFile(name=world.get("name", path.stem), path=path)
    result.physics = _physics(world, path)
    for element in world:
        if not isinstance(element.tag, str):
            continue
        if element.tag == "include":
            _include(element, result, path)
        elif element.tag == "model":
            from workbench.sim.gazebo_sdf import sim_model_from_element

            model = sim_model_from_element(
                element,
                name=None,
                source=str(path),
                base_dir=path.parent,
                version=root.get("version"),
            )
            result.models.append(WorldModel(model))
        elif element.tag == "plugin":
            result.plugins.append(
                PluginSpec(
                    name=element.get("name", ""),
                    filename=element.get("filename", ""),
                    element=etree.tostring(element, encoding="unicode"),
                    kind="world",
                    base_dir=path.parent,
                    source=f"{path}:{element.sourceline}",
                )
            )
    names = [m.model.name for m in result.models]
    duplicates = {n for n in names if names.count(n) > 1}
    if duplicates:
        raise SimulationError(f"two models are named '{sorted(duplicates)[0]}'", path=path)
    return result


def _include(element: etree._Element, result: WorldFile, path: Path) -> None:
    from workbench.sim.model_paths import BUILT_IN_MODELS, find_model_file

    uri = (element.findtext("uri") or "").strip()
    if not uri.startswith("model://"):
        raise SimulationError(
            f"<include> needs <uri>model://NAME</uri>, got '{uri}'",
            path=path,
            line=element.sourceline,
        )
    name = uri[len("model://") :].strip("/")
    if name == "ground_plane":
        result.ground_plane = True
        return
    if name in BUILT_IN_MODELS:
        return
    file = find_model_file(name)
    if file is None:
        from workbench.sim.model_paths import model_search_path

        folders = ", ".join(str(p) for p in model_search_path())
        raise SimulationError(
            f"cannot resolve {uri}: no model '{name}'",
            path=path,
            line=element.sourceline,
            hint=f"looked in {folders} and urdf/; add folders to GAZEBO_MODEL_PATH",
        )
    new_name = (element.findtext("name") or "").strip() or None
    model = _read_model(file, new_name)
    static = element.find("static")
    if static is not None:
        model.static = (static.text or "").strip().lower() in ("1", "true")
    pose_element = element.find("pose")
    pose: tuple[float, ...] = (0.0,) * 6
    if pose_element is not None:
        pose = _numbers(pose_element, 6, path)
        model.pose = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    result.models.append(WorldModel(model, pose))  # type: ignore[arg-type]


def _read_model(file: Path, name: str | None) -> SimModel:
    from workbench.sim.loading import load_sim_model

    return load_sim_model(file, name=name)


def _physics(world: etree._Element, path: Path) -> Physics:
    physics = Physics()
    element = world.find("physics")
    if element is not None:
        step = element.find("max_step_size")
        if step is not None:
            value = _numbers(step, 1, path)[0]
            if not 0 < value <= 0.1:
                raise SimulationError(
                    f"<max_step_size> must be in (0, 0.1] s, got {value:g}",
                    path=path,
                    line=step.sourceline,
                )
            physics.time_step = value
        rtf = element.find("real_time_factor")
        if rtf is not None:
            value = _numbers(rtf, 1, path)[0]
            physics.real_time_factor = value if value > 0 else None
    gravity = world.find("gravity")
    if gravity is None and element is not None:
        gravity = element.find("gravity")
    if gravity is not None:
        g = _numbers(gravity, 3, path)
        physics.gravity = (g[0], g[1], g[2])
    return physics


def _numbers(element: etree._Element, count: int, path: Path) -> tuple[float, ...]:
    import math

    text = (element.text or "").strip()
    try:
        values = tuple(float(v) for v in text.split())
    except ValueError:
        values = ()
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise SimulationError(
            f"<{element.tag}> must be {count} finite number{'s' if count > 1 else ''}, got '{text}'",
            path=path,
            line=element.sourceline,
        )
    return values
