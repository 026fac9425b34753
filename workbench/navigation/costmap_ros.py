"""costmap_2d's ``Costmap2DROS`` on a bus node: parameters, layers, topics and timers.

``CostmapROS(node, "global_costmap", tf_buffer)`` reads its parameters under the
node's private namespace and the name (``/move_base/global_costmap/...``) as costmap_2d
does: ``global_frame`` (map), ``robot_base_frame`` (base_link), ``rolling_window``,
``track_unknown_space``, ``always_send_full_costmap``, ``transform_tolerance`` (0.3 s),
``update_frequency`` (5 Hz), ``publish_frequency`` (0 Hz), ``width``/``height`` (10 m),
``resolution`` (0.05 m), ``origin_x``/``origin_y`` (0 m), ``footprint`` or
``robot_radius`` (0.46 m, both searched upwards) and ``footprint_padding`` (0.01 m).
The layers come from ``plugins`` (``costmap_2d::StaticLayer``, ``ObstacleLayer``,
``InflationLayer``) or, when that is missing, from the pre-Hydro keys
(:func:`~workbench.navigation.costmap_params.convert_pre_hydro`).

It publishes ``~<name>/costmap`` (``nav_msgs/OccupancyGrid``, latched, costmap_2d's
0..100 translation, every ``1 / publish_frequency`` s) and ``~<name>/footprint``
(``geometry_msgs/PolygonStamped``, the padded footprint at the robot's pose in the
global frame, each update). The map is not waited for (costmap_2d blocks until it
arrives): until then the costmap has its configured size. Every publication is the full
grid (as with ``always_send_full_costmap``; there are no ``costmap_updates``), and the
footprint is not read from a topic (Noetic subscribes and publishes ``footprint`` with
two types; here it is published only).
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Sequence
from typing import Any

from workbench.navigation.costmap_errors import CostmapError
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_inflation import InflationLayer
from workbench.navigation.costmap_layer import LayeredCostmap
from workbench.navigation.costmap_obstacle import ObstacleLayer
from workbench.navigation.costmap_params import (
    INFLATION,
    OBSTACLE,
    STATIC,
    VOXEL,
    Params,
    convert_pre_hydro,
    copy_parent_parameters,
    plugin_list,
    warn_old_parameters,
)
from workbench.navigation.costmap_publish import costmap_message, footprint_message
from workbench.navigation.costmap_static import StaticLayer
from workbench.navigation.footprint import (
    Point,
    footprint_from_radius,
    footprint_string,
    pad_footprint,
    parse_footprint,
    transform_footprint,
)


def read_footprint(params: Params) -> list[Point]:
    """The unpadded footprint (``makeFootprintFromParams`` and the reconfigure defaults)."""
    found = params.search("footprint")
    if found is not None:
        value = params.server.get(found)
        if not (isinstance(value, str) and value.strip() in ("", "[]")):
            points = parse_footprint(value, found)
            params.set("footprint", footprint_string(points))
            return points
    found = params.search("robot_radius")
    radius = params.number("robot_radius", 0.46, full=found) if found is not None else 0.46
    if radius < 0:
        raise CostmapError(
            f"parameter {found or params.name('robot_radius')} must not be negative, got {radius}"
        )
    return footprint_from_radius(radius)


class CostmapROS:
    """A costmap kept up to date on a node (costmap_2d's ``Costmap2DROS``).

    Args:
        node: The host ``workbench.bus.Node`` (``move_base``).
        name: The costmap's name (``global_costmap``, ``local_costmap``).
        tf_buffer: A ``workbench.tf.Buffer`` filled by a listener.
        start_timers: Run the update timer (``update_frequency``) on the bus clock; with
            False the host calls :meth:`update`.

    Raises:
        CostmapError: A parameter has the wrong type or value (one line naming it).
    """

    def __init__(self, node: Any, name: str, tf_buffer: Any, *, start_timers: bool = True) -> None:
        from workbench.msgs.geometry_msgs import PolygonStamped
        from workbench.msgs.nav_msgs import OccupancyGrid

        self.node = node
        self.name = name
        self.tf_buffer = tf_buffer
        self.log = node.get_logger()
        self._lock = threading.RLock()
        self._throttle: dict[str, float] = {}
        params = Params(node, node.resolve_name("~" + name, "parameter name"))
        self.params = params
        self.global_frame = params.text("global_frame", "map").lstrip("/")
        self.robot_base_frame = params.text("robot_base_frame", "base_link").lstrip("/")
        rolling = params.flag("rolling_window", False)
        track = params.flag("track_unknown_space", False)
        self.always_send_full_costmap = params.flag("always_send_full_costmap", False)
        self.layered = LayeredCostmap(self.global_frame, rolling, track)
        if not params.has("plugins"):
            convert_pre_hydro(params, self.log, name)
        else:
            warn_old_parameters(params, self.log, name)
        self._subscriptions: list[Any] = []
        for plugin_name, plugin_type in plugin_list(params):
            self.log.info('%s: Using plugin "%s"', name, plugin_name)
            copy_parent_parameters(params, plugin_name, plugin_type)
            self._add_layer(plugin_name, plugin_type, params.sub(plugin_name))
        self.transform_tolerance = params.number("transform_tolerance", 0.3)
        self.update_frequency = params.number("update_frequency", 5.0)
        self.publish_frequency = params.number("publish_frequency", 0.0)
        width, height = params.integer("width", 10), params.integer("height", 10)
        resolution = params.number("resolution", 0.05)
        if not resolution > 0:
            raise CostmapError(f"parameter {params.name('resolution')} must be positive")
        origin_x, origin_y = params.number("origin_x", 0.0), params.number("origin_y", 0.0)
        self.footprint_padding = params.number("footprint_padding", 0.01)
        with self._lock:
            if not self.layered.size_locked:
                self.layered.resize_map(
                    int(width / resolution),
                    int(height / resolution),
                    resolution,
                    origin_x,
                    origin_y,
                )
        self.unpadded_footprint = read_footprint(params)
        self.set_footprint(self.unpadded_footprint)
        self.costmap_pub = node.create_publisher(f"~{name}/costmap", OccupancyGrid, 1, latch=True)
        self.footprint_pub = node.create_publisher(f"~{name}/footprint", PolygonStamped, 1)
        self._last_publish = -1e300
        self._timer = None
        if start_timers and self.update_frequency > 0:
            self._timer = node.create_timer(1.0 / self.update_frequency, lambda event: self.cycle())

    # ------------------------------------------------------------------ set-up
    def _add_layer(self, plugin_name: str, plugin_type: str, params: Params) -> None:
        from workbench.msgs.nav_msgs import OccupancyGrid
        from workbench.msgs.sensor_msgs import LaserScan

        layered = self.layered
        if plugin_type == STATIC:
            static = StaticLayer(plugin_name, params, self.log)
            static.tf_buffer = self.tf_buffer
            layered.add(static)
            self.log.info("Requesting the map...")
            self._subscriptions.append(
                self.node.create_subscription(
                    static.map_topic,
                    OccupancyGrid,
                    lambda msg, layer=static: self._locked(layer.on_map, msg, layered),
                    1,
                    inline=True,
                )
            )
        elif plugin_type in (OBSTACLE, VOXEL):
            if plugin_type == VOXEL:
                self.log.warn(
                    "%s: %s is read as a costmap_2d::ObstacleLayer (obstacles in 2-D, its "
                    "voxel parameters are not used)",
                    self.name,
                    plugin_name,
                )
            obstacles = ObstacleLayer(plugin_name, params, layered, self.log, self._now)
            obstacles.tf_buffer = self.tf_buffer
            layered.add(obstacles)
            for buffer in obstacles.buffers:
                if buffer.data_type != "LaserScan":
                    self.log.warn(
                        "%s: observation source %s has data_type %s; only LaserScan sources "
                        "are read",
                        self.name,
                        buffer.source,
                        buffer.data_type,
                    )
                    continue
                self._subscriptions.append(
                    self.node.create_subscription(
                        buffer.topic,
                        LaserScan,
                        lambda msg, layer=obstacles, b=buffer: self._on_scan(layer, b, msg),
                        50,
                        inline=True,
                    )
                )
        elif plugin_type == INFLATION:
            layered.add(InflationLayer(plugin_name, params, self.log))
        else:
            raise CostmapError(
                f"parameter {self.params.name('plugins')} names the layer type {plugin_type!r}: "
                "supported are costmap_2d::StaticLayer, costmap_2d::ObstacleLayer (or "
                "VoxelLayer, read as an obstacle layer) and costmap_2d::InflationLayer"
            )

    def _on_scan(self, layer: ObstacleLayer, buffer: Any, msg: Any) -> None:
        # This runs on the transport's thread: it must not wait for an update in progress
        # (that would hold up every message to this process); the update places the scan.
        layer.hold(buffer, msg)
        if self._lock.acquire(blocking=False):
            try:
                layer.flush_pending()
            finally:
                self._lock.release()

    def _locked(self, function: Any, *args: Any) -> None:
        with self._lock:
            function(*args)

    def _now(self) -> float:
        return float(self.node.now().to_sec())

    def _throttled(self, key: str, level: str, text: str, *args: Any) -> None:
        now = time.monotonic()
        if now - self._throttle.get(key, -10.0) >= 1.0:
            self._throttle[key] = now
            getattr(self.log, level)(text, *args)

    # ------------------------------------------------------------------ public
    @property
    def footprint(self) -> list[Point]:
        """The padded footprint in the robot frame (m)."""
        return list(self.layered.footprint)

    @property
    def inscribed_radius(self) -> float:
        """The padded footprint's inscribed radius (m)."""
        return self.layered.inscribed_radius

    @property
    def circumscribed_radius(self) -> float:
        """The padded footprint's circumscribed radius (m)."""
        return self.layered.circumscribed_radius

    def set_footprint(self, points: Sequence[Point]) -> None:
        """Use an unpadded footprint (padded by ``footprint_padding``)."""
        with self._lock:
            self.unpadded_footprint = list(points)
            self.layered.set_footprint(pad_footprint(points, self.footprint_padding))

    def robot_pose(self) -> tuple[float, float, float] | None:
        """The robot's ``(x, y, yaw)`` in the global frame, or None (``getRobotPose``)."""
        from workbench.spatial.messages import matrix_from_msg
        from workbench.tf import ConnectivityException, ExtrapolationException, LookupException

        now = self.node.now()
        g, b = self.global_frame, self.robot_base_frame
        try:
            if self.tf_buffer.can_transform(g, b, now):
                transform = self.tf_buffer.lookup_transform(g, b, now)
            else:
                transform = self.tf_buffer.lookup_transform(g, b, 0)
        except LookupException as error:
            self._throttled(
                "pose", "error", "No Transform available Error looking up robot pose: %s", error
            )
            return None
        except ConnectivityException as error:
            self._throttled("pose", "error", "Connectivity Error looking up robot pose: %s", error)
            return None
        except ExtrapolationException as error:
            self._throttled("pose", "error", "Extrapolation Error looking up robot pose: %s", error)
            return None
        stamp = float(transform.header.stamp.to_sec())
        current = float(now.to_sec())
        if stamp != 0 and current - stamp > self.transform_tolerance:
            self._throttled(
                "timeout",
                "warn",
                "Costmap2DROS transform timeout. Current time: %.4f, global_pose stamp: %.4f, "
                "tolerance: %.4f",
                current,
                stamp,
                self.transform_tolerance,
            )
            return None
        m = matrix_from_msg(transform.transform)
        return float(m[0, 3]), float(m[1, 3]), math.atan2(m[1, 0], m[0, 0])

    def update(self) -> None:
        """One map update at the robot's current pose (``updateMap``); publishes the footprint."""
        pose = self.robot_pose()
        if pose is None:
            return
        with self._lock:
            self.layered.update_map(*pose)
            polygon = transform_footprint(*pose, self.layered.footprint)
        self.footprint_pub.publish(footprint_message(polygon, self.global_frame, self.node.now()))

    def cycle(self) -> None:
        """One update, then a publication when ``1 / publish_frequency`` s have passed."""
        self.update()
        if self.publish_frequency > 0 and self.layered.initialized:
            now = self._now()
            if self._last_publish + 1.0 / self.publish_frequency < now:
                self.publish()
                self._last_publish = now

    def publish(self) -> None:
        """Publish the costmap now on ``~<name>/costmap``."""
        with self._lock:
            msg = costmap_message(self.layered.master, self.node.now())
        self.costmap_pub.publish(msg)

    def costmap(self) -> Costmap2D:
        """A consistent copy of the current master costmap."""
        with self._lock:
            return self.layered.master.copy()

    def layer(self, name: str) -> Any:
        """The layer called ``name`` (or None)."""
        return self.layered.layer(name)

    def reset_layers(self) -> None:
        """Reset the master grid and every layer (``resetLayers``)."""
        with self._lock:
            self.layered.master.costs[:] = self.layered.default_value
            for layer in self.layered.layers:
                layer.reset()

    def clear_outside(self, radius: float, layers: Sequence[str] = ("obstacle_layer",)) -> None:
        """Forget obstacles outside the square of side ``2 * radius`` around the robot.

        clear_costmap_recovery's ``clearMap`` for the named obstacle layers.
        """
        pose = self.robot_pose()
        if pose is None:
            return
        with self._lock:
            for layer in self.layered.layers:
                if layer.name in layers and isinstance(layer, ObstacleLayer):
                    layer.clear_outside(pose[0], pose[1], radius)

    def is_current(self) -> bool:
        """Whether every layer's data is current (``isCurrent``)."""
        with self._lock:
            return self.layered.is_current()

    def shutdown(self) -> None:
        """Stop the timer and unsubscribe."""
        if self._timer is not None:
            self._timer.shutdown()
            self._timer = None
        for sub in self._subscriptions:
            sub.unregister()
        self._subscriptions.clear()


__all__ = ["CostmapROS", "read_footprint"]
