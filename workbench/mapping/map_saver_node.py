"""``map_server/map_saver``: save the map published on ``map``, as ROS Noetic's map_saver does.

``workbench run map_server map_saver [--occ T] [--free T] [-f NAME] [map:=/topic]``
(``map_server/src/map_saver.cpp``, map_server 1.17):

* logs ``Waiting for the map`` and subscribes to ``map`` (``nav_msgs/OccupancyGrid``,
  queue 1; latched by map_server, slam_gmapping and friends);
* on the first map, logs ``Received a W X H map @ R m/pix``, writes ``NAME.pgm``
  (``Writing map occupancy data to NAME.pgm``): binary P5 with the comment
  ``# CREATOR: map_saver.cpp R m/pix``, rows from the top, a cell in
  ``0..free`` 254, else one ``>= occ`` 0, anything else 205 (``--occ`` 65 and
  ``--free`` 25 by default); then ``NAME.yaml`` (logged with the same words) with
  ``image: NAME.pgm``, ``resolution``, ``origin: [x, y, yaw]`` (``%f``; the yaw
  from the orientation as tf2's ``getEulerYPR``), ``negate: 0``,
  ``occupied_thresh: 0.65``, ``free_thresh: 0.196`` and an empty line; logs
  ``Done`` and exits.

``NAME`` is used as given, relative to the working directory, and is what the
YAML's ``image`` says. Unlike the original, which logs ``Couldn't save map file
to NAME.pgm`` and goes on waiting, an unwritable file is an error that ends the
node (status 1). Without a map it waits, as the original, until Ctrl-C or SIGTERM.
"""

from __future__ import annotations

import math
import re
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from workbench.mapping.errors import MapFileError, MappingError
from workbench.mapping.mapfile import cells_to_pixels

USAGE = (
    "Usage: \n"
    "  map_saver -h\n"
    "  map_saver [--occ <threshold_occupied>] [--free <threshold_free>] [-f <mapname>] "
    "[ROS remapping args]"
)
_USAGE_HINT = "usage: " + USAGE.splitlines()[-1].strip()

#: map_saver's default thresholds on cell values (percent).
DEFAULT_OCCUPIED = 65
DEFAULT_FREE = 25


@dataclass
class SaverOptions:
    """map_saver's command line.

    Attributes:
        mapname: ``-f``: the files are ``mapname.pgm`` and ``mapname.yaml``.
        threshold_occupied: ``--occ``: a cell at least this is occupied (1..100).
        threshold_free: ``--free``: a cell from 0 to this is free (0..100).
        show_help: ``-h`` was given.
    """

    mapname: str = "map"
    threshold_occupied: int = DEFAULT_OCCUPIED
    threshold_free: int = DEFAULT_FREE
    show_help: bool = False


def c_atoi(text: str) -> int:
    """C's ``atoi``: the integer at the start of ``text`` (after blanks), else 0."""
    match = re.match(r"\s*([+-]?\d+)", text)
    return int(match.group(1)) if match else 0


def check_thresholds(threshold_occupied: int, threshold_free: int) -> None:
    """Raise map_saver's error for thresholds it refuses.

    Raises:
        MappingError: ``threshold_occupied must be between 1 and 100`` and the like.
    """
    if not 1 <= threshold_occupied <= 100:
        raise MappingError("threshold_occupied must be between 1 and 100")
    if not 0 <= threshold_free <= 100:
        raise MappingError("threshold_free must be between 0 and 100")
    if threshold_occupied <= threshold_free:
        raise MappingError("threshold_free must be smaller than threshold_occupied")


def parse_arguments(args: Sequence[str]) -> SaverOptions:
    """map_saver's options from its arguments (remappings removed), read left to right.

    Raises:
        MappingError: An unknown argument, a missing value, or a threshold out of range.
    """
    options = SaverOptions()
    values = list(args)
    index = 0
    while index < len(values):
        arg = values[index]
        if arg == "-h":
            options.show_help = True
            return options
        if arg not in ("-f", "--occ", "--free"):
            raise MappingError(f"map_saver: unknown argument '{arg}'", hint=_USAGE_HINT)
        if index + 1 >= len(values):
            raise MappingError(f"map_saver: {arg} needs a value", hint=_USAGE_HINT)
        value = values[index + 1]
        if arg == "-f":
            options.mapname = value
        elif arg == "--occ":
            options.threshold_occupied = c_atoi(value)
            if not 1 <= options.threshold_occupied <= 100:
                raise MappingError("threshold_occupied must be between 1 and 100")
        else:
            options.threshold_free = c_atoi(value)
            if not 0 <= options.threshold_free <= 100:
                raise MappingError("threshold_free must be between 0 and 100")
        index += 2
    check_thresholds(options.threshold_occupied, options.threshold_free)
    return options


def c_fixed(value: float, digits: int = 6) -> str:
    """``value`` as glibc's ``printf("%.<digits>f")`` writes it (``-nan`` for a negative NaN)."""
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    return f"{value:.{digits}f}"


def yaw_from_quaternion(x: float, y: float, z: float, w: float) -> float:
    """The yaw map_saver writes: tf2 ``Matrix3x3(q).getEulerYPR`` (solution 1).

    A quaternion of length 0 has no rotation: tf2 divides by zero and the yaw is
    NaN, which glibc prints ``-nan`` on x86-64; so is the result here.
    """
    length2 = x * x + y * y + z * z + w * w
    if length2 == 0.0 or not math.isfinite(length2):
        return -math.nan
    s = 2.0 / length2
    ys, zs = y * s, z * s  # tf2 Matrix3x3::setRotation, same operations in the same order
    m00 = 1.0 - (y * ys + z * zs)
    m10 = x * ys + w * zs
    m20 = x * zs - w * ys
    if abs(m20) >= 1.0:
        return 0.0  # pitch at a singularity: tf2 sets the yaw to 0
    cos_pitch = math.cos(-math.asin(m20))
    return math.atan2(m10 / cos_pitch, m00 / cos_pitch)


def _float32(value: float) -> float:
    """A ``float32`` message field as C++ promotes it to ``double`` for printf."""
    return float(np.float32(value))


def pgm_bytes(grid: Any, threshold_occupied: int, threshold_free: int) -> bytes:
    """The ``NAME.pgm`` map_saver writes for an ``OccupancyGrid``.

    Raises:
        MapFileError: The grid's data does not hold ``width * height`` cells.
    """
    width, height = int(grid.info.width), int(grid.info.height)
    data = np.asarray(grid.data, dtype=np.int8).reshape(-1)
    if data.size != width * height:
        raise MapFileError(
            f"the map holds {data.size} cells, not width x height = {width} x {height}"
        )
    pixels = cells_to_pixels(data.reshape(height, width), threshold_occupied, threshold_free)
    header = (
        f"P5\n# CREATOR: map_saver.cpp {c_fixed(_float32(grid.info.resolution), 3)} m/pix\n"
        f"{width} {height}\n255\n"
    )
    return header.encode("ascii") + np.ascontiguousarray(pixels).tobytes()


def yaml_text(image: str, grid: Any) -> str:
    """The ``NAME.yaml`` map_saver writes for an ``OccupancyGrid`` whose image is ``image``."""
    origin = grid.info.origin
    q = origin.orientation
    yaw = yaw_from_quaternion(q.x, q.y, q.z, q.w)
    x, y = float(origin.position.x), float(origin.position.y)
    return (
        f"image: {image}\nresolution: {c_fixed(_float32(grid.info.resolution))}\n"
        f"origin: [{c_fixed(x)}, {c_fixed(y)}, {c_fixed(yaw)}]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
    )


def _write(path: str, content: bytes) -> None:
    try:
        with open(path, "wb") as stream:
            stream.write(content)
    except OSError as error:
        raise MapFileError(f"Couldn't save map file to {path}", hint=error.strerror) from None


def save_map_files(
    grid: Any,
    mapname: str = "map",
    threshold_occupied: int = DEFAULT_OCCUPIED,
    threshold_free: int = DEFAULT_FREE,
    log: Callable[[str], None] | None = None,
) -> tuple[Path, Path]:
    """Write ``mapname.pgm`` and ``mapname.yaml`` for an ``OccupancyGrid`` as map_saver does.

    Args:
        grid: The ``nav_msgs/OccupancyGrid``.
        mapname: The files' name without extension, relative to the working directory.
        threshold_occupied: Cells at least this are written occupied (0).
        threshold_free: Cells from 0 to this are written free (254).
        log: Called with map_saver's log lines.

    Returns:
        The paths of the PGM and the YAML.

    Raises:
        MapFileError: A file cannot be written, or the grid is malformed.
        MappingError: The thresholds are out of range.
    """
    check_thresholds(threshold_occupied, threshold_free)
    say = log if log is not None else (lambda text: None)
    info = grid.info
    say(
        f"Received a {int(info.width)} X {int(info.height)} map @ "
        f"{c_fixed(_float32(info.resolution), 3)} m/pix"
    )
    pgm, yaml_path = mapname + ".pgm", mapname + ".yaml"
    say(f"Writing map occupancy data to {pgm}")
    _write(pgm, pgm_bytes(grid, threshold_occupied, threshold_free))
    say(f"Writing map occupancy data to {yaml_path}")
    _write(yaml_path, yaml_text(pgm, grid).encode())
    say("Done\n")
    return Path(pgm), Path(yaml_path)


class MapSaver:
    """Save the first map published on ``map`` (``MapGenerator``).

    Args:
        node: The ``workbench.bus.Node`` (remap ``map`` to save another topic).
        mapname: ``-f``: the files' name without extension.
        threshold_occupied: ``--occ``.
        threshold_free: ``--free``.

    Attributes:
        saved: Set once a map arrived (saved, or failed with :attr:`error`).
        files: The PGM and YAML written.
        error: Why the map could not be saved.
    """

    def __init__(
        self,
        node: Any,
        mapname: str = "map",
        threshold_occupied: int = DEFAULT_OCCUPIED,
        threshold_free: int = DEFAULT_FREE,
    ) -> None:
        from workbench.msgs.nav_msgs import OccupancyGrid

        check_thresholds(threshold_occupied, threshold_free)
        self.node = node
        self.mapname = mapname
        self.thresholds = (threshold_occupied, threshold_free)
        self.saved = threading.Event()
        self.files: tuple[Path, Path] | None = None
        self.error: MappingError | None = None
        self._lock = threading.Lock()
        self.log = node.get_logger()
        self.log.info("Waiting for the map")
        self.subscription = node.create_subscription("map", OccupancyGrid, self._on_map, 1)

    def _on_map(self, grid: Any) -> None:
        with self._lock:
            if self.saved.is_set():
                return
            q = grid.info.origin.orientation
            if q.x == q.y == q.z == q.w == 0.0:
                self.log.warn(
                    "the map's origin orientation is the zero quaternion: the YAML's yaw "
                    "is nan, as ROS writes it, and map_server cannot load it"
                )
            try:
                self.files = save_map_files(
                    grid, self.mapname, *self.thresholds, log=lambda text: self.log.info(text)
                )
            except MappingError as error:
                self.error = error
            self.saved.set()

    def wait(self, timeout: float | None = None) -> bool:
        """Run the node's callbacks until a map was handled (or ``timeout`` seconds).

        Returns:
            Whether a map arrived.
        """
        return bool(self.node.bus.spin_until(self.saved.is_set, timeout))


def main(argv: Sequence[str] = ()) -> int:
    """``map_server/map_saver``: wait for one map, save it, exit."""
    from workbench.bus import Node
    from workbench.bus.names import myargv

    options = parse_arguments(myargv(list(argv)))
    if options.show_help:
        print(USAGE)
        return 0
    node = Node("map_saver", argv=list(argv))
    try:
        saver = MapSaver(node, options.mapname, options.threshold_occupied, options.threshold_free)
        saver.wait()
        if saver.error is not None:
            raise saver.error
    finally:
        node.shutdown()
    return 0


__all__ = [
    "MapSaver",
    "SaverOptions",
    "main",
    "parse_arguments",
    "pgm_bytes",
    "save_map_files",
    "yaml_text",
    "yaw_from_quaternion",
]
