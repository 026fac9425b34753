"""Bounds on the work a world file or a spawn request may ask of the simulator.

A world or a model sent over the bus is input like a model file: it may not make
the server build or step for ever, nor hand Drake a name it crashes on. The bounds
are far above any world of the lab (the TurtleBot3 house is one model of 34 links,
Clearpath's playpen has 72 models; gazebo_models' largest model has 100 links)
and are listed in the README under "Limits on input". Past them the world or the
request is refused in one line before anything is built. Near them the simulator is
slow but answers: on one core a 500-link chain steps 0.01 s in about 0.3 s, and a world
of 200 boxes takes about 7 s to build (each spawn rebuilds the whole plant).
"""

from __future__ import annotations

import hashlib
import re
from typing import Any

from workbench.errors import SimulationError

#: Most models in one world (world file and spawned, the ground not counted).
MAX_WORLD_MODELS = 200
#: Most links of moving models in one world, all models together (and most links of one
#: spawned model, static or not): each is a body the physics steps.
MAX_WORLD_LINKS = 500
#: Most links of static models in one world (walls a map image was traced into: the
#: Intel lab's map gives 1,606); they are only collision geometry.
MAX_STATIC_LINKS = 2_000
#: Most plugins a world file may load (world, model and sensor plugins together).
MAX_WORLD_PLUGINS = 100
#: Smallest and largest physics step, s. Gazebo's worlds use 1 ms (the finest ones
#: 0.1 ms); each step runs the plugins, so at 0.1 ms a world with a plugin simulates
#: 0.3 s in about 2.5 s, and at 10 us in 22 s.
MIN_STEP_SIZE, MAX_STEP_SIZE = 1e-4, 0.1
#: Longest ``robot_namespace`` of a spawn request, characters.
MAX_NAMESPACE_LENGTH = 256

_README = "see 'Limits on input' in the README"


def check_step_size(value: float, what: str) -> None:
    """Refuse a physics step outside [:data:`MIN_STEP_SIZE`, :data:`MAX_STEP_SIZE`] s.

    Raises:
        SimulationError: ``<what> must be in [1e-05, 0.1] s, got ...`` (no file named:
            the caller adds it).
    """
    if not MIN_STEP_SIZE <= value <= MAX_STEP_SIZE:
        raise SimulationError(
            f"{what} must be in [{MIN_STEP_SIZE:g}, {MAX_STEP_SIZE:g}] s, got {value:g}",
            hint="Gazebo's worlds use 0.001 s",
        )


def model_links(text: str) -> int:
    """How many links a :class:`~workbench.sim.model_spec.SimModel`'s text holds.

    Counted once per text: every spawn counts every model of the world. The cache is
    keyed by digest, so that it keeps no deleted model's text alive.
    """
    digest = hashlib.sha1(text.encode(), usedforsecurity=False).digest()
    count = _LINK_COUNTS.get(digest)
    if count is None:
        if len(_LINK_COUNTS) >= 4096:
            _LINK_COUNTS.clear()
        count = _LINK_COUNTS[digest] = _count_links(text)
    return count


_LINK_COUNTS: dict[bytes, int] = {}


def _count_links(text: str) -> int:
    from lxml import etree

    # the text is what Drake parses, which forgives what libsdformat forgives (a "--" in a
    # comment)
    parser = etree.XMLParser(recover=True, resolve_entities=False, no_network=True, huge_tree=True)
    root = etree.fromstring(text.encode(), parser)
    if root is None:
        return 0
    return sum(1 for element in root.iter("link") if element.getparent().tag in ("robot", "model"))


def check_room(load: tuple[int, int, int], adding: int, static: bool, name: str) -> None:
    """Refuse a model of ``adding`` links in a world holding ``load`` (:func:`world_load`).

    Raises:
        SimulationError: The world would hold more than :data:`MAX_WORLD_MODELS` models,
            :data:`MAX_WORLD_LINKS` moving or :data:`MAX_STATIC_LINKS` static links.
    """
    from workbench.model.limits import shown_name

    models, moving, fixed = load
    if models + 1 > MAX_WORLD_MODELS:
        raise SimulationError(
            f"model '{shown_name(name)}': the world already has {models:,} models; the "
            f"simulator holds at most {MAX_WORLD_MODELS:,}",
            hint="delete a model first; " + _README,
        )
    have, limit = (fixed, MAX_STATIC_LINKS) if static else (moving, MAX_WORLD_LINKS)
    kind = "static" if static else "moving"
    if have + adding > limit:
        already = f"the world has {have:,}, " if have else ""
        raise SimulationError(
            f"model '{shown_name(name)}' has {adding:,} links; {already}the simulator holds at "
            f"most {limit:,} links of {kind} models",
            hint="simulate fewer links; " + _README,
        )


def count_problem(moving: int, static: int, plugins: int) -> str | None:
    """Why a world of these many moving links, static links and plugins is refused, or None."""
    for count, limit, what in (
        (moving, MAX_WORLD_LINKS, "links of moving models"),
        (static, MAX_STATIC_LINKS, "links of static models"),
        (plugins, MAX_WORLD_PLUGINS, "plugins"),
    ):
        if count > limit:
            return f"{count:,} {what}; the simulator holds at most {limit:,}"
    return None


def check_model_name(name: str, what: str) -> None:
    """Refuse a model name Drake cannot take (too long, control characters, empty).

    Raises:
        SimulationError: ``<what> '<name...>' has 100,000 characters; at most 256``.
    """
    from workbench.model.limits import name_problem, shown_name

    problem = name_problem(name)
    if problem is not None:
        raise SimulationError(
            f"{what} '{shown_name(name)}' {problem}",
            hint="give it a short name of printable characters",
        )


def namespace_problem(namespace: str) -> str | None:
    """Why ``namespace`` cannot be a spawn request's ``robot_namespace``, or None."""
    if len(namespace) > MAX_NAMESPACE_LENGTH:
        return f"has {len(namespace):,} characters; at most {MAX_NAMESPACE_LENGTH}"
    bad = next((c for c in namespace if not (c.isalnum() or c in "_/~")), None)
    if bad is not None:
        return f"contains {bad!r}, which a ROS name cannot hold"
    return None


def world_load(world: Any) -> tuple[int, int, int]:
    """``(models, moving links, static links)`` of what a :class:`~workbench.sim.World` holds."""
    moving = static = 0
    for placed in world.models.values():
        links = model_links(placed.model.text)
        static += links if placed.model.static else 0
        moving += 0 if placed.model.static else links
    moving += sum(len(robot.links) for robot in world.robots.values())
    return len(world.models) + len(world.robots), moving, static


def spawn_request_problem(name: str, namespace: str, xml: str) -> str | None:
    """Why a spawn request must be refused before its model is read, or None.

    The name and namespace go to Drake and into bus names; a name of 100,000
    characters crashes Drake, so they are checked before anything else (and the
    messages never quote them whole).
    """
    from workbench.model.limits import MAX_MODEL_BYTES, name_problem, shown_name

    if name:
        problem = name_problem(name)
        if problem is not None:
            return f"model name '{shown_name(name)}' {problem}"
    problem = namespace_problem(namespace)
    if problem is not None:
        return f"robot_namespace '{shown_name(namespace)}' {problem}"
    if len(xml) > MAX_MODEL_BYTES:
        return f"model_xml has {len(xml):,} characters; at most {MAX_MODEL_BYTES:,}"
    # counted in the text before it is parsed (World.add_model counts exactly); a spawned
    # model, static or not, is built while the world runs, so it brings at most as many
    # links as a world's moving models may have
    links = len(_LINK.findall(xml))
    if links > MAX_WORLD_LINKS:
        return f"the model has {links:,} links; a spawned model has at most {MAX_WORLD_LINKS:,}"
    return None


_LINK = re.compile(r"<link[\s>/]")
