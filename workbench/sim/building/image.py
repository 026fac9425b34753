"""Import a floor plan from an image, as the building editor's "Import": dark pixels become walls.

The image is a map_server map (its YAML gives resolution, origin and
thresholds) or a picture (PGM, PNG, ...) of ``resolution`` m per pixel whose
lower-left corner goes to ``origin``. A pixel is a wall when its occupancy,
``(255 - grey) / 255`` as map_server reads it, is above ``threshold``; unknown
grey (205) is free. The wall pixels are covered exactly by axis-aligned
rectangles (:mod:`workbench.sim.building.rectangles`), each a wall along its
longer side, as thick as its shorter side.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from workbench.sim.building.limits import MAX_PLAN_NUMBER
from workbench.sim.building.plan import (
    DEFAULT_HEIGHT,
    WALL_COLOUR,
    BuildingPlan,
    Level,
    PlanError,
    Wall,
)
from workbench.sim.building.rectangles import rectangles

#: A floor plan is lines on a background: more wall than this is not one.
MAX_WALL_FRACTION = 0.5
#: More wall boxes than this would make a simulation crawl.
MAX_WALLS = 20000


def plan_from_image(
    path: str | os.PathLike[str],
    resolution: float | None = None,
    *,
    height: float = DEFAULT_HEIGHT,
    threshold: float | None = None,
    negate: bool | None = None,
    origin: tuple[float, float] | None = None,
    min_pixels: int = 1,
    name: str | None = None,
) -> BuildingPlan:
    """The walls drawn in a floor-plan image (or a map_server map YAML).

    Args:
        path: A map YAML, or an image (PGM, PNG, JPEG, ...).
        resolution: Metres per pixel (default for a map YAML: its own; needed otherwise).
        height: Wall height, m.
        threshold: Occupancy above which a pixel is a wall (default: the map's
            ``occupied_thresh``, else 0.65).
        negate: Light walls on a dark background (default: the map's ``negate``).
        origin: Where the image's lower-left corner goes, m (default: the map's, else (0, 0)).
        min_pixels: Drop specks of fewer wall pixels than this (8-connected).
        name: The building's name (default: the file's name).

    Raises:
        PlanError: The file cannot be read, a bad option, or an image that is not a
            floor plan (no walls, or mostly walls); one line naming the file.
    """
    from workbench.mapping.errors import MapFileError

    file = Path(path)
    yaw = 0.0
    try:
        if file.suffix.lower() in (".yaml", ".yml"):
            from workbench.mapping.mapfile import read_map_metadata

            meta = read_map_metadata(file)
            image = meta.image
            resolution = meta.resolution if resolution is None else resolution
            threshold = meta.occupied_thresh if threshold is None else threshold
            negate = meta.negate if negate is None else negate
            if origin is None:
                origin, yaw = (meta.origin[0], meta.origin[1]), meta.origin[2]
        else:
            image = file
        from workbench.mapping.pgm import read_image

        pixels, has_alpha = read_image(image)
    except MapFileError as error:
        raise PlanError(error.message, path=error.path, line=error.line, hint=error.hint) from None
    if resolution is None:
        raise PlanError(
            "the image's scale is unknown",
            path=file,
            hint="give its resolution in m/pixel with --resolution, e.g. 0.05",
        )
    _check_option(file, "resolution", resolution, "m per pixel")
    _check_option(file, "height", height, "m")
    threshold = 0.65 if threshold is None else threshold
    if not 0 <= threshold < 1:
        raise PlanError(f"threshold must be in [0, 1), got {threshold:g}", path=file)
    walls_mask = wall_pixels(pixels, has_alpha, threshold=threshold, negate=bool(negate))
    _check_floor_plan(walls_mask, image)
    if min_pixels > 1:
        walls_mask = _despeckle(walls_mask, min_pixels)
        if not walls_mask.any():
            raise PlanError(
                f"no walls left after dropping specks under {min_pixels} pixels",
                path=image,
                hint="lower --min-pixels",
            )
    boxes = rectangles(walls_mask)
    if len(boxes) > MAX_WALLS:
        raise PlanError(
            f"the image gives {len(boxes)} wall boxes, too many to simulate",
            path=image,
            hint="drop specks with --min-pixels, or use a cleaner or coarser image",
        )
    ox, oy = origin if origin is not None else (0.0, 0.0)
    if not all(math.isfinite(v) and abs(v) <= MAX_PLAN_NUMBER for v in (ox, oy)):
        raise PlanError(
            f"the origin must be within {MAX_PLAN_NUMBER:,.0f} m, got ({ox:g}, {oy:g})",
            path=file,
        )
    rows = walls_mask.shape[0]
    level = Level(name="ground")
    for index, (r0, r1, c0, c1) in enumerate(boxes):
        x0, x1 = ox + c0 * resolution, ox + c1 * resolution
        y0, y1 = oy + (rows - r1) * resolution, oy + (rows - r0) * resolution
        if x1 - x0 >= y1 - y0:
            ends = ((x0, (y0 + y1) / 2), (x1, (y0 + y1) / 2))
            thickness = y1 - y0
        else:
            ends = (((x0 + x1) / 2, y0), ((x0 + x1) / 2, y1))
            thickness = x1 - x0
        start, end = (_rotate(p, (ox, oy), yaw) for p in ends)
        level.walls.append(
            Wall(
                name=f"wall_{index}",
                start=start,
                end=end,
                thickness=thickness,
                height=height,
                colour=WALL_COLOUR,
                square_ends=False,
            )
        )
    plan = BuildingPlan(name=name or file.stem, levels=[level], source=str(file), traced=True)
    plan.validate()
    return plan


def wall_pixels(
    pixels: np.ndarray, has_alpha: bool, *, threshold: float = 0.65, negate: bool = False
) -> np.ndarray:
    """Which pixels of ``(height, width, channels)`` uint8 ``pixels`` are wall (rows top-down)."""
    channels = pixels.shape[2]
    colour_channels = channels - 1 if has_alpha else channels
    grey = pixels[:, :, :colour_channels].astype(float).mean(axis=2)
    if negate:
        grey = 255.0 - grey
    walls = (255.0 - grey) / 255.0 > threshold
    if has_alpha:
        walls &= pixels[:, :, -1] > 0
    return np.asarray(walls, dtype=bool)


def _check_floor_plan(walls: np.ndarray, image: Path) -> None:
    fraction = float(walls.mean())
    if fraction == 0.0:
        raise PlanError(
            "no walls: no pixel is dark enough to be a wall, so this is not a floor plan",
            path=image,
            hint="a floor plan has dark walls on a light background; try --threshold or --negate",
        )
    if fraction > MAX_WALL_FRACTION:
        everything = "every pixel is" if fraction == 1.0 else f"{fraction:.0%} of the pixels are"
        raise PlanError(
            f"{everything} wall, so this is not a floor plan",
            path=image,
            hint="a floor plan has dark walls on a light background; try --negate or --threshold",
        )


def _despeckle(walls: np.ndarray, min_pixels: int) -> np.ndarray:
    from scipy import ndimage

    labels, count = ndimage.label(walls, structure=np.ones((3, 3), dtype=bool))
    sizes = np.bincount(labels.ravel(), minlength=count + 1)
    keep = sizes >= min_pixels
    keep[0] = False
    return np.asarray(keep[labels], dtype=bool)


def _check_option(file: Path, what: str, value: float, unit: str) -> None:
    if not (math.isfinite(value) and 0 < value <= MAX_PLAN_NUMBER):
        raise PlanError(
            f"{what} must be a positive number ({unit}) of at most {MAX_PLAN_NUMBER:,.0f}, "
            f"got {value:g}",
            path=file,
        )


def _rotate(
    point: tuple[float, float], centre: tuple[float, float], yaw: float
) -> tuple[float, float]:
    if yaw == 0.0:
        return point
    dx, dy = point[0] - centre[0], point[1] - centre[1]
    c, s = math.cos(yaw), math.sin(yaw)
    return (centre[0] + c * dx - s * dy, centre[1] + s * dx + c * dy)
