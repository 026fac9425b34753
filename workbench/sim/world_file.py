"""SDF world files as Gazebo users write them, and the worlds workbench ships.

A world is an SDF file with one ``<world>`` (``.world`` or ``.sdf``), or the
name of a shipped world in ``mapping/worlds`` (``empty``; Gazebo's
``worlds/empty.world`` means the same). Read from it:

* ``<include><uri>model://NAME</uri></include>`` with optional ``<name>``,
  ``<pose>``, ``<static>`` and ``<plugin>``: ``ground_plane`` and ``sun`` are
  built in (the ground and, ignored, the light); other names (``NAME`` or
  ``FOLDER/NAME``) are looked up as :mod:`workbench.model.gazebo_models` says.
  An include's ``<pose>`` replaces the model's own, as in Gazebo.
* ``<model>`` elements written in the world; models inside models are merged
  into them as Gazebo names them (:mod:`workbench.model.sdf_nesting`). A model
  called ``ground_plane`` whose shapes are planes facing up (every world saved
  from Gazebo has one) is the built-in ground.
* The first ``<state>`` (worlds saved from Gazebo): the poses and joint angles
  it holds are applied as Gazebo applies them on load, its ``<insertions>``
  are added and its ``<deletions>`` removed (:mod:`workbench.sim.world_state`).
* ``<plugin>`` elements of the world (world plugins).
* ``<physics><max_step_size>`` and ``<real_time_factor>``, and ``<gravity>``.

``<population>`` is refused in one line (write the models out instead).
Everything else (lights, scene, GUI camera, actors) is not simulated and is skipped.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from workbench.errors import ModelError, SimulationError
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
    """A model of the world file, where it goes (x, y, z, roll, pitch, yaw; m, rad) and the
    positions of its 1-dof joints (rad or m, by Gazebo joint name)."""

    model: SimModel
    pose: Pose = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    joint_positions: dict[str, float] = field(default_factory=dict)


@dataclass
class WorldFile:
    """What a world file holds."""

    name: str
    path: Path | None
    physics: Physics = field(default_factory=Physics)
    ground_plane: bool = False
    ground_z: float = 0.0
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
    from workbench.model.sdf_xml import read_sdf_text

    try:
        root = read_sdf_text(path)
    except ModelError as error:
        reason = error.message.removeprefix("not well-formed XML: ")
        message = f"not an XML world file: {reason}" if reason != error.message else reason
        raise SimulationError(message, path=path, line=error.line) from None
    world = root.find("world") if root.tag == "sdf" else (root if root.tag == "world" else None)
    if world is None:
        raise SimulationError(
            f"not an SDF world: the root is <{root.tag}> without a <world>",
            path=path,
            hint="a world file is <sdf><world>...</world></sdf>",
        )
    result = WorldFile(name=world.get("name", path.stem), path=path)
    _check_size(world, path)
    result.physics = _physics(world, path)
    version = root.get("version")
    for element in world:
        if not isinstance(element.tag, str):
            continue
        if element.tag == "include":
            _include(element, result, path)
        elif element.tag == "model":
            ground = ground_height(element)
            if ground is not None:
                result.ground_plane, result.ground_z = True, ground
                continue
            result.models.append(WorldModel(world_model(element, path, version)))
        elif element.tag == "population":
            raise SimulationError(
                f"<population> '{element.get('name', '')}' is not supported",
                path=path,
                line=element.sourceline,
                hint="write the models it would make into the world as <model> or <include>",
            )
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
    state = world.find("state")
    if state is not None:
        from workbench.sim.world_state import apply_state

        apply_state(state, result, path, version)
    names = [m.model.name for m in result.models]
    duplicates = {n for n in names if names.count(n) > 1}
    if duplicates:
        raise SimulationError(f"two models are named '{sorted(duplicates)[0]}'", path=path)
    _check_totals(result, path)
    return result


def _check_size(world: etree._Element, path: Path) -> None:
    """Refuse a world that asks for more models, links or plugins than the simulator holds,
    counted in the file before anything is loaded (an included model's are counted after)."""
    from workbench.sim.bounds import MAX_WORLD_MODELS, count_problem

    built_in = ("model://ground_plane", "model://sun")
    entries = [
        e
        for e in world
        if e.tag == "model"
        or (e.tag == "include" and (e.findtext("uri") or "").strip() not in built_in)
    ]
    if len(entries) > MAX_WORLD_MODELS:
        raise SimulationError(
            f"the world has {len(entries):,} models and includes; the simulator holds at most "
            f"{MAX_WORLD_MODELS:,}",
            path=path,
            line=entries[MAX_WORLD_MODELS].sourceline,
            hint="see 'Limits on input' in the README",
        )
    moving = static = 0
    for model in (e for e in entries if e.tag == "model"):
        links = sum(1 for _ in model.iter("link"))
        if (model.findtext("static") or "").strip().lower() in ("1", "true"):
            static += links
        else:
            moving += links
    plugins = sum(1 for entry in world if entry.tag != "state" for _ in entry.iter("plugin"))
    problem = count_problem(moving, static, plugins)
    if problem is not None:
        raise SimulationError(
            f"the world has {problem}",
            path=path,
            hint="see 'Limits on input' in the README",
        )


def _check_totals(result: WorldFile, path: Path) -> None:
    """:func:`_check_size` once the included models are loaded (their links and plugins)."""
    from workbench.sim.bounds import count_problem, model_links

    links = [(model_links(item.model.text), item.model.static) for item in result.models]
    plugins = len(result.plugins) + sum(len(item.model.plugins) for item in result.models)
    moving = sum(count for count, static in links if not static)
    problem = count_problem(moving, sum(count for count, static in links if static), plugins)
    if problem is not None:
        raise SimulationError(
            f"the world and the models it includes have {problem}",
            path=path,
            hint="see 'Limits on input' in the README",
        )


def world_model(element: etree._Element, path: Path, version: str | None) -> SimModel:
    """The :class:`SimModel` of a ``<model>`` written in the world file ``path``."""
    from workbench.sim.gazebo_sdf import sim_model_from_element

    return sim_model_from_element(
        element, name=None, source=str(path), base_dir=path.parent, version=version
    )


def ground_height(model: etree._Element) -> float | None:
    """The height of the ground a world's ``ground_plane`` model stands for, or None when the
    model is something else (not static, shapes that are not planes facing up, tilted)."""
    if model.get("name") != "ground_plane" or model.find("model") is not None:
        return None
    if (model.findtext("static") or "").strip().lower() not in ("1", "true"):
        return None
    geometries = model.findall("link/collision/geometry") + model.findall("link/visual/geometry")
    if not geometries or any(g.find("plane") is None for g in geometries):
        return None
    z = 0.0
    poses = [model.find("pose"), *model.findall("link/pose"), *model.findall("link/collision/pose")]
    for pose in (p for p in poses if p is not None):
        try:
            values = [float(v) for v in (pose.text or "").split()] or [0.0] * 6
        except ValueError:
            return None
        if len(values) != 6 or any(abs(v) > 1e-9 for v in values[3:]) or pose.get("relative_to"):
            return None
        z += values[2]
    for plane in model.iter("plane"):
        normal = (plane.findtext("normal") or "0 0 1").split()
        if [n.strip() for n in normal] not in (["0", "0", "1"], ["0.0", "0.0", "1.0"]):
            return None
    return z


def _include(element: etree._Element, result: WorldFile, path: Path) -> None:
    from workbench.model.gazebo_models import BUILT_IN_MODELS, uri_path
    from workbench.model.limits import shown_name, uri_problem
    from workbench.model.sdf_nesting import include_file
    from workbench.sim.model_spec import plugin_spec

    uri = (element.findtext("uri") or "").strip()
    problem = uri_problem(uri)
    if problem is not None:
        raise SimulationError(
            f"<include> <uri> '{shown_name(uri)}' {problem}",
            path=path,
            line=element.sourceline,
            hint="give the model's folder name or file path",
        )
    name = uri_path(uri) if uri.startswith("model://") else None
    if name == "ground_plane":
        result.ground_plane = True
        return
    if name in BUILT_IN_MODELS:
        return
    try:
        file = include_file(uri, path, element.sourceline)
    except ModelError as error:
        raise SimulationError(
            error.message, path=error.path, line=error.line, hint=error.hint
        ) from None
    new_name = (element.findtext("name") or "").strip() or None
    if new_name is not None:
        from workbench.sim.bounds import check_model_name

        try:
            check_model_name(new_name, "<include> <name>")
        except SimulationError as error:
            name_element = element.find("name")
            line = name_element.sourceline if name_element is not None else element.sourceline
            raise SimulationError(error.message, path=path, line=line, hint=error.hint) from None
    model = _read_model(file, new_name)
    for plugin in element.findall("plugin"):
        model.plugins.append(plugin_spec(plugin, "model", None, file.parent, str(path)))
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
            from workbench.sim.bounds import check_step_size

            try:
                check_step_size(value, "<max_step_size>")
            except SimulationError as error:
                raise SimulationError(
                    error.message, path=path, line=step.sourceline, hint=error.hint
                ) from None
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

    from workbench.model.limits import shown_name

    text = (element.text or "").strip()
    try:
        values = tuple(float(v) for v in text.split())
    except ValueError:
        values = ()
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise SimulationError(
            f"<{element.tag}> must be {count} finite number{'s' if count > 1 else ''}, got "
            f"'{shown_name(text, 60)}'",
            path=path,
            line=element.sourceline,
        )
    return values
