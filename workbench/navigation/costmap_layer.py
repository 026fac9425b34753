"""The layered costmap: a master grid that its layers write into (costmap_2d's LayeredCostmap).

Each update resets the master grid to its default (unknown when the costmap tracks
unknown space, else free) and lets every enabled layer write its costs in order
(static, obstacles, inflation). costmap_2d updates only the bounding box its layers
report; here the whole grid is rewritten each time, which gives the same costs (the
layers hold their state in their own grids).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costs import FREE_SPACE, NO_INFORMATION
from workbench.navigation.footprint import Point, inscribed_and_circumscribed


class Layer:
    """A costmap layer (costmap_2d's ``Layer``); subclasses override what they need.

    Attributes:
        name: The layer's name (``static_layer``, ``obstacle_layer`` ...).
        enabled: Whether updates use it.
    """

    def __init__(self, name: str) -> None:
        self.name = name
        self.enabled = True

    def match_size(self, layered: LayeredCostmap) -> None:
        """The master grid was resized."""

    def on_footprint_changed(self, layered: LayeredCostmap) -> None:
        """The footprint changed."""

    def update_bounds(self, x: float, y: float, yaw: float, layered: LayeredCostmap) -> None:
        """Bring the layer's own state up to date for a robot at ``(x, y, yaw)``."""

    def update_costs(self, master: Costmap2D, layered: LayeredCostmap) -> None:
        """Write the layer's costs into ``master``."""

    def is_current(self) -> bool:
        """Whether the layer's data is recent enough."""
        return True

    def reset(self) -> None:
        """Forget what the layer learnt (move_base's reset)."""


class LayeredCostmap:
    """The master costmap and its layers.

    Args:
        global_frame: The costmap's frame.
        rolling_window: Whether the grid follows the robot.
        track_unknown_space: Whether unset cells are unknown (255) rather than free (0).
    """

    def __init__(self, global_frame: str, rolling_window: bool, track_unknown_space: bool) -> None:
        self.global_frame = global_frame
        self.rolling_window = rolling_window
        self.track_unknown_space = track_unknown_space
        self.default_value = NO_INFORMATION if track_unknown_space else FREE_SPACE
        self.master = Costmap2D(
            np.full((1, 1), self.default_value, np.uint8), 0.05, 0.0, 0.0, global_frame
        )
        self.layers: list[Layer] = []
        self.size_locked = False
        self.initialized = False
        self.footprint: list[Point] = []
        self.inscribed_radius = 0.0
        self.circumscribed_radius = 0.0

    def add(self, layer: Layer) -> None:
        """Append a layer (it is sized to the master grid)."""
        self.layers.append(layer)
        layer.match_size(self)

    def layer(self, name: str) -> Layer | None:
        """The layer called ``name``, if any."""
        return next((layer for layer in self.layers if layer.name == name), None)

    def resize_map(
        self,
        size_x: int,
        size_y: int,
        resolution: float,
        origin_x: float,
        origin_y: float,
        size_locked: bool = False,
    ) -> None:
        """Resize the master grid and every layer (``resizeMap``)."""
        self.size_locked = size_locked
        self.master.resize(
            max(size_x, 1), max(size_y, 1), resolution, origin_x, origin_y, self.default_value
        )
        for layer in self.layers:
            layer.match_size(self)

    def set_footprint(self, points: Sequence[Point]) -> None:
        """Set the (padded) footprint and its radii (``setFootprint``)."""
        self.footprint = list(points)
        self.inscribed_radius, self.circumscribed_radius = inscribed_and_circumscribed(points)
        for layer in self.layers:
            layer.on_footprint_changed(self)

    def update_map(self, x: float, y: float, yaw: float) -> None:
        """One update for a robot at ``(x, y, yaw)`` in the global frame (``updateMap``)."""
        master = self.master
        if self.rolling_window:
            size_x_m, size_y_m = master.size_in_meters()
            master.update_origin(x - size_x_m / 2, y - size_y_m / 2, self.default_value)
        for layer in self.layers:
            if layer.enabled:
                layer.update_bounds(x, y, yaw, self)
        master.costs[:] = self.default_value
        for layer in self.layers:
            if layer.enabled:
                layer.update_costs(master, self)
        self.initialized = True

    def is_current(self) -> bool:
        """Whether every enabled layer is current."""
        return all(layer.is_current() for layer in self.layers if layer.enabled)


__all__ = ["Layer", "LayeredCostmap"]
