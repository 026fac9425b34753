"""costmap_2d's StaticLayer: costs from a ``nav_msgs/OccupancyGrid`` map (``plugins/static_layer.cpp``).

A map value (read as an unsigned byte, so -1 is 255) equal to ``unknown_cost_value``
becomes unknown (255) when ``track_unknown_space`` is true, else free; a value of at
least ``lethal_cost_threshold`` (clamped to 0..100) is lethal (254); with
``trinary_costmap`` every other value is free, without it it is scaled to
``value / lethal_cost_threshold * 254``. The first map resizes a static (not rolling)
costmap to the map and locks that size; in a rolling window the map is sampled at
each cell's centre through tf (``map frame <- global frame``, latest).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_layer import Layer, LayeredCostmap
from workbench.navigation.costmap_params import Params
from workbench.navigation.costs import FREE_SPACE, LETHAL_OBSTACLE, NO_INFORMATION


def interpret_values(
    data: np.ndarray,
    *,
    track_unknown_space: bool = True,
    lethal_threshold: int = 100,
    unknown_cost_value: int = -1,
    trinary_costmap: bool = True,
) -> np.ndarray:
    """Map values (int8, -1..100) as costmap costs (``StaticLayer::interpretValue``)."""
    value = np.asarray(data).astype(np.int64) & 0xFF
    lethal = max(min(int(lethal_threshold), 100), 0)
    unknown = int(unknown_cost_value) & 0xFF
    if trinary_costmap:
        other = np.zeros(value.shape, np.uint8)
    else:
        with np.errstate(divide="ignore", invalid="ignore"):
            other = (value / lethal * LETHAL_OBSTACLE).astype(np.uint8)
    cost = np.where(value >= lethal, np.uint8(LETHAL_OBSTACLE), other)
    unknown_cost = NO_INFORMATION if track_unknown_space else FREE_SPACE
    return np.where(value == unknown, np.uint8(unknown_cost), cost).astype(np.uint8)


class StaticLayer(Layer):
    """The map as costs.

    Args:
        name: The layer's name.
        params: The layer's parameters (``<costmap>/<name>``).
        log: A logger (``info``/``warn``/``error``).
    """

    def __init__(self, name: str, params: Params, log: Any) -> None:
        super().__init__(name)
        self.log = log
        self.map_topic = params.text("map_topic", "map")
        self.first_map_only = params.flag("first_map_only", False)
        self.subscribe_to_updates = params.flag("subscribe_to_updates", False)
        self.track_unknown_space = params.flag("track_unknown_space", True)
        self.use_maximum = params.flag("use_maximum", False)
        self.lethal_threshold = params.integer("lethal_cost_threshold", 100)
        self.unknown_cost_value = params.integer("unknown_cost_value", -1)
        self.trinary_costmap = params.flag("trinary_costmap", True)
        self.enabled = params.flag("enabled", True)
        self.grid: Costmap2D | None = None
        self.map_frame = ""
        self.maps_received = 0
        self.tf_buffer: Any = None

    def on_map(self, msg: Any, layered: LayeredCostmap) -> None:
        """A map arrived (``incomingMap``)."""
        if self.first_map_only and self.maps_received:
            return
        info = msg.info
        size_x, size_y = int(info.width), int(info.height)
        if size_x * size_y != len(msg.data):
            self.log.error(
                "%s: the map on %s has %d cells, not width x height = %d x %d; it is ignored",
                self.name,
                self.map_topic,
                len(msg.data),
                size_x,
                size_y,
            )
            return
        resolution = float(info.resolution)
        ox, oy = float(info.origin.position.x), float(info.origin.position.y)
        master = layered.master
        if not layered.rolling_window and (
            master.size_x != size_x
            or master.size_y != size_y
            or master.resolution != resolution
            or master.origin_x != ox
            or master.origin_y != oy
        ):
            self.log.info("Resizing costmap to %d X %d at %f m/pix", size_x, size_y, resolution)
            layered.resize_map(size_x, size_y, resolution, ox, oy, size_locked=True)
        cells = np.asarray(msg.data).reshape(size_y, size_x)
        costs = interpret_values(
            cells,
            track_unknown_space=self.track_unknown_space,
            lethal_threshold=self.lethal_threshold,
            unknown_cost_value=self.unknown_cost_value,
            trinary_costmap=self.trinary_costmap,
        )
        self.grid = Costmap2D(costs, resolution, ox, oy, str(msg.header.frame_id))
        self.map_frame = str(msg.header.frame_id)
        if not self.maps_received:
            self.log.info("Received a %d X %d map at %f m/pix", size_x, size_y, resolution)
        self.maps_received += 1

    def update_costs(self, master: Costmap2D, layered: LayeredCostmap) -> None:
        """Overwrite (or, with ``use_maximum``, raise) the master's costs with the map's."""
        grid = self.grid
        if grid is None:
            return
        if not layered.rolling_window:
            if grid.costs.shape != master.costs.shape:
                return
            if self.use_maximum:
                np.maximum(master.costs, grid.costs, out=master.costs)
            else:
                master.costs[:] = grid.costs
            return
        self._sample_into(master, grid, layered)

    def _sample_into(self, master: Costmap2D, grid: Costmap2D, layered: LayeredCostmap) -> None:
        from workbench.spatial.messages import matrix_from_msg
        from workbench.tf import TransformException

        if self.tf_buffer is None:
            return
        try:
            transform = self.tf_buffer.lookup_transform(self.map_frame, layered.global_frame, 0)
        except TransformException as error:
            self.log.error("%s", error)
            return
        m = matrix_from_msg(transform.transform)
        jj, ii = np.mgrid[0 : master.size_y, 0 : master.size_x]
        wx = master.origin_x + (ii + 0.5) * master.resolution
        wy = master.origin_y + (jj + 0.5) * master.resolution
        px = m[0, 0] * wx + m[0, 1] * wy + m[0, 3]
        py = m[1, 0] * wx + m[1, 1] * wy + m[1, 3]
        mx, my, inside = grid.world_to_map_array(np.column_stack((px.ravel(), py.ravel())))
        inside = inside.reshape(master.costs.shape)
        values = grid.costs[my.reshape(inside.shape), mx.reshape(inside.shape)]
        if self.use_maximum:
            values = np.maximum(values, master.costs)
        master.costs[inside] = values[inside]

    def reset(self) -> None:
        """Nothing to forget: the map stays until a new one arrives."""


__all__ = ["StaticLayer", "interpret_values"]
