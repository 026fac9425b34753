"""2-D laser mapping: occupancy grids, map_server map files, laser logs and graph SLAM.

Only numpy and scipy are used here (no simulator, no bus), so everything can
run offline on recorded logs.
"""

from __future__ import annotations

from workbench.mapping.bagfile import read_bag, read_log, resolve_log, shipped_logs
from workbench.mapping.carmen import read_carmen
from workbench.mapping.errors import LogError, MapFileError
from workbench.mapping.grid import GridMap, OccupancyGrid
from workbench.mapping.likelihood import LikelihoodField
from workbench.mapping.mapfile import MapMetadata, load_map, read_map_metadata, save_map
from workbench.mapping.matcher import MatchResult, match_scan
from workbench.mapping.posegraph import Edge, PoseGraph
from workbench.mapping.scan import LaserLog, Scan
from workbench.mapping.slam import Slam, SlamConfig, SlamResult, build_map, run_slam

__all__ = [
    "Edge",
    "GridMap",
    "LaserLog",
    "LikelihoodField",
    "LogError",
    "MapFileError",
    "MapMetadata",
    "MatchResult",
    "OccupancyGrid",
    "PoseGraph",
    "Scan",
    "Slam",
    "SlamConfig",
    "SlamResult",
    "build_map",
    "load_map",
    "match_scan",
    "read_bag",
    "read_carmen",
    "read_log",
    "resolve_log",
    "shipped_logs",
    "read_map_metadata",
    "run_slam",
    "save_map",
]
