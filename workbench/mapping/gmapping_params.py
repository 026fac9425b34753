"""slam_gmapping's private parameters, read as ``slam_gmapping.cpp`` (noetic) reads them.

The names and defaults are GMapping's. Those that mean something for graph SLAM
(frames, periods, ranges, resolution, initial map bounds, update distances) are
used; the particle filter's and scan matcher's own tuning (``particles``,
``sigma``, ``lstep``, ``srr`` ...) has no counterpart here: it is accepted and
named in one notice line.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from workbench.mapping.config import SlamConfig

#: GMapping parameters accepted but without meaning for graph SLAM (besides ``particles``).
IGNORED = (
    "sigma",
    "kernelSize",
    "lstep",
    "astep",
    "iterations",
    "lsigma",
    "ogain",
    "lskip",
    "minimumScore",
    "srr",
    "srt",
    "str",
    "stt",
    "resampleThreshold",
    "llsamplerange",
    "llsamplestep",
    "lasamplerange",
    "lasamplestep",
    "occ_thresh",
    "minUrange",
)


@dataclass
class GmappingParams:
    """The parameters slam_gmapping uses.

    Attributes:
        base_frame: The robot's frame (``~base_frame``, ``base_link``).
        odom_frame: The odometry frame (``~odom_frame``, ``odom``).
        map_frame: The map frame (``~map_frame``, ``map``).
        transform_publish_period: Seconds between ``map -> odom`` transforms (0: none).
        tf_delay: The transform is stamped this far in the future (s; default the period).
        map_update_interval: Seconds of scan time between map publications.
        throttle_scans: Only every this many scans is used.
        max_range: ``~maxRange``: readings at or beyond it are no-returns (m); None: the
            first scan's ``range_max - 0.01``.
        max_urange: ``~maxUrange``: readings are used up to this (m); None: ``max_range``.
        delta: Map resolution (m).
        xmin: Initial map bounds (m); the map grows beyond them.
        ymin: See ``xmin``.
        xmax: See ``xmin``.
        ymax: See ``xmin``.
        linear_update: Process a scan after this much travel (m).
        angular_update: ... or this much turn (rad).
        temporal_update: ... or this much time (s); negative: never by time.
        particles: ``~particles`` if it was set (ignored).
        ignored: The other GMapping parameters that were set (ignored).
    """

    base_frame: str = "base_link"
    odom_frame: str = "odom"
    map_frame: str = "map"
    transform_publish_period: float = 0.05
    tf_delay: float = 0.05
    map_update_interval: float = 5.0
    throttle_scans: int = 1
    max_range: float | None = None
    max_urange: float | None = None
    delta: float = 0.05
    xmin: float = -100.0
    ymin: float = -100.0
    xmax: float = 100.0
    ymax: float = 100.0
    linear_update: float = 1.0
    angular_update: float = 0.5
    temporal_update: float = -1.0
    particles: int | None = None
    ignored: tuple[str, ...] = ()

    def ranges(self, range_max: float) -> tuple[float, float]:
        """``(maxRange, maxUrange)`` for a laser whose ``range_max`` is given (initMapper)."""
        max_range = self.max_range if self.max_range is not None else range_max - 0.01
        max_urange = self.max_urange if self.max_urange is not None else max_range
        return float(max_range), float(min(max_urange, max_range))

    def slam_config(self, range_max: float) -> SlamConfig:
        """The graph-SLAM configuration for a laser whose ``range_max`` is given."""
        _, max_urange = self.ranges(range_max)
        return SlamConfig(
            resolution=self.delta,
            linear_update=self.linear_update,
            angular_update=self.angular_update,
            temporal_update=self.temporal_update,
            max_urange=max_urange,
            match_range=max_urange,
            # Live: odometry from the robot's encoders at every scan, as GMapping's motion
            # model uses it.
            weigh_odometry=True,
            # Scans a fraction of a second apart: search as far as the odometry can be off.
            odometry_window=True,
            # A robot wandering a house closes a loop every few keyframes.
            loop_defer_chi2=1.0,
            loop_every=4,
            # The estimator's own grid starts no larger than a scan's reach and grows; the
            # published map is padded to the initial bounds.
            map_size=min(max(self.xmax - self.xmin, self.ymax - self.ymin), 2 * max_urange + 2),
        )

    def notices(self) -> list[str]:
        """The notice lines for parameters that were set and are ignored."""
        lines = []
        if self.particles is not None:
            lines.append(
                f"~particles ({self.particles}) is ignored: this slam_gmapping keeps one "
                "graph-SLAM estimate, not a particle filter"
            )
        if self.ignored:
            lines.append(
                "ignored GMapping parameters (graph SLAM has its own scan matcher and "
                f"motion model): {', '.join(self.ignored)}"
            )
        return lines


def _number(node: Any, name: str, default: float) -> float:
    value = node.get_param("~" + name, default)
    try:
        return float(value)
    except (TypeError, ValueError):
        from workbench.mapping.errors import MappingError

        raise MappingError(f"parameter ~{name} must be a number, got {value!r}") from None


def read_params(node: Any) -> GmappingParams:
    """slam_gmapping's parameters from ``node``'s private namespace.

    Raises:
        MappingError: A numeric parameter is not a number, or a value is out of range.
    """
    from workbench.mapping.errors import MappingError

    p = GmappingParams()
    p.base_frame = str(node.get_param("~base_frame", p.base_frame))
    p.odom_frame = str(node.get_param("~odom_frame", p.odom_frame))
    p.map_frame = str(node.get_param("~map_frame", p.map_frame))
    p.transform_publish_period = _number(node, "transform_publish_period", 0.05)
    p.tf_delay = _number(node, "tf_delay", p.transform_publish_period)
    p.map_update_interval = _number(node, "map_update_interval", 5.0)
    p.throttle_scans = max(1, int(_number(node, "throttle_scans", 1)))
    if node.has_param("~maxRange"):
        p.max_range = _number(node, "maxRange", 30.0)
    if node.has_param("~maxUrange"):
        p.max_urange = _number(node, "maxUrange", 30.0)
    p.delta = _number(node, "delta", 0.05)
    p.xmin = _number(node, "xmin", -100.0)
    p.ymin = _number(node, "ymin", -100.0)
    p.xmax = _number(node, "xmax", 100.0)
    p.ymax = _number(node, "ymax", 100.0)
    p.linear_update = _number(node, "linearUpdate", 1.0)
    p.angular_update = _number(node, "angularUpdate", 0.5)
    p.temporal_update = _number(node, "temporalUpdate", -1.0)
    if node.has_param("~particles"):
        p.particles = int(_number(node, "particles", 30))
    p.ignored = tuple(name for name in IGNORED if node.has_param("~" + name))
    if not p.delta > 0:
        raise MappingError(f"parameter ~delta must be positive, got {p.delta}")
    if p.xmax <= p.xmin or p.ymax <= p.ymin:
        raise MappingError(
            f"the initial map bounds are empty: x {p.xmin}..{p.xmax}, y {p.ymin}..{p.ymax}"
        )
    if p.transform_publish_period < 0:
        raise MappingError("parameter ~transform_publish_period must not be negative")
    return p


__all__ = ["IGNORED", "GmappingParams", "read_params"]
