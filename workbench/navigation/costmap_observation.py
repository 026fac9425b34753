"""Laser observations for the obstacle layer (costmap_2d's ObservationBuffer, Noetic).

A scan becomes points as laser_geometry projects it (readings that are finite and in
``[range_min, range_max)``; with ``inf_is_valid`` a +inf reading becomes
``range_max - 0.0001``), transformed into the costmap's global frame with the
transform at the scan's stamp. The sensor origin is the origin of ``sensor_frame``
(default: the scan's frame) at that stamp. Points outside
``[min_obstacle_height, max_obstacle_height]`` (global z) are dropped. With
``observation_persistence`` 0 only the newest observation is kept, else those no
older than it (s) before the last update.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.navigation.costmap_params import Params


@dataclass
class Observation:
    """A sensor reading in the global frame.

    Attributes:
        origin: The sensor origin ``(x, y, z)`` (m).
        points: ``(N, 3)`` points (m).
        obstacle_range: Points farther than this mark nothing (m).
        raytrace_range: Rays clear at most this far (m).
        stamp: The reading's time (s).
    """

    origin: np.ndarray
    points: np.ndarray
    obstacle_range: float
    raytrace_range: float
    stamp: float


def scan_points(msg: Any, inf_is_valid: bool = False) -> np.ndarray:
    """A ``sensor_msgs/LaserScan``'s points in its own frame, ``(N, 3)`` (m)."""
    ranges = np.asarray(msg.ranges, dtype=np.float64)
    angles = float(msg.angle_min) + np.arange(ranges.size) * float(msg.angle_increment)
    range_max = float(msg.range_max)
    if inf_is_valid:
        ranges = np.where(np.isposinf(ranges), np.float32(range_max) - np.float32(0.0001), ranges)
    keep = np.isfinite(ranges) & (ranges >= float(msg.range_min)) & (ranges < range_max)
    r, a = ranges[keep], angles[keep]
    return np.column_stack((r * np.cos(a), r * np.sin(a), np.zeros(r.size)))


class ObservationBuffer:
    """One observation source of the obstacle layer.

    Args:
        source: The source's name (in ``observation_sources``).
        params: The source's parameters (``<layer>/<source>``; ``obstacle_range`` and
            ``raytrace_range`` are searched from there upwards, as costmap_2d does).
        global_frame: The costmap's frame.
    """

    def __init__(self, source: str, params: Params, global_frame: str) -> None:
        self.source = source
        self.topic = params.text("topic", source)
        self.sensor_frame = params.text("sensor_frame", "")
        self.keep_time = params.number("observation_persistence", 0.0)
        self.expected_update_rate = params.number("expected_update_rate", 0.0)
        self.data_type = params.text("data_type", "PointCloud")
        self.min_obstacle_height = params.number("min_obstacle_height", 0.0)
        self.max_obstacle_height = params.number("max_obstacle_height", 2.0)
        self.inf_is_valid = params.flag("inf_is_valid", False)
        self.clearing = params.flag("clearing", False)
        self.marking = params.flag("marking", True)
        self.obstacle_range = _searched_number(params, "obstacle_range", 2.5)
        self.raytrace_range = _searched_number(params, "raytrace_range", 3.0)
        self.global_frame = global_frame
        self.observations: list[Observation] = []
        self.last_updated = 0.0

    def buffer_scan(self, msg: Any, tf_buffer: Any, now: float) -> None:
        """Add a scan (``bufferCloud``); raises tf's exceptions when it cannot be placed."""
        from workbench.spatial.messages import matrix_from_msg

        stamp = msg.header.stamp
        scan_frame = str(msg.header.frame_id)
        origin_frame = self.sensor_frame or scan_frame
        to_global = matrix_from_msg(
            tf_buffer.lookup_transform(self.global_frame, scan_frame, stamp).transform
        )
        if origin_frame == scan_frame:
            origin = to_global[:3, 3].copy()
        else:
            origin_tf = tf_buffer.lookup_transform(self.global_frame, origin_frame, stamp)
            origin = matrix_from_msg(origin_tf.transform)[:3, 3].copy()
        local = scan_points(msg, self.inf_is_valid)
        points = local @ to_global[:3, :3].T + to_global[:3, 3]
        z = points[:, 2]
        keep = (z <= self.max_obstacle_height) & (z >= self.min_obstacle_height)
        self.observations.insert(
            0,
            Observation(
                origin,
                points[keep],
                self.obstacle_range,
                self.raytrace_range,
                float(stamp.to_sec()),
            ),
        )
        self.last_updated = now
        self.purge()

    def purge(self) -> None:
        """Drop stale observations (``purgeStaleObservations``)."""
        if not self.observations:
            return
        if self.keep_time == 0.0:
            del self.observations[1:]
            return
        for i, obs in enumerate(self.observations):
            if self.last_updated - obs.stamp > self.keep_time:
                del self.observations[i:]
                return

    def get(self) -> list[Observation]:
        """The current observations (newest first)."""
        self.purge()
        return list(self.observations)

    def is_current(self, now: float, log: Any) -> bool:
        """Whether the source was updated within ``expected_update_rate`` (0: always)."""
        if self.expected_update_rate == 0.0:
            return True
        late = now - self.last_updated
        if late <= self.expected_update_rate:
            return True
        log.warn(
            "The %s observation buffer has not been updated for %.2f seconds, and it should "
            "be updated every %.2f seconds.",
            self.topic,
            late,
            self.expected_update_rate,
        )
        return False

    def reset_last_updated(self, now: float) -> None:
        """Count the source as updated now (``resetLastUpdated``)."""
        self.last_updated = now


def _searched_number(params: Params, key: str, default: float) -> float:
    found = params.search(key)
    if found is None:
        return default
    return params.number(key, default, full=found)


__all__ = ["Observation", "ObservationBuffer", "scan_points"]
