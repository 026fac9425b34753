"""``map_server/map_server``: serve a saved map on the bus, as ROS Noetic's map_server does.

``workbench run map_server map_server MAP.yaml`` (``map_server/src/main.cpp``,
map_server 1.17):

* reads the YAML (:func:`~workbench.mapping.map_server_yaml.read_map_yaml`) and
  the image (:func:`~workbench.mapping.mapfile.pixels_to_map`: trinary, scale or
  raw, negate, thresholds; image row 0 is the top map row);
* publishes the map once on the latched topics ``map`` (``nav_msgs/OccupancyGrid``)
  and ``map_metadata`` (``nav_msgs/MapMetaData``), stamped now, in the frame
  ``~frame_id`` (default ``map``), the origin's yaw as a quaternion about z;
* serves ``static_map`` (``nav_msgs/GetMap``: the same map) and ``change_map``
  (``nav_msgs/LoadMap``: load another YAML and publish it; result 0, or 255 when
  it cannot be loaded, keeping the old map);
* logs ``Loading map from image "..."``, ``Read a W X H map @ R m/cell`` and, per
  request, ``Sending map``;
* the deprecated ``map_server IMAGE RESOLUTION`` warns and reads ``~negate``,
  ``~occupied_thresh`` and ``~free_thresh`` (0, 0.65, 0.196) with origin 0.

A bad YAML or image is one error line naming the file and the key (map_server's
own texts), and the node exits with status 1. The node is anonymous
(``map_server_<pid>_<ms>``) as the original's ``ros::init_options::AnonymousName``.
"""

from __future__ import annotations

import re
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from workbench.mapping.errors import MapFileError, MappingError
from workbench.mapping.grid_message import occupancy_grid_message
from workbench.mapping.map_server_yaml import read_map_yaml
from workbench.mapping.mapfile import MapMetadata, pixels_to_map
from workbench.mapping.pgm import read_image

USAGE = (
    "USAGE: map_server <map.yaml> (map.yaml: map description file); "
    "DEPRECATED USAGE: map_server <map> <resolution> "
    "(map: image file to load, resolution: map resolution [meters/pixel])"
)
DEPRECATED_WARNING = "Using deprecated map server interface. Please switch to new interface."


def c_atof(text: str) -> float:
    """C's ``atof``: the longest number at the start of ``text`` (after blanks), else 0."""
    match = re.match(r"\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", text)
    return float(match.group(0)) if match else 0.0


@dataclass
class LoadedMap:
    """A map read from disk, ready to publish.

    Attributes:
        meta: Its YAML's contents (or the deprecated form's values).
        cells: ``(height, width)`` int8 cells, row 0 at the origin.
    """

    meta: MapMetadata
    cells: np.ndarray


def load_image(meta: MapMetadata) -> LoadedMap:
    """Read the image of ``meta`` into cells as map_server's ``loadMapFromFile``.

    Raises:
        MapFileError: ``failed to open image file "IMAGE": reason``, as map_server says.
    """
    try:
        pixels, has_alpha = read_image(meta.image)
    except MapFileError as error:
        raise MapFileError(f'failed to open image file "{meta.image}": {error.message}') from None
    return LoadedMap(meta, pixels_to_map(pixels, has_alpha, meta))


def load_map_yaml(path: str) -> LoadedMap:
    """Read a map YAML and its image as ``map_server MAP.yaml`` does.

    Raises:
        MapFileError: map_server's error for the first bad key, or the image's.
    """
    return load_image(read_map_yaml(path))


class MapServer:
    """map_server on a bus node: latched ``map`` and ``map_metadata``, ``static_map``, ``change_map``.

    Args:
        node: The ``workbench.bus.Node``.
        source: The map YAML (or, with ``resolution``, the image), or a map loaded
            already (:func:`load_map_yaml`).
        resolution: Non-zero: the deprecated form (``source`` is an image of this
            resolution, read with the ``~negate``/``~occupied_thresh``/``~free_thresh``
            parameters and origin 0).

    Raises:
        MapFileError: The map cannot be loaded (map_server's error text).
    """

    def __init__(self, node: Any, source: str | LoadedMap, resolution: float = 0.0) -> None:
        from workbench.msgs.nav_msgs import GetMap, LoadMap, MapMetaData, OccupancyGrid

        self.node = node
        self.log = node.get_logger()
        self.frame_id = str(node.get_param("~frame_id", "map"))
        self._lock = threading.Lock()
        self.map = OccupancyGrid()
        self._servers = [
            node.create_service("static_map", GetMap, self._on_get_map),
            node.create_service("change_map", LoadMap, self._on_change_map),
        ]
        self.metadata_pub = node.create_publisher("map_metadata", MapMetaData, 1, latch=True)
        self.map_pub = node.create_publisher("map", OccupancyGrid, 1, latch=True)
        if isinstance(source, LoadedMap):
            self.publish(source)
        elif resolution == 0:
            self.load_yaml(source)
        else:
            self.load_image(source, resolution)

    def load_yaml(self, path: str) -> None:
        """Load the map of a YAML and publish it (``loadMapFromYaml``)."""
        self.publish(load_map_yaml(path))

    def load_image(self, image: str, resolution: float) -> None:
        """Load an image with the deprecated parameters and publish it (``loadMapFromParams``)."""
        meta = MapMetadata(
            yaml_path=Path(image),
            image=Path(image),
            resolution=resolution,
            origin=(0.0, 0.0, 0.0),
            negate=bool(self.node.get_param("~negate", 0)),
            occupied_thresh=float(self.node.get_param("~occupied_thresh", 0.65)),
            free_thresh=float(self.node.get_param("~free_thresh", 0.196)),
        )
        self.publish(load_image(meta))

    def publish(self, loaded: LoadedMap) -> None:
        """Make ``loaded`` the map: publish it on ``map`` and ``map_metadata``, serve it."""
        meta = loaded.meta
        self.log.info('Loading map from image "%s"', meta.image)
        now = self.node.now()
        grid = occupancy_grid_message(
            loaded.cells, meta.resolution, meta.origin, self.frame_id, now, load_time=now
        )
        info = grid.info
        self.log.info("Read a %d X %d map @ %.3f m/cell", info.width, info.height, info.resolution)
        with self._lock:
            self.map = grid
        self.metadata_pub.publish(grid.info)
        self.map_pub.publish(grid)

    def _on_get_map(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import GetMap

        with self._lock:
            grid = self.map
        self.log.info("Sending map")
        return GetMap.Response(map=grid)

    def _on_change_map(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import LoadMap

        try:
            self.load_yaml(request.map_url)
        except MapFileError as error:
            self.log.error("%s", error.one_line())
            return LoadMap.Response(result=LoadMap.Response.RESULT_UNDEFINED_FAILURE)
        self.log.info("Changed map to %s", request.map_url)
        return LoadMap.Response(result=LoadMap.Response.RESULT_SUCCESS)


def parse_arguments(args: Sequence[str]) -> tuple[str, float]:
    """``(file, resolution)`` from map_server's arguments (resolution 0: a YAML).

    Raises:
        MappingError: Not one or two arguments (the usage).
    """
    if len(args) not in (1, 2):
        raise MappingError(f"map_server takes 1 or 2 arguments, got {len(args)}", hint=USAGE)
    return args[0], (c_atof(args[1]) if len(args) == 2 else 0.0)


def main(argv: Sequence[str] = ()) -> int:
    """``map_server/map_server``: serve the map until interrupted."""
    from workbench.bus import Node
    from workbench.bus.names import myargv

    fname, resolution = parse_arguments(myargv(list(argv)))
    # A bad map is reported before joining the bus, so it is the only line printed.
    source: str | LoadedMap = load_map_yaml(fname) if resolution == 0 else fname
    node = Node("map_server", argv=list(argv), anonymous=True)
    try:
        if len(myargv(list(argv))) == 2:
            node.get_logger().warn(DEPRECATED_WARNING)
        MapServer(node, source, resolution)
        node.bus.spin()
    finally:
        node.shutdown()
    return 0


__all__ = [
    "LoadedMap",
    "MapServer",
    "load_image",
    "load_map_yaml",
    "main",
    "parse_arguments",
]
