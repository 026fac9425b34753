"""costmap_2d's InflationLayer (``plugins/inflation_layer.cpp``, Noetic), by a distance transform.

Every cell within ``ceil(inflation_radius / resolution)`` cells of a lethal cell gets
``computeCost`` of its distance ``d`` (in cells) to the nearest lethal cell: 254 at
``d == 0``, 253 while ``d * resolution <= inscribed_radius``, else
``uint8(252 * exp(-cost_scaling_factor * (d * resolution - inscribed_radius)))``.
A cell keeps the larger of its cost and the inflated one; an unknown cell takes the
inflated cost only when it is at least 253 (any non-zero one with
``inflate_unknown``). costmap_2d finds the nearest obstacle by a wavefront in
distance order; :func:`scipy.ndimage.distance_transform_edt` gives the exact
Euclidean distance to it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.ndimage import distance_transform_edt

from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_layer import Layer, LayeredCostmap
from workbench.navigation.costmap_params import Params
from workbench.navigation.costs import (
    FREE_SPACE,
    INSCRIBED_INFLATED_OBSTACLE,
    LETHAL_OBSTACLE,
    NO_INFORMATION,
)


def compute_cost(
    distance: np.ndarray, resolution: float, inscribed_radius: float, cost_scaling_factor: float
) -> np.ndarray:
    """``InflationLayer::computeCost`` of distances in cells (any shape)."""
    d = np.asarray(distance, dtype=np.float64)
    metres = d * resolution
    factor = np.exp(-1.0 * cost_scaling_factor * (metres - inscribed_radius))
    cost = ((INSCRIBED_INFLATED_OBSTACLE - 1) * factor).astype(np.uint8)
    cost = np.where(metres <= inscribed_radius, np.uint8(INSCRIBED_INFLATED_OBSTACLE), cost)
    return np.where(d == 0, np.uint8(LETHAL_OBSTACLE), cost).astype(np.uint8)


def inflate(
    costs: np.ndarray,
    resolution: float,
    inflation_radius: float,
    inscribed_radius: float,
    cost_scaling_factor: float,
    inflate_unknown: bool = False,
) -> None:
    """Inflate the lethal cells of ``costs`` (uint8, changed in place) as costmap_2d does."""
    cell_radius = int(max(0.0, math.ceil(inflation_radius / resolution)))
    if cell_radius == 0:
        return
    lethal = costs == LETHAL_OBSTACLE
    if not lethal.any():
        return
    distance = distance_transform_edt(~lethal)
    near = distance <= cell_radius
    d = distance[near]
    cost = compute_cost(d, resolution, inscribed_radius, cost_scaling_factor)
    old = costs[near]
    unknown = old == NO_INFORMATION
    takes = (cost > FREE_SPACE) if inflate_unknown else (cost >= INSCRIBED_INFLATED_OBSTACLE)
    costs[near] = np.where(unknown, np.where(takes, cost, old), np.maximum(old, cost))


def inflate_changes(
    old_before: np.ndarray,
    old_after: np.ndarray,
    costs: np.ndarray,
    resolution: float,
    inflation_radius: float,
    inscribed_radius: float,
    cost_scaling_factor: float,
    inflate_unknown: bool = False,
) -> np.ndarray:
    """:func:`inflate` of ``costs`` given that ``old_before`` inflated to ``old_after``.

    A cell's inflated cost depends on its own cost and the lethal cells within the
    inflation radius R, so only cells within R of a changed cell change; they are computed
    from a window reaching R further. Returns the inflated grid (``costs`` is kept).
    """
    changed = old_before != costs
    rows = np.flatnonzero(changed.any(axis=1))
    if rows.size == 0:
        return old_after.copy()
    cols = np.flatnonzero(changed.any(axis=0))
    r = int(max(0.0, math.ceil(inflation_radius / resolution)))
    h, w = costs.shape
    inner = (
        max(int(rows[0]) - r, 0),
        min(int(rows[-1]) + r + 1, h),
        max(int(cols[0]) - r, 0),
        min(int(cols[-1]) + r + 1, w),
    )
    outer = (max(inner[0] - r, 0), min(inner[1] + r, h), max(inner[2] - r, 0), min(inner[3] + r, w))
    window = costs[outer[0] : outer[1], outer[2] : outer[3]].copy()
    inflate(
        window, resolution, inflation_radius, inscribed_radius, cost_scaling_factor, inflate_unknown
    )
    out = old_after.copy()
    out[inner[0] : inner[1], inner[2] : inner[3]] = window[
        inner[0] - outer[0] : inner[1] - outer[0], inner[2] - outer[2] : inner[3] - outer[2]
    ]
    return out


class InflationLayer(Layer):
    """Costs falling off with the distance to obstacles.

    Args:
        name: The layer's name.
        params: The layer's parameters (``<costmap>/<name>``).
        log: A logger.
    """

    def __init__(self, name: str, params: Params, log: Any) -> None:
        super().__init__(name)
        self.enabled = params.flag("enabled", True)
        self.inflation_radius = params.number("inflation_radius", 0.55)
        self.cost_scaling_factor = params.number("cost_scaling_factor", 10.0)
        self.inflate_unknown = params.flag("inflate_unknown", False)
        self.inscribed_radius = 0.0
        self._last: tuple[tuple[float, ...], np.ndarray, np.ndarray] | None = None

    def on_footprint_changed(self, layered: LayeredCostmap) -> None:
        """Take the new inscribed radius."""
        self.inscribed_radius = layered.inscribed_radius

    def update_costs(self, master: Costmap2D, layered: LayeredCostmap) -> None:
        """Inflate the master grid's lethal cells.

        When the parameters and the grid's size are those of the last update, only the
        cells near what changed are inflated again (a global costmap mostly stays the
        same between updates: the obstacle layer marks around the robot).
        """
        settings = (
            master.resolution,
            self.inflation_radius,
            self.inscribed_radius,
            self.cost_scaling_factor,
            float(self.inflate_unknown),
        )
        last = self._last
        if last is not None and last[0] == settings and last[1].shape == master.costs.shape:
            before = master.costs.copy()
            master.costs[:] = inflate_changes(
                last[1], last[2], before, *settings[:4], inflate_unknown=self.inflate_unknown
            )
            self._last = (settings, before, master.costs.copy())
            return
        before = master.costs.copy()
        inflate(master.costs, *settings[:4], inflate_unknown=self.inflate_unknown)
        self._last = (settings, before, master.costs.copy())

    def reset(self) -> None:
        """Forget the last inflation."""
        self._last = None


__all__ = ["InflationLayer", "compute_cost", "inflate", "inflate_changes"]
