"""What the simulator needs to know about one model before Drake parses it.

A :class:`SimModel` is produced from a URDF (with its ``<gazebo>`` extension
blocks), an SDF ``<model>`` or a ``model://`` include, and consumed by
:class:`workbench.sim.World`, which hands ``text`` to Drake's parser each time
the diagram is (re)built. Everything Drake does not understand (plugins,
``selfCollide``, per-model gravity) is lifted out of the text into fields here.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


@dataclass(frozen=True)
class PluginSpec:
    """One ``<plugin>`` element of a world, a model or a sensor.

    Attributes:
        name: The plugin's ``name`` attribute.
        filename: The ``filename`` attribute: a Python file (``my_plugin.py``), an
            entry point ``module:Class``, or a Gazebo library name (``libgazebo_ros_*.so``).
        element: The whole ``<plugin>`` element as XML text (its children are the
            plugin's parameters).
        kind: ``"world"``, ``"model"`` or ``"sensor"``.
        reference: The link (URDF ``<gazebo reference>``) or sensor the plugin belongs
            to, or None.
        base_dir: Folder of the file the plugin was declared in; a relative Python
            file name is looked up there first.
        source: File (and line) for messages, e.g. ``"worlds/demo.world:12"``.
        sensor: For a sensor plugin, the enclosing ``<sensor>`` element as XML text.
    """

    name: str
    filename: str
    element: str
    kind: str
    reference: str | None = None
    base_dir: Path | None = None
    source: str = ""
    sensor: str = ""


@dataclass(frozen=True)
class CollisionPieces:
    """A concave collision mesh of a static link, as convex prisms (see
    :mod:`workbench.model.mesh_pieces`), registered on the link after Drake parsed the model.

    Attributes:
        link: The link's Drake name.
        name: The ``<collision>``'s name.
        pose: ``(x, y, z, roll, pitch, yaw)`` of the collision in the link frame, m and rad.
        pieces: Each prism's points in the collision frame, (6, 3) arrays, m.
        friction: Coulomb friction of the surface (``<surface><friction><ode><mu>``).
    """

    link: str
    name: str
    pose: tuple[float, float, float, float, float, float]
    pieces: tuple[Any, ...]
    friction: float = 1.0


@dataclass
class SimModel:
    """A model ready for Drake's parser, plus what the simulator applies itself.

    Attributes:
        name: The model's name in the world (``-model`` of spawn_model); the text
            already carries it (URDF ``<robot name>`` / SDF ``<model name>``).
        format: ``"urdf"`` or ``"sdf"`` (the text's format for Drake).
        text: URDF or SDF XML for ``Parser.AddModelsFromString``: name set, mesh URIs
            absolute, Gazebo extensions translated into Drake's tags, ``<plugin>``
            and ``<gazebo>`` elements removed, inertia made valid.
        package_map: ``package://`` name -> folder, for Drake's parser.
        root_link: The link whose pose is the model's pose (URDF root; SDF canonical
            link, i.e. the first link).
        static: Weld the model to the world where it is placed (URDF ``<static>``
            in a ``<gazebo>`` block, SDF ``<static>``).
        static_links: Root links (Drake names) whose own model, nested in this one, is
            static when this one is not, or free when this one is static.
        self_collide: Let the model's links collide with each other (Gazebo's
            ``selfCollide``; off by default, as in Gazebo).
        gravity: False when the model's ``<gravity>`` is off.
        pose: ``(x, y, z, roll, pitch, yaw)`` of the model frame relative to where
            it is placed (an SDF model's own ``<pose>``, removed from ``text``; the
            world composes placement and this pose), m and rad.
        collision_pieces: Concave collision meshes of static links, as convex pieces
            (taken out of ``text``).
        plugins: Model and sensor plugins declared in the model.
        sensors: ``<sensor>`` elements as XML text, with the link each belongs to.
        warnings: One line per thing that was changed so Drake can load it (e.g. an
            inertia that breaks the triangle inequality), naming link and file.
        source: Where the model came from, for messages (a path or
            ``"parameter /robot_description"``).
    """

    name: str
    format: str
    text: str
    package_map: dict[str, str] = field(default_factory=dict)
    root_link: str | None = None
    static: bool = False
    static_links: dict[str, bool] = field(default_factory=dict)
    self_collide: bool = False
    gravity: bool = True
    pose: tuple[float, float, float, float, float, float] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    collision_pieces: list[CollisionPieces] = field(default_factory=list)
    plugins: list[PluginSpec] = field(default_factory=list)
    sensors: list[tuple[str, str]] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    source: str = ""


def element_text(element: Any) -> str:
    """An lxml element as XML text, without the text that follows it."""
    from lxml import etree

    clone = copy.deepcopy(element)
    clone.tail = None
    return etree.tostring(clone, encoding="unicode")


def plugin_spec(
    element: Any,
    kind: str,
    reference: str | None,
    base_dir: Path | None,
    source: str,
    sensor: Any = None,
) -> PluginSpec:
    """The :class:`PluginSpec` of a ``<plugin>`` element read from ``source`` (``sensor``:
    the enclosing ``<sensor>`` element of a sensor plugin)."""
    return PluginSpec(
        name=element.get("name", ""),
        filename=element.get("filename", ""),
        element=element_text(element),
        kind=kind,
        reference=reference,
        base_dir=base_dir,
        source=f"{source}:{element.sourceline}" if element.sourceline else source,
        sensor=element_text(sensor) if sensor is not None else "",
    )
