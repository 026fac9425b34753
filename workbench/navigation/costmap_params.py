"""Typed parameter reading for the costmaps, and costmap_2d's pre-Hydro parameter conversion.

Parameters are read under a full namespace (``/move_base/global_costmap``). A value
of the wrong type is a :class:`~workbench.navigation.costmap_errors.CostmapError`
naming the full parameter; an integer given where a number is expected is fine, and
a number given where an integer is expected is rounded as roscpp rounds it.

:func:`convert_pre_hydro` is ``Costmap2DROS::loadOldParameters`` (costmap_2d,
Noetic): without a ``plugins`` list, ``static_map: true`` adds a ``static_layer``
(moving ``map_topic``, ``unknown_cost_value``, ``lethal_cost_threshold`` and, kept
at the top too, ``track_unknown_space`` into it), an ``obstacle_layer`` always
follows (moving ``max_obstacle_height``, ``raytrace_range``, ``obstacle_range``,
``track_unknown_space``, ``observation_sources`` and each source's namespace), then
an ``inflation_layer`` (moving ``cost_scaling_factor`` and ``inflation_radius``); the
list is written back to ``plugins``. :func:`copy_parent_parameters` is
``copyParentParameters`` for a ``plugins`` list given by the user.
"""

from __future__ import annotations

import math
from typing import Any

from workbench.navigation.costmap_errors import CostmapError

STATIC = "costmap_2d::StaticLayer"
OBSTACLE = "costmap_2d::ObstacleLayer"
VOXEL = "costmap_2d::VoxelLayer"
INFLATION = "costmap_2d::InflationLayer"

#: Parameters copyParentParameters copies into a layer of each type.
PARENT_PARAMETERS = {
    STATIC: ("map_topic", "unknown_cost_value", "lethal_cost_threshold", "track_unknown_space"),
    VOXEL: (
        "origin_z",
        "z_resolution",
        "z_voxels",
        "mark_threshold",
        "unknown_threshold",
        "publish_voxel_map",
    ),
    OBSTACLE: ("max_obstacle_height", "raytrace_range", "obstacle_range", "track_unknown_space"),
    INFLATION: ("cost_scaling_factor", "inflation_radius"),
}


def _join(ns: str, key: str) -> str:
    return ns.rstrip("/") + "/" + key


class Params:
    """The parameters under one full namespace of a node's bus.

    Args:
        node: The ``workbench.bus.Node`` whose bus holds the parameters.
        namespace: The full namespace (``/move_base/global_costmap``).
    """

    def __init__(self, node: Any, namespace: str) -> None:
        self.node = node
        self.server = node.bus.params
        self.namespace = "/" + namespace.strip("/")

    def name(self, key: str) -> str:
        """The full name of ``key`` here."""
        return _join(self.namespace, key)

    def sub(self, key: str) -> Params:
        """The parameters under ``key``."""
        return Params(self.node, self.name(key))

    def has(self, key: str) -> bool:
        """Whether ``key`` is set here."""
        return bool(self.server.has(self.name(key)))

    def get(self, key: str, default: Any = None) -> Any:
        """The raw value of ``key`` (``default`` when unset)."""
        full = self.name(key)
        return self.server.get(full) if self.server.has(full) else default

    def set(self, key: str, value: Any) -> None:
        """Set ``key`` here."""
        self.server.set(self.name(key), value)

    def search(self, key: str) -> str | None:
        """The full name of ``key`` found from here upwards (roscpp's ``searchParam``)."""
        found = self.server.search(self.namespace, key)
        return str(found) if found is not None else None

    def _wrong(self, full: str, value: Any, kind: str) -> CostmapError:
        return CostmapError(f"parameter {full} must be {kind}, got {value!r}")

    def number(self, key: str, default: float, *, full: str | None = None) -> float:
        """A float parameter (an int is accepted)."""
        full = full or self.name(key)
        value = self.server.get(full) if self.server.has(full) else default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self._wrong(full, value, "a number")
        if math.isnan(value):
            raise self._wrong(full, value, "a number")
        return float(value)

    def integer(self, key: str, default: int) -> int:
        """An int parameter (a float is rounded to the nearest int as roscpp does)."""
        full = self.name(key)
        value = self.server.get(full) if self.server.has(full) else default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self._wrong(full, value, "an integer")
        if isinstance(value, float):
            if not math.isfinite(value):
                raise self._wrong(full, value, "an integer")
            value = math.floor(value) if math.fmod(value, 1.0) < 0.5 else math.ceil(value)
        return int(value)

    def flag(self, key: str, default: bool) -> bool:
        """A bool parameter."""
        full = self.name(key)
        value = self.server.get(full) if self.server.has(full) else default
        if not isinstance(value, bool):
            raise self._wrong(full, value, "true or false")
        return value

    def text(self, key: str, default: str) -> str:
        """A string parameter."""
        full = self.name(key)
        value = self.server.get(full) if self.server.has(full) else default
        if not isinstance(value, str):
            raise self._wrong(full, value, "a string")
        return value

    def move(self, key: str, target: Params, delete: bool = True) -> None:
        """``move_parameter``: copy ``key`` into ``target`` and (by default) delete it here."""
        if not self.has(key):
            return
        target.set(key, self.get(key))
        if delete:
            self.server.delete(self.name(key))


def convert_pre_hydro(params: Params, log: Any, name: str) -> None:
    """Write a ``plugins`` list from pre-Hydro parameters (``loadOldParameters``)."""
    log.warn('%s: Parameter "plugins" not provided, loading pre-Hydro parameters', name)
    plugins: list[dict[str, str]] = []
    if params.has("static_map") and params.flag("static_map", False):
        plugins.append({"name": "static_layer", "type": STATIC})
        layer = params.sub("static_layer")
        for key in ("map_topic", "unknown_cost_value", "lethal_cost_threshold"):
            params.move(key, layer)
        params.move("track_unknown_space", layer, delete=False)
    obstacles = params.sub("obstacle_layer")
    if params.has("map_type") and params.get("map_type") == "voxel":
        plugins.append({"name": "obstacle_layer", "type": VOXEL})
        for key in PARENT_PARAMETERS[VOXEL]:
            params.move(key, obstacles)
    else:
        plugins.append({"name": "obstacle_layer", "type": OBSTACLE})
    for key in ("max_obstacle_height", "raytrace_range", "obstacle_range", "track_unknown_space"):
        params.move(key, obstacles)
    for source in params.text("observation_sources", "").split():
        params.move(source, obstacles)
    params.move("observation_sources", obstacles)
    inflation = params.sub("inflation_layer")
    params.move("cost_scaling_factor", inflation)
    params.move("inflation_radius", inflation)
    plugins.append({"name": "inflation_layer", "type": INFLATION})
    params.set("plugins", plugins)


def warn_old_parameters(params: Params, log: Any, name: str) -> None:
    """``warnForOldParameters``: pre-Hydro keys beside a ``plugins`` list are unused."""
    for key in ("static_map", "map_type"):
        if params.has(key):
            log.warn('%s: Pre-Hydro parameter "%s" unused since "plugins" is provided', name, key)


def copy_parent_parameters(params: Params, plugin_name: str, plugin_type: str) -> None:
    """``copyParentParameters``: a layer inherits its type's keys from the costmap."""
    target = params.sub(plugin_name)
    for key in PARENT_PARAMETERS.get(plugin_type, ()):
        params.move(key, target, delete=False)


def plugin_list(params: Params) -> list[tuple[str, str]]:
    """``(name, type)`` of each entry of ``plugins``.

    Raises:
        CostmapError: ``plugins`` is not a list of ``{name: ..., type: ...}`` entries.
    """
    full = params.name("plugins")
    value = params.get("plugins")
    if not isinstance(value, list):
        raise CostmapError(
            f"parameter {full} must be a list of {{name: ..., type: ...}} entries, got {value!r}"
        )
    result = []
    for i, entry in enumerate(value):
        if not (
            isinstance(entry, dict)
            and isinstance(entry.get("name"), str)
            and isinstance(entry.get("type"), str)
        ):
            raise CostmapError(
                f"parameter {full} entry {i} must be {{name: ..., type: ...}}, got {entry!r}"
            )
        result.append((entry["name"], entry["type"]))
    return result


__all__ = [
    "INFLATION",
    "OBSTACLE",
    "STATIC",
    "VOXEL",
    "Params",
    "convert_pre_hydro",
    "copy_parent_parameters",
    "plugin_list",
    "warn_old_parameters",
]
