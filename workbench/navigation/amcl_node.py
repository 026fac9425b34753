"""``amcl/amcl``: adaptive Monte Carlo localisation on the bus, as ROS Noetic's amcl node.

``workbench run amcl amcl [scan:=/scan] [_param:=value ...]`` (``amcl/src/amcl_node.cpp``,
navigation 1.17). The filter is :class:`~workbench.navigation.amcl_localizer.Localizer`;
the node around it behaves as amcl's:

* the map: with ``~use_map_topic`` it subscribes ``map`` (only the first with
  ``~first_map_only``); otherwise it calls ``static_map`` (``nav_msgs/GetMap``),
  logging ``Requesting the map...`` and ``Request for map failed; trying again...``
  every 0.5 s until it answers. Each map logs ``Received a W X H map @ R m/pix``
  and restarts the filter at ``~initial_pose_*`` / ``~initial_cov_*``;
* ``scan`` (``sensor_msgs/LaserScan``): a scan waits for ``~odom_frame_id -> scan
  frame`` in tf, as amcl's tf message filter holds it (:mod:`amcl_scan_queue`: at most
  100; the newest scan whose transform is known goes first and the older ones are
  dropped, so a node that fell behind is current again with the next scan); a scan
  whose frame tf cannot connect within 0.5 s, or whose stamp fell out of the tf cache,
  is dropped with tf2's ``MessageFilter [target=odom]: Dropped ...`` warning (and a
  line naming a frame that never connects). The laser's mounting is looked up once per
  frame; the odometry is ``~odom_frame_id -> ~base_frame_id`` at the scan's stamp
  (``Failed to compute odom pose, skipping scan (...)``). NaN and inf readings are skipped;
* publishes the latched ``amcl_pose`` (``geometry_msgs/PoseWithCovarianceStamped``,
  stamped with the scan) after each resample, ``particlecloud``
  (``geometry_msgs/PoseArray``) after each filter update, and ``~global_frame_id ->
  ~odom_frame_id`` on ``/tf`` with every scan (a new one after a resample, the last one
  re-sent otherwise), stamped ``~transform_tolerance`` s after the scan;
* ``initialpose`` (``geometry_msgs/PoseWithCovarianceStamped``) restarts the filter
  (``Setting pose (T): X Y A``; a pose in another frame than ``~global_frame_id`` is
  ignored with amcl's warning); services ``global_localization`` and
  ``request_nomotion_update`` (``std_srvs/Empty``) and ``set_map`` (``nav_msgs/SetMap``);
* saves its pose into ``~initial_pose_*`` / ``~initial_cov_*`` every ``1 / ~save_pose_rate`` s.

Scans, initial poses and maps are handled on one worker thread; initial poses (the last
2, as amcl's subscriber queue) and maps go before the scans waiting in the filter, so a
2D Pose Estimate takes effect with the next scan even when amcl is behind. The
``No laser scan received`` warning measures, as amcl's, bus time since the last scan
that passed the filter. SIGINT and SIGTERM stop the node cleanly.
"""

from __future__ import annotations

import collections
import threading
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.mapping.geometry import compose
from workbench.navigation.amcl_laser import LaserScanData, prepare_ranges
from workbench.navigation.amcl_localizer import Estimate, Localizer
from workbench.navigation.amcl_map import AmclMap
from workbench.navigation.amcl_messages import (
    covariance_3,
    covariance_36,
    map_to_odom,
    planar,
    pose_list,
    set_planar,
    transform_pose,
    yaw_in_base,
)
from workbench.navigation.amcl_params import AmclParams, read_params, strip_slash
from workbench.navigation.amcl_scan_queue import (
    MISSING,
    NEVER,
    NO_TRANSFORM,
    QUEUE,
    READY,
    WAIT,
    Dropped,
    HeldScan,
    ScanQueue,
)

#: Wall seconds a scan waits for tf to connect its frame to the odometry frame.
TF_WAIT = 0.5
#: Wall seconds between two looks at tf while scans wait (a fast simulation sends the
#: odometry for a scan's stamp within a millisecond or two).
TF_POLL = 0.002
#: Initial poses and maps held at most (amcl's subscriber queues: ``initialpose`` 2, ``map`` 1).
CONTROL_QUEUES = {"pose": 2, "map": 1}
#: Bus seconds without scans before amcl warns (``laser_check_interval_``).
LASER_CHECK_INTERVAL = 15.0
#: The parameters amcl re-reads with each map (``updatePoseFromServer``).
INITIAL_PARAMS = (
    "initial_pose_x",
    "initial_pose_y",
    "initial_pose_a",
    "initial_cov_xx",
    "initial_cov_yy",
    "initial_cov_aa",
)
#: Wall seconds between tf2's "Dropped ..." warnings.
DROP_WARNING_PERIOD = 60.0


class Amcl:
    """amcl on a bus node.

    Args:
        node: The ``workbench.bus.Node`` (remap ``scan``, ``map``... to read other topics).
        params: The parameters; default: read from the node's ``~`` parameters.

    Attributes:
        localizer: The filter, once a map arrived.
        received: Scans that arrived; ``processed``: scans handled; ``dropped``: scans
            dropped for lack of a transform; ``skipped``: scans dropped unprocessed because
            a newer one was ready (or more than 100 waited) while amcl was busy.
        last_estimate: What the last processed scan produced.
    """

    def __init__(self, node: Any, params: AmclParams | None = None) -> None:
        from workbench.msgs.geometry_msgs import PoseArray, PoseWithCovarianceStamped
        from workbench.msgs.nav_msgs import OccupancyGrid, SetMap
        from workbench.msgs.sensor_msgs import LaserScan
        from workbench.msgs.std_srvs import Empty
        from workbench.tf import Buffer, TransformBroadcaster, TransformListener

        self.node = node
        self.log = node.get_logger()
        self.params = params if params is not None else read_params(node)
        self.localizer: Localizer | None = None
        self.received = self.processed = self.dropped = self.skipped = 0
        self.last_estimate = Estimate()
        self._lock = threading.RLock()
        self._cond = threading.Condition()
        self._control: collections.deque = collections.deque()
        self._scans = ScanQueue(QUEUE, TF_WAIT)
        self._busy = False
        self._stopping = False
        self._lasers: dict[str, tuple[float, float, Any]] = {}
        self._bad_frames: set[str] = set()
        self._next_drop_warning = 0.0
        self._initial: tuple[np.ndarray, np.ndarray] | None = None
        self._maps = 0
        self._latest_tf: np.ndarray | None = None
        self._sent_first_transform = False
        self._last_scan_time = node.now().to_sec()
        self._save_last = 0.0
        self._last_pose: tuple[np.ndarray, np.ndarray] | None = None
        self._latest_odom = np.zeros(3)
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, node)
        self.broadcaster = TransformBroadcaster(node)
        self.pose_pub = node.create_publisher("amcl_pose", PoseWithCovarianceStamped, 2, latch=True)
        self.cloud_pub = node.create_publisher("particlecloud", PoseArray, 2, latch=True)
        self._services = [
            node.create_service("global_localization", Empty, self._on_global_localization),
            node.create_service("request_nomotion_update", Empty, self._on_nomotion_update),
            node.create_service("set_map", SetMap, self._on_set_map),
        ]
        self._worker = threading.Thread(target=self._work, name="amcl", daemon=True)
        self._worker.start()
        self.scan_sub = node.create_subscription(
            "scan", LaserScan, self._on_scan, QUEUE, inline=True
        )
        self.pose_sub = node.create_subscription(
            "initialpose",
            PoseWithCovarianceStamped,
            lambda m: self._push_control("pose", m),
            2,
            inline=True,
        )
        self._map_thread: threading.Thread | None = None
        if self.params.use_map_topic:
            self.map_sub = node.create_subscription(
                "map", OccupancyGrid, self._on_map, 1, inline=True
            )
            self.log.info("Subscribed to map topic.")
        else:
            self._map_thread = threading.Thread(
                target=self._request_map, name="amcl_map", daemon=True
            )
            self._map_thread.start()
        self.timer = node.create_timer(LASER_CHECK_INTERVAL, self._check_laser_received)

    # ------------------------------------------------------------------ inputs
    def _push_control(self, kind: str, msg: Any) -> None:
        with self._cond:
            queued = [item for item in self._control if item[0] == kind]
            if len(queued) >= CONTROL_QUEUES[kind]:  # a full subscriber queue drops the oldest
                self._control.remove(queued[0])
            self._control.append((kind, msg))
            self._cond.notify()

    def _on_scan(self, msg: Any) -> None:
        scan = HeldScan(msg, strip_slash(str(msg.header.frame_id)), time.monotonic())
        with self._cond:
            self.received += 1
            pushed_out = self._scans.add(scan)
            if pushed_out is not None:
                self.skipped += 1
            self._cond.notify()

    def _on_map(self, msg: Any) -> None:
        if self.params.first_map_only and self._maps > 0:
            return
        self._maps += 1
        self._push_control("map", msg)

    def _request_map(self) -> None:
        from workbench.msgs.nav_msgs import GetMap

        client = self.node.create_client("static_map", GetMap)
        self.log.info("Requesting the map...")
        while not self._stopping:
            try:
                response = client.call(GetMap.Request(), timeout=5.0)
            except Exception:  # not offered yet, or it failed: amcl retries forever
                self.log.warn("Request for map failed; trying again...")
                time.sleep(0.5)
                continue
            self._push_control("map", response.map)
            return

    @property
    def busy(self) -> bool:
        """Whether scans, initial poses or maps wait, or one is being handled."""
        with self._cond:
            return bool(self._control or len(self._scans) or self._busy)

    def wait_idle(self, timeout: float = 30.0) -> bool:
        """Wait until everything received so far has been handled (for tests and scripts)."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while self.busy:  # the condition's lock is re-entrant
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    return False
                self._cond.wait(min(remaining, 0.05))
        return True

    def close(self) -> None:
        """Stop the worker after the item in hand."""
        with self._cond:
            self._stopping = True
            self._cond.notify_all()
        self._worker.join(timeout=30.0)

    # -------------------------------------------------------------- the worker
    def _work(self) -> None:
        while True:
            with self._cond:
                while not self._control and not len(self._scans) and not self._stopping:
                    self._cond.wait()
                if self._stopping:
                    return
                scan: HeldScan | None = None
                dropped: list[Dropped] = []
                if self._control:
                    kind, msg = self._control.popleft()
                else:
                    kind, msg = "scan", None
                    scan, dropped = self._scans.take(self._scan_status, time.monotonic())
                    if scan is None and not dropped:
                        self._cond.wait(TF_POLL)  # the scans wait for their transforms
                        continue
                self._busy = True
            try:
                with self._lock:
                    if kind == "scan":
                        self._report_dropped(dropped)
                        if scan is not None:
                            self.laser_received(scan.msg)
                    elif kind == "pose":
                        self.handle_initial_pose(msg)
                    else:
                        self.handle_map(msg)
            except Exception as error:  # bad input must not end the node
                self.log.error("amcl: cannot handle a %s message: %s", kind, error)
            finally:
                with self._cond:
                    self._busy = False
                    self._cond.notify_all()

    def _scan_status(self, scan: HeldScan) -> tuple[str, str]:
        """Where ``odom -> scan frame`` stands at the scan's stamp (tf2's message filter test)."""
        from workbench.tf import TransformException
        from workbench.tf.timeconv import to_ns

        target, stamp = self.params.odom_frame_id, scan.msg.header.stamp
        try:
            answer = self.buffer.can_transform(target, scan.frame, stamp, return_debug_tuple=True)
        except Exception as error:  # a stamp tf cannot read: the scan waits out its time
            return MISSING, str(error)
        ok, why = answer if isinstance(answer, tuple) else (answer, "")
        if ok:
            return READY, ""
        try:
            latest = self.buffer.get_latest_common_time(target, scan.frame)
            t = to_ns(stamp)
        except TransformException:
            return MISSING, str(why)
        # tf2's BufferCore refuses to wait for a stamp further behind the newest transform
        # than the cache keeps: the message filter drops such a message at once
        if latest and t + round(self.buffer.cache_time * 1e9) < latest:
            return NEVER, str(why)
        if t > latest:
            return WAIT, str(why)
        return MISSING, str(why)

    def _report_dropped(self, dropped: list[Dropped]) -> None:
        """Count the scans the filter dropped and warn as tf2's message filter does."""
        behind = [d for d in dropped if d.reason != NO_TRANSFORM]
        if behind:
            self.skipped += len(behind)
            self.log.debug(
                "amcl is behind: %d older scan(s) dropped for the newest one", len(behind)
            )
        for item in dropped:
            if item.reason == NO_TRANSFORM:
                self._drop_for_tf(item)

    def _drop_for_tf(self, item: Dropped) -> None:
        p = self.params
        frame, why = item.scan.frame, item.why
        self.dropped += 1
        now = time.monotonic()
        if now >= self._next_drop_warning:
            self._next_drop_warning = now + DROP_WARNING_PERIOD
            share = 100.0 * self.dropped / max(self.received, 1)
            self.log.warn(
                "MessageFilter [target=%s]: Dropped %.2f%% of messages so far. Please turn "
                "the [ros.amcl.message_notifier] rosconsole logger to DEBUG for more information.",
                p.odom_frame_id,
                share,
            )
            if item.state == NEVER:
                self.log.warn(
                    "  The majority of dropped messages were due to messages growing older than "
                    "the TF cache time.  The last message's timestamp was: %f, and the last "
                    "frame_id was: %s",
                    item.scan.msg.header.stamp.to_sec(),
                    frame,
                )
        if frame not in self._bad_frames and item.state != NEVER:
            self._bad_frames.add(frame)
            reason = why.splitlines()[0] if why else "no transform"
            self.log.warn(
                'scans in frame "%s" are dropped: no transform to "%s" at their stamp (%s)',
                frame,
                p.odom_frame_id,
                reason,
            )

    # ------------------------------------------------------------------ scans
    def _laser_setup(self, frame: str) -> tuple[float, float, Any] | None:
        from workbench.tf import TransformException

        if frame in self._lasers:
            return self._lasers[frame]
        try:
            mount = self.buffer.lookup_transform(self.params.base_frame_id, frame, 0)
        except TransformException:
            self.log.error(
                "Couldn't transform from %s to %s, even though the message notifier is in use",
                frame,
                self.params.base_frame_id,
            )
            return None
        t = mount.transform
        laser = (float(t.translation.x), float(t.translation.y), t.rotation)
        self.log.debug("Received laser's pose wrt robot: %.3f %.3f %.3f", laser[0], laser[1], 0.0)
        self._lasers[frame] = laser
        return laser

    def _odom_pose(self, stamp: Any) -> np.ndarray | None:
        from workbench.tf import TransformException

        p = self.params
        try:
            t = self.buffer.lookup_transform(p.odom_frame_id, p.base_frame_id, stamp)
        except TransformException as error:
            self.log.warn(
                "Failed to compute odom pose, skipping scan (%s)", str(error).splitlines()[0]
            )
            return None
        return transform_pose(t)

    def laser_received(self, msg: Any) -> None:
        """Handle one scan whose frame tf knows (``AmclNode::laserReceived``)."""
        self._last_scan_time = self.node.now().to_sec()
        localizer = self.localizer
        if localizer is None:
            return  # no map yet
        frame = strip_slash(str(msg.header.frame_id))
        laser = self._laser_setup(frame)
        if laser is None:
            return
        odom = self._odom_pose(msg.header.stamp)
        if odom is None:
            self.log.error("Couldn't determine robot's pose associated with laser scan")
            return
        data = self._scan_data(msg, laser)
        if data is None:
            return
        localizer.set_laser_pose(laser[0], laser[1])
        self._latest_odom = odom
        estimate = localizer.process(odom, data)
        self.processed += 1
        self.last_estimate = estimate
        if estimate.weighed:
            self._publish_cloud()
        if estimate.publish and estimate.pose is not None:
            self._publish_pose(msg.header.stamp, estimate.pose, estimate.cov)
            self._latest_tf = map_to_odom(estimate.pose, odom)
            self._send_transform(msg.header.stamp)
            self._sent_first_transform = True
        elif self._latest_tf is not None:
            self._send_transform(msg.header.stamp)
            self._maybe_save_pose()

    def _scan_data(self, msg: Any, laser: tuple[float, float, Any]) -> LaserScanData | None:
        p = self.params
        angle_min = yaw_in_base(laser[2], float(msg.angle_min))
        increment = (
            yaw_in_base(laser[2], float(msg.angle_min) + float(msg.angle_increment)) - angle_min
        )
        increment = float(np.fmod(increment + 5 * np.pi, 2 * np.pi) - np.pi)
        range_max = float(msg.range_max)
        if p.laser_max_range > 0.0:
            range_max = min(range_max, p.laser_max_range)
        range_min = float(msg.range_min)
        if p.laser_min_range > 0.0:
            range_min = max(range_min, p.laser_min_range)
        if range_max <= 0.0 or range_min < 0.0:
            self.log.error("range_max or range_min from laser is negative! ignore this message.")
            return None
        ranges = np.asarray(msg.ranges, dtype=float)
        bearings = angle_min + np.arange(len(ranges)) * increment
        return LaserScanData(prepare_ranges(ranges, range_min, range_max), bearings, range_max)

    # ---------------------------------------------------------------- outputs
    def _publish_cloud(self) -> None:
        from workbench.msgs.geometry_msgs import PoseArray

        assert self.localizer is not None
        cloud = PoseArray(poses=pose_list(self.localizer.pf.poses))
        cloud.header.stamp = self.node.now()
        cloud.header.frame_id = self.params.global_frame_id
        self.cloud_pub.publish(cloud)

    def _publish_pose(self, stamp: Any, pose: np.ndarray, cov: np.ndarray | None) -> None:
        from workbench.msgs.geometry_msgs import PoseWithCovarianceStamped

        cov = cov if cov is not None else np.zeros((3, 3))
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = self.params.global_frame_id
        msg.header.stamp = stamp
        set_planar(msg.pose.pose.position, msg.pose.pose.orientation, pose)
        msg.pose.covariance = covariance_36(cov)
        self.pose_pub.publish(msg)
        self._last_pose = (np.asarray(pose, dtype=float).copy(), cov.copy())
        self.log.debug("New pose: %6.3f %6.3f %6.3f", pose[0], pose[1], pose[2])

    def _send_transform(self, scan_stamp: Any) -> None:
        from workbench.msgs import Duration
        from workbench.msgs.geometry_msgs import TransformStamped

        p = self.params
        if not p.tf_broadcast or self._latest_tf is None:
            return
        msg = TransformStamped()
        msg.header.stamp = scan_stamp + Duration.from_sec(p.transform_tolerance)
        msg.header.frame_id = p.global_frame_id
        msg.child_frame_id = p.odom_frame_id
        set_planar(msg.transform.translation, msg.transform.rotation, self._latest_tf)
        self.broadcaster.send_transform(msg)

    def map_to_odom(self) -> np.ndarray | None:
        """The last ``map -> odom`` transform ``(x, y, theta)``, None before the first pose."""
        with self._lock:
            return None if self._latest_tf is None else self._latest_tf.copy()

    def _maybe_save_pose(self) -> None:
        p = self.params
        now = self.node.now().to_sec()
        if p.save_pose_rate > 0 and now - self._save_last >= 1.0 / p.save_pose_rate:
            self.save_pose()
            self._save_last = now

    def save_pose(self) -> None:
        """Store the pose and covariance in ``~initial_pose_*`` / ``~initial_cov_*`` (``savePoseToServer``)."""
        if self._latest_tf is None or self._last_pose is None:
            return
        x, y, a = (float(v) for v in compose(self._latest_tf, self._latest_odom))
        cov = self._last_pose[1]
        for name, value in (
            ("initial_pose_x", x),
            ("initial_pose_y", y),
            ("initial_pose_a", a),
            ("initial_cov_xx", float(cov[0, 0])),
            ("initial_cov_yy", float(cov[1, 1])),
            ("initial_cov_aa", float(cov[2, 2])),
        ):
            self.node.set_param("~" + name, value)

    def _check_laser_received(self, event: Any) -> None:
        waited = self.node.now().to_sec() - self._last_scan_time
        if waited > LASER_CHECK_INTERVAL:
            self.log.warn(
                "No laser scan received (and thus no pose updates have been published) for %f "
                "seconds.  Verify that data is being published on the %s topic.",
                waited,
                self.node.resolve_name("scan"),
            )

    # ------------------------------------------------------ map and initial pose
    def handle_map(self, grid: Any) -> None:
        """Take a new map and restart the filter (``handleMapMessage``)."""
        p = self.params
        info = grid.info
        self.log.info(
            "Received a %d X %d map @ %.3f m/pix", info.width, info.height, info.resolution
        )
        if grid.header.frame_id != p.global_frame_id:
            self.log.warn(
                "Frame_id of map received:'%s' doesn't match global_frame_id:'%s'. This could "
                "cause issues with reading published topics",
                grid.header.frame_id,
                p.global_frame_id,
            )
        amcl_map = AmclMap.from_message(grid)
        self._lasers.clear()
        self._update_initial_from_params()
        self.log.info(
            "Initializing likelihood field model; this can take some time on large maps..."
        )
        self.localizer = Localizer(amcl_map, p)
        self.log.info("Done initializing likelihood field model.")
        self._apply_initial_pose()

    def _update_initial_from_params(self) -> None:
        """Re-read ``~initial_pose_*`` / ``~initial_cov_*`` (``updatePoseFromServer``)."""
        for name in INITIAL_PARAMS:
            value = self.node.get_param("~" + name, getattr(self.params, name))
            if isinstance(value, (int, float)) and not np.isnan(value):
                setattr(self.params, name, float(value))

    def handle_initial_pose(self, msg: Any) -> None:
        """Restart the filter at a pose from ``initialpose`` (``handleInitialPoseMessage``)."""
        from workbench.tf import TransformException

        p = self.params
        frame = str(msg.header.frame_id)
        if frame == "":
            self.log.warn(
                "Received initial pose with empty frame_id.  You should always supply a frame_id."
            )
        elif strip_slash(frame) != p.global_frame_id:
            self.log.warn(
                'Ignoring initial pose in frame "%s"; initial poses must be in the global '
                'frame, "%s"',
                strip_slash(frame),
                p.global_frame_id,
            )
            return
        now = self.node.now()
        try:
            moved = transform_pose(
                self.buffer.lookup_transform_full(
                    p.base_frame_id, msg.header.stamp, p.base_frame_id, now, p.odom_frame_id, 0.5
                )
            )
        except TransformException as error:
            if self._sent_first_transform:
                self.log.warn(
                    "Failed to transform initial pose in time (%s)", str(error).splitlines()[0]
                )
            moved = np.zeros(3)
        pose = compose(planar(msg.pose.pose.position, msg.pose.pose.orientation), moved)
        self.log.info("Setting pose (%.6f): %.3f %.3f %.3f", now.to_sec(), *pose)
        self._initial = (pose, covariance_3(msg.pose.covariance))
        self._apply_initial_pose()
        if p.force_update_after_initialpose and self.localizer is not None:
            self.localizer.force_update = True

    def _apply_initial_pose(self) -> None:
        if self._initial is not None and self.localizer is not None:
            self.localizer.set_pose(*self._initial)
            self._initial = None

    # ---------------------------------------------------------------- services
    def _on_global_localization(self, request: Any) -> Any:
        from workbench.msgs.std_srvs import Empty

        with self._lock:
            if self.localizer is not None:
                self.log.info("Initializing with uniform distribution")
                self.localizer.global_localization()
                self.log.info("Global initialisation done!")
        return Empty.Response()

    def _on_nomotion_update(self, request: Any) -> Any:
        from workbench.msgs.std_srvs import Empty

        with self._lock:
            if self.localizer is not None:
                self.localizer.force_update = True
        return Empty.Response()

    def _on_set_map(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import SetMap

        with self._lock:
            self.handle_map(request.map)
            self.handle_initial_pose(request.initial_pose)
            if self.params.force_update_after_set_map and self.localizer is not None:
                self.localizer.force_update = True
        return SetMap.Response(success=True)


def main(argv: Sequence[str] = ()) -> int:
    """``amcl/amcl``: localise from ``scan``, tf and the map until interrupted."""
    from workbench.bus import Node

    node = Node("amcl", argv=list(argv))
    amcl: Amcl | None = None
    try:
        amcl = Amcl(node)
        node.on_shutdown(_pose_saver(amcl))
        node.bus.spin()
    finally:
        if amcl is not None:
            amcl.close()
        node.shutdown()
    return 0


def _pose_saver(amcl: Amcl) -> Any:
    """A shutdown hook that saves the last pose to ``~initial_pose_*`` as ROS's amcl does when
    interrupted; it runs while the node can still reach the parameter server (after
    ``spin`` returns, a Ctrl-C has already closed the bus)."""

    def save(*_: Any) -> None:
        if amcl.localizer is not None:
            amcl.save_pose()

    return save


__all__ = ["Amcl", "main"]
