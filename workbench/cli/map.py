"""``workbench map show MAP.yaml``: describe a map_server map and draw it."""

from __future__ import annotations

import argparse
from pathlib import Path


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the ``show`` verb."""
    parser.description = "Show and convert saved maps (map_server YAML + image)."
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    show = verbs.add_parser("show", help="print a map's size, origin and cell counts; draw it")
    show.add_argument("map", help="the map YAML (as written by map_saver or workbench slam)")
    show.add_argument("--png", help="write a picture of the map here")
    show.add_argument("--trajectory", help="a CSV (t, x, y, theta) to draw on the picture")


def run(args: argparse.Namespace) -> int:
    """Run the chosen verb; returns the exit status."""
    return show(args.map, png=args.png, trajectory=args.trajectory)


def show(map_yaml: str, *, png: str | None = None, trajectory: str | None = None) -> int:
    """Print a map's size, origin, thresholds and cell counts; draw it into ``png``.

    Args:
        map_yaml: The map's YAML (map_server format).
        png: Write a picture of the map here.
        trajectory: A CSV (``t, x, y[, theta]``; m, rad) drawn on the picture.

    Raises:
        MapFileError: The map or the trajectory cannot be read.
    """
    import numpy as np

    from workbench.mapping import load_map, read_map_metadata
    from workbench.mapping.errors import MapFileError
    from workbench.mapping.render import save_png

    meta = read_map_metadata(map_yaml)
    grid = load_map(map_yaml)
    data = grid.data
    free = int(((data >= 0) & (data <= 25)).sum())
    occupied = int((data >= 65).sum())
    unknown = int(data.size - free - occupied)
    print(f"map: {meta.yaml_path}")
    print(f"image: {meta.image} ({meta.mode}{', negated' if meta.negate else ''})")
    print(
        f"size: {grid.width} x {grid.height} cells = {grid.width * grid.resolution:.2f} x "
        f"{grid.height * grid.resolution:.2f} m at {grid.resolution:.3f} m/cell"
    )
    print(f"origin: [{grid.origin[0]:.3f}, {grid.origin[1]:.3f}, {grid.origin[2]:.3f}]")
    print(f"thresholds: occupied > {meta.occupied_thresh}, free < {meta.free_thresh}")
    print(f"cells: {free} free, {occupied} occupied, {unknown} unknown")
    if png:
        trajectories = []
        if trajectory:
            try:
                rows = np.loadtxt(trajectory, delimiter=",", skiprows=1, ndmin=2)
            except (OSError, ValueError) as exc:
                raise MapFileError(f"cannot read trajectory CSV: {exc}", path=trajectory) from None
            if rows.shape[1] < 3:
                raise MapFileError("trajectory CSV needs columns t, x, y[, theta]", path=trajectory)
            trajectories.append((rows[:, 1:3], (220, 30, 30)))
        scale = 2 if max(grid.width, grid.height) < 1000 else 1
        path = save_png(grid, Path(png), trajectories, scale=scale)
        print(f"wrote {path}")
    return 0
