"""``workbench map show MAP.yaml``: describe a map_server map and draw it."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any


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
    from workbench.mapping import load_map, read_map_metadata
    from workbench.mapping.errors import MapFileError
    from workbench.mapping.render import save_png

    rows = read_trajectory_csv(trajectory) if trajectory else None
    if png:
        from workbench.output_files import check_output

        check_output(png, "png", option="--png", error=MapFileError)
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
        if rows is not None:
            trajectories.append((rows[:, 1:3], (220, 30, 30)))
        scale = 2 if max(grid.width, grid.height) < 1000 else 1
        path = save_png(grid, Path(png), trajectories, scale=scale)
        print(f"wrote {path}")
    return 0


#: Largest trajectory CSV ``map show`` reads, bytes, and most rows drawn.
MAX_TRAJECTORY_BYTES = 64 * 1024 * 1024
MAX_TRAJECTORY_ROWS = 1_000_000


def read_trajectory_csv(path: str) -> Any:
    """The rows ``t, x, y[, theta]`` of a trajectory CSV (a header line, then numbers).

    A file that is not one (``/etc/passwd``, a binary) is refused by its line number only:
    the message never quotes what the file holds.

    Returns:
        A float array of shape (rows, 3 or more).

    Raises:
        MapFileError: Not a regular file, too large, or not a trajectory CSV.
    """
    import numpy as np

    from workbench.limits import read_bytes_bounded
    from workbench.mapping.errors import MapFileError

    data = read_bytes_bounded(path, "trajectory CSV", MAX_TRAJECTORY_BYTES, MapFileError)
    lines = data.splitlines()[1:]  # the header: t,x,y,theta
    rows: list[list[float]] = []
    width = None
    for number, raw in enumerate(lines, start=2):
        if not raw.strip():
            continue
        try:
            values = [float(field) for field in raw.split(b",")]
        except ValueError:
            values = []
        if len(values) < 3 or (width is not None and len(values) != width):
            raise MapFileError(
                f"is not a trajectory CSV (line {number}: expected t, x, y[, theta]: "
                f"{width or '3 or more'} numbers separated by commas)",
                path=path,
            )
        if not all(np.isfinite(values)):
            raise MapFileError(
                f"trajectory CSV line {number} holds a number that is not finite", path=path
            )
        width = len(values)
        rows.append(values)
        if len(rows) > MAX_TRAJECTORY_ROWS:
            raise MapFileError(
                f"trajectory CSV has more than {MAX_TRAJECTORY_ROWS:,} rows", path=path
            )
    if not rows:
        raise MapFileError("is not a trajectory CSV (no rows of t, x, y[, theta])", path=path)
    return np.asarray(rows, dtype=float)
