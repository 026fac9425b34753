"""``workbench slam LOG``: build an occupancy map from a laser log (like gmapping + map_saver)."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from workbench.errors import MappingError

#: Largest --resolution (cell size) and --max-range, m.
MAX_RESOLUTION = 10.0
MAX_RANGE = 1000.0


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the command's arguments."""
    parser.description = (
        "Run graph SLAM on a CARMEN log (plain or .gz) or a ROS 1 bag with LaserScan and "
        "odometry, and save the map as map_saver does (NAME.pgm + NAME.yaml), a picture "
        "with the trajectory (NAME.png) and the trajectory (NAME.csv: t, x, y, theta)."
    )
    parser.add_argument("log", help="CARMEN log or ROS 1 bag")
    parser.add_argument(
        "--out", default="map", help="output DIR/NAME without extension (default: ./map)"
    )
    parser.add_argument(
        "--resolution", type=float, default=0.05, help="map cell size in metres (default 0.05)"
    )
    parser.add_argument("--png", help="where to write the picture (default: NAME.png)")
    parser.add_argument("--scan-topic", help="LaserScan topic of a bag (default: the only one)")
    parser.add_argument(
        "--odom-topic", help="Odometry topic of a bag (default: the only one, or /tf)"
    )
    parser.add_argument(
        "--max-range", type=float, default=30.0, help="readings beyond this are not mapped (m)"
    )
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


class ProgressBar:
    """A one-line progress bar on stderr, redrawn at most ten times a second."""

    def __init__(self, total: int, label: str, enabled: bool = True) -> None:
        self.total = max(total, 1)
        self.label = label
        self.enabled = enabled
        self.start = time.monotonic()
        self.last = 0.0

    def __call__(self, done: int, total: int) -> None:
        now = time.monotonic()
        if not self.enabled or (now - self.last < 0.1 and done < total):
            return
        self.last = now
        width = 30
        filled = int(width * done / self.total)
        bar = "#" * filled + "." * (width - filled)
        sys.stderr.write(
            f"\r{self.label} [{bar}] {100 * done // self.total:3d}% {done}/{total} "
            f"{now - self.start:5.1f} s"
        )
        if done >= total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def run(args: argparse.Namespace) -> int:
    """Read the log, run SLAM, write the map files; returns the exit status."""
    return slam(
        args.log,
        out=args.out,
        resolution=args.resolution,
        png=args.png,
        scan_topic=args.scan_topic,
        odom_topic=args.odom_topic,
        max_range=args.max_range,
        quiet=args.quiet,
    )


def slam(
    log_path: str,
    *,
    out: str = "map",
    resolution: float = 0.05,
    png: str | None = None,
    scan_topic: str | None = None,
    odom_topic: str | None = None,
    max_range: float = 30.0,
    quiet: bool = False,
) -> int:
    """Run graph SLAM on a laser log and save the map as map_saver does.

    Writes ``OUT.pgm`` + ``OUT.yaml`` (map_server format), a picture (``OUT.png``) and
    the trajectory (``OUT.csv``: t, x, y, theta in s, m, rad).

    Args:
        log_path: A CARMEN log (plain or .gz) or a ROS 1 bag with LaserScan and odometry.
        out: Output path without extension.
        resolution: Map cell size, m.
        png: Where to write the picture (default ``OUT.png``).
        scan_topic, odom_topic: The bag's topics (default: the only one; odometry else /tf).
        max_range: Readings beyond this are not mapped, m.
        quiet: No progress bar.

    Raises:
        MappingError: A bad number, a missing input or output folder, an unreadable log.
    """
    import numpy as np

    from workbench.mapping import SlamConfig, build_map, read_log, run_slam, save_map
    from workbench.mapping.render import save_png

    if not (resolution > 0 and np.isfinite(resolution)):
        raise MappingError(f"--resolution must be a positive number of metres, got {resolution}")
    if not (max_range > 0 and np.isfinite(max_range)):
        raise MappingError(f"--max-range must be a positive number of metres, got {max_range}")
    if resolution > MAX_RESOLUTION or max_range > MAX_RANGE:
        raise MappingError(
            f"--resolution must be at most {MAX_RESOLUTION:g} m and --max-range at most "
            f"{MAX_RANGE:g} m, got {resolution:g} and {max_range:g}",
            hint="a lab map has cells of a few centimetres and a laser of tens of metres",
        )
    if not out.strip():
        raise MappingError("--out needs a name for the map (DIR/NAME without extension)")
    target = Path(out)
    if target.suffix in (".yaml", ".pgm", ".png"):
        target = target.with_suffix("")
    if not target.parent.is_dir():
        raise MappingError(
            "the output directory does not exist",
            path=target.parent,
            hint="create it or change --out",
        )
    _check_outputs(target, png)

    started = time.perf_counter()
    cpu_started = time.process_time()
    options = {}
    if scan_topic:
        options["scan_topic"] = scan_topic
    if odom_topic:
        options["odom_topic"] = odom_topic
    log = read_log(log_path, **options)
    for warning in log.warnings[:10]:
        print(f"warning: {warning}", file=sys.stderr)
    if len(log.warnings) > 10:
        print(f"warning: ... and {len(log.warnings) - 10} more skipped lines", file=sys.stderr)
    scans = log.scans
    bar = ProgressBar(len(scans), "slam", enabled=not quiet)
    result = run_slam(scans, SlamConfig(resolution=resolution), progress=bar)
    grid = build_map(scans, result.poses, resolution, max_range).to_map()
    pgm, yaml_path = save_map(grid, target)
    picture = save_png(
        grid,
        Path(png) if png else target.with_name(target.name + ".png"),
        [(result.poses, (220, 30, 30))],
        scale=2 if max(grid.width, grid.height) < 1000 else 1,
    )
    csv = target.with_name(target.name + ".csv")
    rows = np.column_stack([result.stamps, result.poses])
    try:
        np.savetxt(csv, rows, delimiter=",", header="t,x,y,theta", comments="", fmt="%.6f")
    except OSError as exc:
        raise MappingError(f"cannot write trajectory: {exc.strerror}", path=csv) from None
    wall = time.perf_counter() - started
    cpu = time.process_time() - cpu_started
    speed = f", {log.duration / wall:.0f}x real time" if log.duration > 0 else ""
    print(
        f"{len(scans)} scans over {log.duration:.1f} s from {log_path}: "
        f"{len(result.keyframes)} keyframes, {len(result.loop_closures)} loop closures"
    )
    print(
        f"map {grid.width} x {grid.height} cells at {grid.resolution:.3f} m, "
        f"origin ({grid.origin[0]:.3f}, {grid.origin[1]:.3f}, {grid.origin[2]:.3f})"
    )
    print(f"wrote {yaml_path}, {pgm}, {picture}, {csv}")
    print(f"took {wall:.1f} s wall, {cpu:.1f} s CPU{speed}")
    return 0


def _check_outputs(target: Path, png: str | None) -> None:
    """Check, before the SLAM runs, that the map, picture and trajectory can be written.

    Raises:
        MappingError: A name the file system refuses, a pipe, device or directory, or a
            picture or trajectory file workbench did not write.
    """
    import contextlib
    import os

    from workbench.output_files import check_output

    for path in (target.with_name(target.name + ".pgm"), target.with_name(target.name + ".yaml")):
        shown = str(path) if len(str(path)) <= 100 else str(path)[:97] + "..."
        try:
            exists = path.exists()
            if exists and not path.is_file():
                raise MappingError(f"cannot write {shown}: it is not a regular file")
            if not exists:
                os.close(os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
                with contextlib.suppress(OSError):
                    os.unlink(path)
        except OSError as error:
            raise MappingError(f"cannot write {shown}: {error.strerror}") from None
    picture = Path(png) if png else target.with_name(target.name + ".png")
    check_output(picture, "png", error=MappingError)
    check_output(target.with_name(target.name + ".csv"), "trajectory-csv", error=MappingError)
