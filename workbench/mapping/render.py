"""Pictures of maps: the map_saver grey levels with an optional trajectory drawn on top."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workbench.mapping.errors import MapFileError
from workbench.mapping.grid import GridMap
from workbench.mapping.mapfile import map_to_pixels


def map_image(
    grid: GridMap,
    trajectories: list[tuple[np.ndarray, tuple[int, int, int]]] | None = None,
    scale: int = 1,
):
    """An RGB Pillow image of a map (rows top-down), with trajectories as coloured polylines.

    Args:
        grid: The map.
        trajectories: ``(poses (N, >=2) in the map frame, RGB colour)`` pairs.
        scale: Pixels per cell.
    """
    from PIL import Image, ImageDraw

    grey = map_to_pixels(grid)
    image = Image.fromarray(np.repeat(grey[:, :, None], 3, axis=2), "RGB")
    if scale > 1:
        image = image.resize((grid.width * scale, grid.height * scale), Image.NEAREST)
    draw = ImageDraw.Draw(image)
    for poses, colour in trajectories or []:
        poses = np.asarray(poses, dtype=float)
        if len(poses) < 2:
            continue
        c, s = np.cos(grid.origin[2]), np.sin(grid.origin[2])
        dx, dy = poses[:, 0] - grid.origin[0], poses[:, 1] - grid.origin[1]
        u = (c * dx + s * dy) / grid.resolution * scale
        v = (grid.height - (-s * dx + c * dy) / grid.resolution) * scale
        draw.line(list(zip(u.tolist(), v.tolist(), strict=True)), fill=colour, width=max(scale, 1))
    return image


def save_png(
    grid: GridMap,
    path: str | Path,
    trajectories: list[tuple[np.ndarray, tuple[int, int, int]]] | None = None,
    scale: int = 1,
) -> Path:
    """Write :func:`map_image` to a PNG file.

    Raises:
        MapFileError: when the file cannot be written.
    """
    path = Path(path)
    image = map_image(grid, trajectories, scale)
    try:
        image.save(path, format="PNG")
    except OSError as exc:
        raise MapFileError(
            f"cannot write PNG: {exc}", path=path, hint="choose a writable path"
        ) from None
    return path
