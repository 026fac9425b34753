"""``gmapping/slam_gmapping``: live laser SLAM on the bus, as ROS Noetic's slam_gmapping runs.

``workbench run gmapping slam_gmapping [scan:=/scan] [_param:=value ...]``
(``gmapping/src/slam_gmapping.cpp``, slam_gmapping 1.4). The estimator is
:class:`~workbench.mapping.Slam` (incremental graph SLAM), not a particle filter;
the node around it behaves as slam_gmapping's:

* subscribes to ``scan`` (``sensor_msgs/LaserScan``); the first 19 scans are
  skipped and then every ``~throttle_scans``-th is used;
* on the first scan it looks up the laser's mounting ``~base_frame -> laser``
  in tf (``Failed to compute laser pose, aborting initialization (...)`` and
  ``Couldn't initialize mapper on the first scan. Returning`` while it cannot;
  the next scan tries again), checks the laser is level (``Laser has to be mounted
  planar! ...``), logs ``Laser is mounted upwards.`` or ``... upside down.`` and
  ``Initialization complete``;
* each scan's odometry is ``~odom_frame -> ~base_frame`` at the scan's stamp,
  waited for briefly (``Failed to compute odom pose, skipping scan (...)``);
* a scan is matched only after ``~linearUpdate`` m of travel, ``~angularUpdate``
  rad of turn or ``~temporalUpdate`` s; the others are placed by odometry;
* publishes the latched ``map`` (``nav_msgs/OccupancyGrid`` in ``~map_frame``:
  100 occupied, 0 free, -1 unknown; at least ``~xmin..~xmax`` x ``~ymin..~ymax``
  at ``~delta`` m, growing as the robot explores) and ``map_metadata`` on the
  first scan and then every ``~map_update_interval`` s of scan time; serves them
  on ``dynamic_map`` (``nav_msgs/GetMap``);
* publishes ``~entropy`` (``std_msgs/Float64``) with each map: the differential
  entropy (nats) of the pose graph's marginal Gaussian of the latest pose (GMapping
  publishes its particles' weight entropy instead);
* broadcasts ``~map_frame -> ~odom_frame`` on ``/tf`` every
  ``~transform_publish_period`` s (identity until the first scan), stamped
  ``~tf_delay`` s in the future.

Scans are processed on a worker thread, one at a time: a scan arriving while
one is being processed waits in a one-scan slot, and a newer one replaces it
(the replaced scan is dropped, as slam_gmapping drops scans it cannot keep up
with). At shutdown the counts are logged at debug level. Bad scans do not stop
the node: NaN readings are ignored, ranges below ``range_min`` mark nothing, and
a scan whose beam count differs from the first scan's is refused (one warning
per new count). SIGINT and SIGTERM stop it cleanly.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.mapping.gmapping_params import GmappingParams, read_params
from workbench.mapping.grid_message import occupancy_grid_message
from workbench.mapping.incremental import Slam
from workbench.mapping.live_map import (
    gmapping_cells,
    matrix,
    planar_pose,
    pose_entropy,
    up_in_sensor,
)
from workbench.mapping.scan import Scan

#: Scans slam_gmapping skips at start (``laser_count_ < 20``).
SKIPPED_AT_START = 19
#: Wall seconds a scan waits for its transforms (tf's message filter waits likewise).
TF_WAIT = 0.5


class _Laser:
    """The laser model set from the first scan (``initMapper``)."""

    def __init__(self, frame: str, mounting: np.ndarray, msg: Any, params: GmappingParams) -> None:
        self.frame = frame
        self.mounting = mounting
        self.beams = len(msg.ranges)
        self.upright = up_in_sensor(mounting) > 0
        sign = 1.0 if self.upright else -1.0
        index = np.arange(self.beams, dtype=float)
        self.angles = sign * (float(msg.angle_min) + index * float(msg.angle_increment))
        self.max_range, self.max_urange = params.ranges(float(msg.range_max))


class SlamGMapping:
    """slam_gmapping on a bus node.

    Args:
        node: The ``workbench.bus.Node`` (remap ``scan`` to read another topic).
        params: The parameters; default: read from the node's ``~`` parameters.

    Attributes:
        slam: The estimator, once the first scan initialised it.
        received: Scans that arrived.
        processed: Scans given to the estimator.
        dropped: Scans replaced while the worker was busy.
    """

    def __init__(self, node: Any, params: GmappingParams | None = None) -> None:
        from workbench.msgs.nav_msgs import GetMap, MapMetaData, OccupancyGrid
        from workbench.msgs.sensor_msgs import LaserScan
        from workbench.msgs.std_msgs import Float64
        from workbench.tf import Buffer, TransformBroadcaster, TransformListener

        self.node = node
        self.log = node.get_logger()
        self.params = params if params is not None else read_params(node)
        for line in self.params.notices():
            self.log.info(line)
        self.slam: Slam | None = None
        self.laser: _Laser | None = None
        self.received = self.processed = self.dropped = 0
        self._refused: set[int] = set()
        self._cond = threading.Condition()
        self._pending: Any = None
        self._stopping = False
        self._map_to_odom = np.zeros(3)
        self._map_msg: Any = None
        self._last_tf_ns = -1
        self._last_map_stamp: float | None = None
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, node)
        self.broadcaster = TransformBroadcaster(node)
        self.entropy_pub = node.create_publisher("~entropy", Float64, 1, latch=True)
        self.map_pub = node.create_publisher("map", OccupancyGrid, 1, latch=True)
        self.metadata_pub = node.create_publisher("map_metadata", MapMetaData, 1, latch=True)
        self.service = node.create_service("dynamic_map", GetMap, self._on_get_map)
        self._worker = threading.Thread(target=self._work, name="slam_gmapping", daemon=True)
        self._worker.start()
        self.timer = None
        if self.params.transform_publish_period > 0:
            self.timer = node.create_timer(
                self.params.transform_publish_period, lambda event: self.publish_transform()
            )
        self.subscription = node.create_subscription(
            "scan", LaserScan, self._on_scan, 5, inline=True
        )

    # ------------------------------------------------------------ bus side
    def _on_scan(self, msg: Any) -> None:
        with self._cond:
            self.received += 1
            count = self.received
            if count <= SKIPPED_AT_START or count % self.params.throttle_scans:
                return
            if self._pending is not None:
                self.dropped += 1
            self._pending = msg
            self._cond.notify()

    def publish_transform(self) -> None:
        """Broadcast ``map -> odom`` now, stamped ``tf_delay`` s in the future."""
        from workbench.msgs import Duration
        from workbench.msgs.geometry_msgs import TransformStamped

        stamp = self.node.now() + Duration.from_sec(self.params.tf_delay)
        with self._cond:
            x, y, theta = (float(v) for v in self._map_to_odom)
            if stamp.to_nsec() == self._last_tf_ns:
                return  # the clock stands still (a paused simulation): nothing new to say
            self._last_tf_ns = stamp.to_nsec()
        msg = TransformStamped()
        msg.header.stamp = stamp
        msg.header.frame_id = self.params.map_frame
        msg.child_frame_id = self.params.odom_frame
        msg.transform.translation.x, msg.transform.translation.y = x, y
        msg.transform.rotation.z = float(np.sin(theta / 2.0))
        msg.transform.rotation.w = float(np.cos(theta / 2.0))
        self.broadcaster.send_transform(msg)

    @property
    def waiting(self) -> bool:
        """Whether a scan waits in the slot for the worker (a newer one would replace it)."""
        with self._cond:
            return self._pending is not None

    def map_to_odom(self) -> np.ndarray:
        """The current ``map -> odom`` transform ``(x, y, theta)``."""
        with self._cond:
            return self._map_to_odom.copy()

    def _on_get_map(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import GetMap

        with self._cond:
            grid = self._map_msg
        if grid is None:
            raise RuntimeError("slam_gmapping has no map yet")
        return GetMap.Response(map=grid)

    def close(self) -> None:
        """Stop the worker (after the scan in hand) and log the counts at debug level."""
        with self._cond:
            self._stopping = True
            self._cond.notify_all()
        self._worker.join(timeout=30.0)
        self.log.debug(
            "slam_gmapping: %d scans received, %d processed, %d dropped while busy",
            self.received,
            self.processed,
            self.dropped,
        )

    # --------------------------------------------------------- worker side
    def _work(self) -> None:
        while True:
            with self._cond:
                while self._pending is None and not self._stopping:
                    self._cond.wait()
                if self._stopping:
                    return
                msg, self._pending = self._pending, None
            try:
                self._laser_callback(msg)
            except Exception as error:  # a bad scan must not end the node
                self.log.error("slam_gmapping: cannot process a scan: %s", error)

    def _wait_for_tf(self, target: str, source: str, stamp: Any) -> Any:
        deadline = time.monotonic() + TF_WAIT
        while not self.buffer.can_transform(target, source, stamp):
            if time.monotonic() > deadline or self._stopping:
                break
            time.sleep(0.005)
        return self.buffer.lookup_transform(target, source, stamp)

    def _init_mapper(self, msg: Any) -> bool:
        from workbench.tf import TransformException

        p = self.params
        frame = str(msg.header.frame_id)
        try:
            mounting = matrix(self._wait_for_tf(p.base_frame, frame, msg.header.stamp).transform)
        except TransformException as error:
            self.log.warn("Failed to compute laser pose, aborting initialization (%s)", error)
            return False
        up = up_in_sensor(mounting)
        self.log.debug("Z-Axis in sensor frame: %.3f", up)
        if abs(abs(up) - 1) > 0.001:
            self.log.warn(
                "Laser has to be mounted planar! Z-coordinate has to be 1 or -1, but gave: %.5f",
                up,
            )
            return False
        laser = _Laser(frame, mounting, msg, p)
        self.log.info(
            "Laser is mounted upwards." if laser.upright else "Laser is mounted upside down."
        )
        self.log.debug(
            "Laser angles in laser-frame: min: %.3f max: %.3f inc: %.3f",
            msg.angle_min,
            msg.angle_max,
            msg.angle_increment,
        )
        self.laser = laser
        self.slam = Slam(p.slam_config(float(msg.range_max)))
        self.log.info("Initialization complete")
        return True

    def _odom_pose(self, msg: Any, laser: _Laser) -> np.ndarray | None:
        from workbench.tf import TransformException

        p = self.params
        try:
            base = self._wait_for_tf(p.odom_frame, p.base_frame, msg.header.stamp)
        except TransformException as error:
            self.log.warn("Failed to compute odom pose, skipping scan (%s)", error)
            return None
        return planar_pose(matrix(base.transform) @ laser.mounting)

    def _laser_callback(self, msg: Any) -> None:
        if self.laser is None and not self._init_mapper(msg):
            print("Couldn't initialize mapper on the first scan. Returning", flush=True)
            return
        laser, slam = self.laser, self.slam
        assert laser is not None and slam is not None
        if len(msg.ranges) != laser.beams:
            if len(msg.ranges) not in self._refused:
                self._refused.add(len(msg.ranges))
                self.log.warn(
                    "a scan with %d beams is refused: the laser model has %d (from the "
                    "first scan); scans of another length are skipped",
                    len(msg.ranges),
                    laser.beams,
                )
            self.log.debug("cannot process scan")
            return
        odom = self._odom_pose(msg, laser)
        if odom is None:
            return
        stamp = float(msg.header.stamp.to_sec())
        scan = Scan(
            stamp=stamp,
            ranges=np.asarray(msg.ranges, dtype=float),
            angles=laser.angles,
            odom=odom,
            max_range=laser.max_range,
            min_range=float(msg.range_min),
            source=f"scan:{laser.frame}",
        )
        pose = slam.add_scan(scan)
        correction = slam.map_to_odom()
        with self._cond:
            self.processed += 1
            self._map_to_odom = correction
        self.log.debug("new best pose: %.3f %.3f %.3f", *pose)
        self.log.debug("odom pose: %.3f %.3f %.3f", *odom)
        last = self._last_map_stamp
        if last is None or stamp - last > self.params.map_update_interval:
            self.update_map()
            self._last_map_stamp = stamp

    def update_map(self) -> None:
        """Publish the current map, its metadata and the pose entropy (``updateMap``)."""
        from workbench.msgs.std_msgs import Float64

        slam, p = self.slam, self.params
        if slam is None:
            return
        cells, origin = gmapping_cells(slam.map(), (p.xmin, p.ymin, p.xmax, p.ymax))
        grid = occupancy_grid_message(
            cells, p.delta, (origin[0], origin[1], 0.0), p.map_frame, self.node.now()
        )
        nodes = len(slam.graph.nodes)
        if nodes > 1:
            entropy = pose_entropy(slam.graph.relative_covariance(0, nodes - 1))
            if np.isfinite(entropy):
                self.entropy_pub.publish(Float64(data=entropy))
        with self._cond:
            self._map_msg = grid
        self.map_pub.publish(grid)
        self.metadata_pub.publish(grid.info)
        self.log.debug("Updated the map")


def main(argv: Sequence[str] = ()) -> int:
    """``gmapping/slam_gmapping``: map from ``scan`` and tf until interrupted."""
    from workbench.bus import Node

    node = Node("slam_gmapping", argv=list(argv))
    mapper: SlamGMapping | None = None
    try:
        mapper = SlamGMapping(node)
        node.bus.spin()
    finally:
        if mapper is not None:
            mapper.close()
        node.shutdown()
    return 0


__all__ = ["SlamGMapping", "main"]
