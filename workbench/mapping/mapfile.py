"""map_server maps on disk: ``NAME.yaml`` + ``NAME.pgm``, saved as ``map_saver`` and loaded as ``map_server``.

Saving follows ``map_saver`` (ros-planning/navigation, noetic): a binary P5
PGM with rows top-down, cells ``0..25`` written 254 (free), ``65`` and above
written 0 (occupied), everything else (unknown ``-1`` and ``26..64``) 205,
and a YAML with ``image, resolution, origin, negate: 0,
occupied_thresh: 0.65, free_thresh: 0.196``.

Loading follows ``map_server``'s image loader: the mean of the colour
channels ``c`` (inverted when ``negate``), ``occ = (255 - c) / 255``;
``occ > occupied_thresh`` is 100, ``occ < free_thresh`` is 0, anything
between is -1 (``trinary``, the default), or ``1 + 98 * (occ - free) / (occ_th -
free)`` truncated (``scale``, map_server 1.17.1 and later, where a fully
transparent pixel stays -1); ``raw`` copies ``c`` into the cell. Image row 0
becomes the top map row.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workbench.limits import load_yaml_file
from workbench.mapping.errors import MapFileError
from workbench.mapping.grid import GridMap
from workbench.mapping.pgm import read_image, write_pgm

#: map_saver's default thresholds on cell values (percent).
SAVER_FREE_MAX = 25
SAVER_OCCUPIED_MIN = 65
#: The thresholds map_saver writes into every YAML.
OCCUPIED_THRESH = 0.65
FREE_THRESH = 0.196
#: Pixel values map_saver writes.
PIXEL_FREE, PIXEL_OCCUPIED, PIXEL_UNKNOWN = 254, 0, 205

MODES = ("trinary", "scale", "raw")


@dataclass
class MapMetadata:
    """The contents of a map YAML (paths resolved).

    Attributes:
        yaml_path: The YAML file.
        image: The image file, resolved relative to the YAML's directory.
        resolution: Metres per cell.
        origin: ``(x, y, yaw)`` of the lower-left pixel's corner (m, rad).
        negate: Whether white means occupied.
        occupied_thresh: Occupancy above this is occupied.
        free_thresh: Occupancy below this is free.
        mode: ``trinary``, ``scale`` or ``raw``.
    """

    yaml_path: Path
    image: Path
    resolution: float
    origin: tuple[float, float, float]
    negate: bool
    occupied_thresh: float
    free_thresh: float
    mode: str = "trinary"


def _map_paths(base: str | Path) -> tuple[Path, Path]:
    base = Path(base)
    if base.suffix in (".yaml", ".yml", ".pgm"):
        base = base.with_suffix("")
    return base.with_name(base.name + ".pgm"), base.with_name(base.name + ".yaml")


def cells_to_pixels(
    cells: np.ndarray, occupied_min: int = SAVER_OCCUPIED_MIN, free_max: int = SAVER_FREE_MAX
) -> np.ndarray:
    """The PGM pixels ``map_saver`` writes for ``(height, width)`` cells (row 0 at the origin).

    As ``map_saver --occ OCCUPIED_MIN --free FREE_MAX``: a cell in ``0..free_max`` is
    254, else one ``>= occupied_min`` is 0, anything else 205. Rows come out top-down.
    """
    data = np.asarray(cells, dtype=np.int8)
    pixels = np.full(data.shape, PIXEL_UNKNOWN, dtype=np.uint8)
    free = (data >= 0) & (data <= free_max)
    pixels[free] = PIXEL_FREE
    pixels[~free & (data >= occupied_min)] = PIXEL_OCCUPIED
    return pixels[::-1]


def map_to_pixels(grid: GridMap) -> np.ndarray:
    """The PGM pixels ``map_saver`` writes for a grid (rows top-down), default thresholds."""
    return cells_to_pixels(grid.data)


def save_map(grid: GridMap, base: str | Path) -> tuple[Path, Path]:
    """Save like ``rosrun map_server map_saver -f BASE``: ``BASE.pgm`` and ``BASE.yaml``.

    The YAML's ``image`` is the PGM's file name, which map_server resolves
    relative to the YAML, so the pair can be moved together.

    Returns:
        The paths of the PGM and the YAML.

    Raises:
        MapFileError: when a file cannot be written.
    """
    pgm_path, yaml_path = _map_paths(base)
    if not pgm_path.parent.is_dir():
        raise MapFileError(
            "the directory for the map does not exist",
            path=pgm_path.parent,
            hint="create it first or choose another --out",
        )
    write_pgm(pgm_path, map_to_pixels(grid), f"CREATOR: workbench {grid.resolution:.3f} m/pix")
    x, y, yaw = (float(v) for v in grid.origin)
    text = (
        f"image: {pgm_path.name}\nresolution: {grid.resolution:f}\n"
        f"origin: [{x:f}, {y:f}, {yaw:f}]\nnegate: 0\n"
        f"occupied_thresh: {OCCUPIED_THRESH}\nfree_thresh: {FREE_THRESH}\n\n"
    )
    try:
        yaml_path.write_text(text)
    except OSError as exc:
        raise MapFileError(
            f"cannot write map YAML: {exc.strerror}", path=yaml_path, hint="choose a writable --out"
        ) from None
    return pgm_path, yaml_path


def _number(doc: dict, key: str, path: Path) -> float:
    try:
        value = float(doc[key])
    except KeyError:
        raise MapFileError(
            f"map YAML has no '{key}' key", path=path, hint="map_server needs it"
        ) from None
    except (TypeError, ValueError):
        raise MapFileError(f"'{key}' is not a number: {doc[key]!r}", path=path) from None
    if not math.isfinite(value):
        raise MapFileError(f"'{key}' is not finite: {doc[key]!r}", path=path)
    return value


def read_map_metadata(path: str | Path) -> MapMetadata:
    """Read and check a map YAML the way map_server does (every key but ``mode`` is required).

    Raises:
        MapFileError: for a missing file, bad YAML, or a missing or invalid key.
    """
    path = Path(path)
    if not path.exists():
        raise MapFileError("map YAML not found", path=path)
    doc = load_yaml_file(path, "map YAML", MapFileError)
    if not isinstance(doc, dict):
        raise MapFileError("map YAML is not a mapping of keys to values", path=path)
    resolution = _number(doc, "resolution", path)
    if resolution <= 0:
        raise MapFileError(f"'resolution' must be positive, got {resolution}", path=path)
    negate = _number(doc, "negate", path)
    occupied = _number(doc, "occupied_thresh", path)
    free = _number(doc, "free_thresh", path)
    if "origin" not in doc:
        raise MapFileError("map YAML has no 'origin' key", path=path, hint="map_server needs it")
    origin = doc["origin"]
    try:
        if not isinstance(origin, list | tuple) or len(origin) != 3:
            raise ValueError
        origin_xyz = (float(origin[0]), float(origin[1]), float(origin[2]))
        if not all(math.isfinite(v) for v in origin_xyz):
            raise ValueError
    except (TypeError, ValueError):
        raise MapFileError(
            f"'origin' must be [x, y, yaw] of finite numbers, got {str(origin)[:60]}", path=path
        ) from None
    mode = str(doc.get("mode", "trinary"))
    if mode not in MODES:
        raise MapFileError(f"invalid mode {mode!r}", path=path, hint="use trinary, scale or raw")
    image = doc.get("image")
    if image is None:
        raise MapFileError("map YAML has no 'image' key", path=path, hint="map_server needs it")
    if not isinstance(image, str) or not image:
        raise MapFileError("'image' must be a non-empty file name", path=path)
    image_path = Path(image)
    if not image_path.is_absolute():
        image_path = path.parent / image_path
    return MapMetadata(path, image_path, resolution, origin_xyz, bool(negate), occupied, free, mode)


def pixels_to_map(pixels: np.ndarray, has_alpha: bool, meta: MapMetadata) -> np.ndarray:
    """Cell values ``(height, width)`` int8 from image pixels ``(h, w, channels)``, as map_server."""
    channels = pixels.shape[2]
    use = channels if (meta.mode == "trinary" or not has_alpha) else channels - 1
    colour = pixels[:, :, :use].astype(np.int64).sum(axis=2) / float(use)
    alpha = np.ones(colour.shape) if channels == 1 else pixels[:, :, -1].astype(float)
    if meta.negate:
        colour = 255.0 - colour
    if meta.mode == "raw":
        # The cell is a signed char holding the truncated unsigned value.
        return colour.astype(np.uint8).view(np.int8)[::-1].copy()
    occ = (255.0 - colour) / 255.0
    values = np.full(colour.shape, -1, dtype=np.int16)
    if meta.mode == "scale":
        ratio = (occ - meta.free_thresh) / (meta.occupied_thresh - meta.free_thresh)
        scaled = np.trunc(1.0 + 98.0 * ratio).astype(np.int16)
        values = np.where(alpha < 1.0, values, scaled)
    values[occ < meta.free_thresh] = 0
    values[occ > meta.occupied_thresh] = 100
    return values.astype(np.int8)[::-1].copy()


def load_map(path: str | Path) -> GridMap:
    """Load a map YAML and its image like ``rosrun map_server map_server MAP.yaml``.

    Raises:
        MapFileError: for a bad YAML, a missing image, or an image that cannot be read.
    """
    meta = read_map_metadata(path)
    pixels, has_alpha = read_image(meta.image)
    data = pixels_to_map(pixels, has_alpha, meta)
    return GridMap(data, meta.resolution, np.array(meta.origin))
