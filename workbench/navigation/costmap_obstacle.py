"""costmap_2d's ObstacleLayer for laser scans (``plugins/obstacle_layer.cpp``, Noetic).

Each update first clears, for every clearing observation, the cells on the rays from
the sensor to each point (Bresenham, at most ``raytrace_range``; rays are cut at the
grid's edge first), then marks lethal the cell of every point of every marking
observation nearer than ``obstacle_range`` (3-D distance from the sensor) and no
higher than the layer's ``max_obstacle_height``. The layer keeps its own grid
(unknown or free by ``track_unknown_space``), clears the robot's footprint
(``footprint_clearing_enabled``) and combines into the master grid by maximum
(``combination_method`` 1, unknown cells left alone) or overwrite (0).
"""

from __future__ import annotations

import threading
import time
from typing import Any

import numpy as np

from workbench.navigation.costmap_errors import CostmapError
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_layer import Layer, LayeredCostmap
from workbench.navigation.costmap_observation import Observation, ObservationBuffer
from workbench.navigation.costmap_params import Params
from workbench.navigation.costmap_raytrace import convex_fill_cells, raytrace_cells
from workbench.navigation.costs import FREE_SPACE, LETHAL_OBSTACLE, NO_INFORMATION
from workbench.navigation.footprint import transform_footprint

#: Scans waiting for their transform, per source (tf2's MessageFilter queue).
PENDING_LIMIT = 50


def clear_rays(grid: Costmap2D, obs: Observation) -> bool:
    """Clear the cells between the sensor and each point (``raytraceFreespace``).

    Returns:
        False when the sensor is outside the grid (nothing is cleared).
    """
    ox, oy = float(obs.origin[0]), float(obs.origin[1])
    start = grid.world_to_map(ox, oy)
    if start is None:
        return False
    if obs.points.shape[0] == 0:
        return True
    x0, y0 = grid.origin_x, grid.origin_y
    x_end = x0 + grid.size_x * grid.resolution
    y_end = y0 + grid.size_y * grid.resolution
    wx, wy = obs.points[:, 0].copy(), obs.points[:, 1].copy()
    a, b = wx - ox, wy - oy
    with np.errstate(divide="ignore", invalid="ignore"):
        cut = wx < x0
        t = (x0 - ox) / a
        wx, wy = np.where(cut, x0, wx), np.where(cut, oy + b * t, wy)
        cut = wy < y0
        t = (y0 - oy) / b
        wx, wy = np.where(cut, ox + a * t, wx), np.where(cut, y0, wy)
        cut = wx > x_end
        t = (x_end - ox) / a
        wx, wy = np.where(cut, x_end - 0.001, wx), np.where(cut, oy + b * t, wy)
        cut = wy > y_end
        t = (y_end - oy) / b
        wx, wy = np.where(cut, ox + a * t, wx), np.where(cut, y_end - 0.001, wy)
    mx, my, inside = grid.world_to_map_array(np.column_stack((wx, wy)))
    xs, ys = raytrace_cells(
        start[0], start[1], mx[inside], my[inside], grid.cell_distance(obs.raytrace_range)
    )
    grid.costs[ys, xs] = FREE_SPACE
    return True


def mark_points(grid: Costmap2D, obs: Observation, max_obstacle_height: float) -> None:
    """Mark lethal the cells of the points in range (``updateBounds``' marking loop)."""
    p = obs.points
    if p.shape[0] == 0:
        return
    d2 = ((p - obs.origin[None, :]) ** 2).sum(axis=1)
    keep = (p[:, 2] <= max_obstacle_height) & (d2 < obs.obstacle_range**2)
    mx, my, inside = grid.world_to_map_array(p[keep, :2])
    grid.costs[my[inside], mx[inside]] = LETHAL_OBSTACLE


def fill_polygon(grid: Costmap2D, polygon: np.ndarray, value: int) -> bool:
    """Set the cells of a convex polygon (``setConvexPolygonCost``); False if it leaves the grid."""
    mx, my, inside = grid.world_to_map_array(polygon)
    if not inside.all():
        return False
    xs, ys = convex_fill_cells(mx, my)
    grid.costs[ys, xs] = value
    return True


class ObstacleLayer(Layer):
    """Obstacles seen by the laser observation sources.

    Args:
        name: The layer's name.
        params: The layer's parameters (``<costmap>/<name>``).
        layered: The costmap it belongs to (frame, rolling, unknown tracking).
        log: A logger.
        clock: Returns the bus time (s).

    Raises:
        CostmapError: A parameter has the wrong type, or a source's ``data_type`` is
            not a laser scan or point cloud.
    """

    def __init__(
        self, name: str, params: Params, layered: LayeredCostmap, log: Any, clock: Any
    ) -> None:
        super().__init__(name)
        self.log = log
        self.clock = clock
        self.rolling_window = layered.rolling_window
        track = params.flag("track_unknown_space", layered.track_unknown_space)
        self.default_value = NO_INFORMATION if track else FREE_SPACE
        self.enabled = params.flag("enabled", True)
        self.footprint_clearing_enabled = params.flag("footprint_clearing_enabled", True)
        self.max_obstacle_height = params.number("max_obstacle_height", 2.0)
        self.combination_method = params.integer("combination_method", 1)
        self.transform_tolerance = params.number("transform_tolerance", 0.2)
        sources = params.text("observation_sources", "")
        log.info("    Subscribed to Topics: %s", sources)
        self.buffers: list[ObservationBuffer] = []
        for source in sources.split():
            buffer = ObservationBuffer(source, params.sub(source), layered.global_frame)
            if buffer.data_type not in ("PointCloud2", "PointCloud", "LaserScan"):
                raise CostmapError(
                    f"parameter {params.sub(source).name('data_type')} is "
                    f"{buffer.data_type!r}: only topics that use point clouds or laser scans "
                    "are currently supported (LaserScan, PointCloud, PointCloud2)"
                )
            self.buffers.append(buffer)
        self.grid = Costmap2D(np.zeros((1, 1), np.uint8), 0.05, 0.0, 0.0, layered.global_frame)
        self.pending: dict[int, list[Any]] = {id(b): [] for b in self.buffers}
        self._pending_lock = threading.Lock()  # the transport's thread adds, updates take
        self.footprint_cells: np.ndarray | None = None
        self.current = True
        self.tf_buffer: Any = None
        self._warned: dict[str, float] = {}

    # ------------------------------------------------------------------ data in
    def on_scan(self, buffer: ObservationBuffer, msg: Any) -> None:
        """A scan for ``buffer`` arrived: place it now, or when its transform is there."""
        self.hold(buffer, msg)
        self.flush_pending()

    def hold(self, buffer: ObservationBuffer, msg: Any) -> None:
        """Queue a scan for ``buffer`` (at most ``PENDING_LIMIT``: the oldest goes first)."""
        with self._pending_lock:
            queue = self.pending[id(buffer)]
            queue.append(msg)
            if len(queue) > PENDING_LIMIT:
                del queue[0]

    def flush_pending(self) -> None:
        """Place the waiting scans whose transforms became available (oldest first)."""
        from workbench.tf import ExtrapolationException, TransformException

        if self.tf_buffer is None:
            return
        for buffer in self.buffers:
            queue = self.pending[id(buffer)]
            while True:
                with self._pending_lock:
                    if not queue:
                        break
                    msg = queue[0]
                try:
                    buffer.buffer_scan(msg, self.tf_buffer, self.clock())
                except ExtrapolationException as error:
                    if self._ahead_of_tf(buffer, msg):
                        break  # wait for newer transforms
                    self._warn(buffer.topic, "Message dropped for %s: %s", buffer.topic, error)
                except TransformException:
                    break
                with self._pending_lock:
                    if queue and queue[0] is msg:  # (unless a full queue pushed it out)
                        del queue[0]

    def _ahead_of_tf(self, buffer: ObservationBuffer, msg: Any) -> bool:
        """Whether ``msg`` is newer than tf's latest transform into the global frame.

        tf2's message filter holds such a scan until its transform arrives. The error text
        does not tell: when the walk from the scan frame stops at a missing odometry
        transform, tf2 explains the lookup by the link above the global frame (amcl's
        ``map -> odom``), which may read "into the past".
        """
        from workbench.tf import TransformException
        from workbench.tf.timeconv import to_ns

        scan_frame = str(msg.header.frame_id)
        frames = {scan_frame, buffer.sensor_frame or scan_frame}
        try:
            latest = min(
                self.tf_buffer.get_latest_common_time(buffer.global_frame, f) for f in frames
            )
            stamp = to_ns(msg.header.stamp)
        except TransformException:
            return False
        return latest != 0 and stamp > latest

    def _warn(self, key: str, text: str, *args: Any) -> None:
        now = time.monotonic()
        if now - self._warned.get(key, -10.0) >= 1.0:
            self._warned[key] = now
            self.log.warn(text, *args)

    # ------------------------------------------------------------------ layer
    def match_size(self, layered: LayeredCostmap) -> None:
        """Take the master grid's size and clear (``matchSize``)."""
        m = layered.master
        self.grid = Costmap2D(
            np.full(m.costs.shape, self.default_value, np.uint8),
            m.resolution,
            m.origin_x,
            m.origin_y,
            m.frame,
        )

    def update_bounds(self, x: float, y: float, yaw: float, layered: LayeredCostmap) -> None:
        """Move (rolling window), clear along rays and mark obstacles."""
        grid = self.grid
        if self.rolling_window:
            size_x_m, size_y_m = grid.size_in_meters()
            grid.update_origin(x - size_x_m / 2, y - size_y_m / 2, self.default_value)
        self.flush_pending()
        now = self.clock()
        current = True
        marking: list[Observation] = []
        clearing: list[Observation] = []
        for buffer in self.buffers:
            if buffer.marking:
                marking += buffer.get()
                current = buffer.is_current(now, self.log) and current
        for buffer in self.buffers:
            if buffer.clearing:
                clearing += buffer.get()
                current = buffer.is_current(now, self.log) and current
        self.current = current
        for obs in clearing:
            if not clear_rays(grid, obs):
                self._warn(
                    "origin",
                    "The origin for the sensor at (%.2f, %.2f) is out of map bounds. So, the "
                    "costmap cannot raytrace for it.",
                    obs.origin[0],
                    obs.origin[1],
                )
        for obs in marking:
            mark_points(grid, obs, self.max_obstacle_height)
        self.footprint_cells = transform_footprint(x, y, yaw, layered.footprint)

    def update_costs(self, master: Costmap2D, layered: LayeredCostmap) -> None:
        """Clear the footprint, then combine into ``master``."""
        if self.footprint_clearing_enabled and self.footprint_cells is not None:
            fill_polygon(self.grid, self.footprint_cells, FREE_SPACE)
        own = self.grid.costs
        if own.shape != master.costs.shape:
            return
        known = own != NO_INFORMATION
        if self.combination_method == 0:
            master.costs[known] = own[known]
        elif self.combination_method == 1:
            old = master.costs
            raise_ = known & ((old == NO_INFORMATION) | (old < own))
            old[raise_] = own[raise_]

    def is_current(self) -> bool:
        """Whether every source with an ``expected_update_rate`` reported in time."""
        return self.current

    def reset(self) -> None:
        """Forget all obstacles and observations (``reset``)."""
        self.grid.costs[:] = self.default_value
        now = self.clock()
        for buffer in self.buffers:
            buffer.observations.clear()
            buffer.reset_last_updated(now)
        self.current = True

    def clear_outside(self, x: float, y: float, radius: float) -> None:
        """Unknown everywhere outside the square of side ``2 * radius`` around ``(x, y)``.

        clear_costmap_recovery's ``clearMap``: cells strictly inside the square keep
        their costs, all others become unknown.
        """
        grid = self.grid
        start = _map_no_bounds(grid, x - radius, y - radius)
        end = _map_no_bounds(grid, x + radius, y + radius)
        xs = np.arange(grid.size_x)[None, :]
        ys = np.arange(grid.size_y)[:, None]
        inside = (xs > start[0]) & (xs < end[0]) & (ys > start[1]) & (ys < end[1])
        grid.costs[~inside] = NO_INFORMATION


def _map_no_bounds(grid: Costmap2D, x: float, y: float) -> tuple[int, int]:
    return int((x - grid.origin_x) / grid.resolution), int((y - grid.origin_y) / grid.resolution)


__all__ = ["ObstacleLayer", "clear_rays", "fill_polygon", "mark_points"]
