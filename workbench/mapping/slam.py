"""Graph SLAM for a planar laser over a whole log: :func:`run_slam` and :func:`build_map`.

:func:`run_slam` feeds the scans one by one to the incremental
:class:`~workbench.mapping.incremental.Slam` (scan matching with
odometry along unconstrained directions, keyframes, checked loop closures,
sparse pose-graph optimisation) and optimises the graph once more at the
end. Scans that are not keyframes keep their pose relative to the keyframe
before them. :func:`build_map` then integrates all scans at their poses.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from workbench.mapping.config import SlamConfig
from workbench.mapping.geometry import transform_points
from workbench.mapping.grid import OccupancyGrid
from workbench.mapping.incremental import Slam
from workbench.mapping.posegraph import PoseGraph
from workbench.mapping.scan import Scan, free_ends

__all__ = ["Slam", "SlamConfig", "SlamResult", "build_map", "run_slam"]


@dataclass
class SlamResult:
    """The output of :func:`run_slam`.

    Attributes:
        poses: Estimated sensor pose per scan ``(N, 3)`` in the map frame (m, rad).
        stamps: Time per scan (s).
        keyframes: Index of the scan of each pose-graph node.
        graph: The optimised pose graph.
        loop_closures: ``(node_i, node_j)`` per accepted loop closure.
        scores: Front-end match score per scan (NaN where not matched).
    """

    poses: np.ndarray
    stamps: np.ndarray
    keyframes: list[int]
    graph: PoseGraph
    loop_closures: list[tuple[int, int]] = field(default_factory=list)
    scores: np.ndarray = field(default_factory=lambda: np.zeros(0))


def run_slam(
    scans: list[Scan],
    config: SlamConfig | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> SlamResult:
    """Estimate the sensor trajectory of a scan sequence.

    Args:
        scans: Scans in time order, each with its odometry.
        config: Parameters (defaults when None).
        progress: Called as ``progress(done, total)`` after each scan.

    Returns:
        The poses of all scans and the pose graph.
    """
    config = config or SlamConfig()
    slam = Slam(config)
    for index, scan in enumerate(scans):
        slam.add_scan(scan)
        if progress is not None:
            progress(index + 1, len(scans))
    slam.optimize(iterations=20)
    return SlamResult(
        poses=slam.poses(),
        stamps=slam.stamps,
        keyframes=list(slam.keyframes),
        graph=slam.graph,
        loop_closures=list(slam.loop_closures),
        scores=slam.scores,
    )


def build_map(
    scans: list[Scan], poses: np.ndarray, resolution: float = 0.05, max_range: float = 30.0
) -> OccupancyGrid:
    """Integrate scans at their poses into an occupancy grid that covers them.

    Args:
        scans: The scans.
        poses: Sensor pose per scan ``(N, 3)`` (m, rad).
        resolution: Cell size (m).
        max_range: The usable range (GMapping's ``maxUrange``, m): readings at or
            beyond it, and no-return readings (the scan's ``max_range`` or +inf), mark
            free space up to it and never an obstacle; readings beyond the scan's
            ``max_range`` (error codes such as a SICK's 81.83 m) mark nothing.
    """
    ends = [transform_points(p, free_ends(s, max_range)) for s, p in zip(scans, poses, strict=True)]
    ends.append(np.asarray(poses)[:, :2])
    grid = OccupancyGrid.covering(np.concatenate(ends), resolution, margin=1.0)
    for scan, pose in zip(scans, poses, strict=True):
        grid.integrate_scan(
            pose,
            scan.ranges,
            scan.angles,
            max_range=scan.max_range,
            min_range=scan.min_range,
            free_range=max_range,
        )
    return grid
