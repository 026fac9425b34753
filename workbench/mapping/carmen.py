"""CARMEN laser logs (``FLASER``, ``RLASER``, ``ROBOTLASER1``, ``ODOM``), plain or gzip.

Formats (one message per line, fields separated by blanks)::

    FLASER n r1 .. rn x y theta odom_x odom_y odom_theta ipc_timestamp host logger_timestamp
    RLASER (as FLASER, for the rear laser)
    ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode
                n r1 .. rn m v1 .. vm laser_x laser_y laser_theta robot_x robot_y robot_theta
                tv rv forward_safety side_safety turn_axis ipc_timestamp host logger_timestamp
    ODOM x y theta tv rv accel ipc_timestamp host logger_timestamp

For ``FLASER``/``RLASER`` the beams span 180 degrees (-90 .. +90) unless the
count is 360/361 (also 180 degrees, half-degree steps), as CARMEN's log
reader assumes; the rear laser looks backwards. ``x y theta`` is the
(possibly corrected) laser pose and ``odom_*`` the odometry; the
``robot_*laser_offset`` PARAMs shift the laser forward of the robot.
Lines that cannot be parsed are reported with their line number and skipped.
"""

from __future__ import annotations

import gzip
import math
import zlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from workbench.limits import check_regular_file
from workbench.mapping.errors import LogError
from workbench.mapping.geometry import compose
from workbench.mapping.scan import LaserLog, Scan, scan_problem

#: SICK LMS readings at or beyond this mean "no return" in CARMEN logs (m).
CARMEN_MAX_RANGE = 81.0
LASER_TAGS = ("FLASER", "RLASER", "ROBOTLASER1")
#: Most bytes a log may hold once decompressed (a gzip bomb stops here).
MAX_LOG_BYTES = 512 * 2**20
#: Most lines a log may hold (2 GiB of newlines would take minutes to count).
MAX_LOG_LINES = 5_000_000
#: Longest line read; a longer one is skipped with a warning.
MAX_LINE_BYTES = 2**20


class _BadLine(ValueError):
    pass


def _floats(fields: list[str]) -> np.ndarray:
    try:
        values = np.array([float(v) for v in fields])
    except ValueError as exc:
        raise _BadLine(f"non-numeric field ({exc})") from None
    return values


def _old_laser(fields: list[str], rear: bool, offset: float) -> Scan:
    if len(fields) < 2:
        raise _BadLine("no beam count")
    try:
        n = int(fields[1])
    except ValueError:
        raise _BadLine(f"beam count {fields[1]!r} is not an integer") from None
    if n <= 0:
        raise _BadLine(f"beam count {n} is not positive")
    if len(fields) < 2 + n + 7:
        raise _BadLine(
            f"expected {n} ranges and 6 pose fields and a time, got {len(fields)} fields"
        )
    values = _floats(fields[2 : 2 + n + 6])
    stamp = _floats([fields[2 + n + 6]])[0]
    ranges = values[:n]
    pose, odom = values[n : n + 3], values[n + 3 : n + 6]
    if not (np.all(np.isfinite(pose)) and np.all(np.isfinite(odom)) and math.isfinite(stamp)):
        raise _BadLine("pose, odometry or time is not finite")
    fov = math.pi
    step = fov / (n - 1) if n in (181, 361) else fov / n
    angles = -0.5 * fov + step * np.arange(n)
    mount = np.array([offset, 0.0, 0.0])
    if rear:
        angles = angles + math.pi
        mount = np.array([-offset, 0.0, 0.0])
    return Scan(
        stamp=float(stamp),
        ranges=ranges,
        angles=angles,
        odom=compose(odom, mount),
        max_range=CARMEN_MAX_RANGE,
        reference=pose.copy(),
    )


def _robotlaser(fields: list[str]) -> Scan:
    try:
        start, _fov, step, max_range = (float(v) for v in fields[2:6])
        n = int(fields[8])
        m = int(fields[9 + n])
    except (ValueError, IndexError):
        raise _BadLine("bad ROBOTLASER1 header") from None
    tail = 10 + n + m
    if n <= 0 or len(fields) < tail + 12:
        raise _BadLine(f"ROBOTLASER1 with {n} ranges has only {len(fields)} fields")
    ranges = _floats(fields[9 : 9 + n])
    laser = _floats(fields[tail : tail + 3])
    stamp = _floats([fields[tail + 11]])[0]
    if not (np.all(np.isfinite(laser)) and math.isfinite(stamp)):
        raise _BadLine("pose or time is not finite")
    if not (math.isfinite(max_range) and max_range > 0):
        max_range = CARMEN_MAX_RANGE
    return Scan(
        stamp=float(stamp),
        ranges=ranges,
        angles=start + step * np.arange(n),
        odom=laser.copy(),
        max_range=max_range,
        reference=laser.copy(),
    )


def _lines(path: Path, warnings: list[str]) -> Iterator[tuple[int, str]]:
    """The log's lines, numbered, within :data:`MAX_LOG_BYTES`, :data:`MAX_LOG_LINES` and
    :data:`MAX_LINE_BYTES` (a longer line is skipped with a warning)."""
    check_regular_file(path, "log", LogError)
    try:
        with open(path, "rb") as probe:
            magic = probe.read(2)
    except OSError as exc:
        raise LogError(f"cannot read log: {exc.strerror}", path=path) from None
    number = total = 0
    try:
        with (gzip.open if magic == b"\x1f\x8b" else open)(path, "rb") as stream:
            while True:
                raw = stream.readline(MAX_LINE_BYTES + 1)
                if not raw:
                    return
                number += 1
                total += len(raw)
                if total > MAX_LOG_BYTES or number > MAX_LOG_LINES:
                    raise LogError(
                        f"the log is longer than {MAX_LOG_BYTES // 2**20} MiB or "
                        f"{MAX_LOG_LINES:,} lines once decompressed",
                        path=path,
                        hint="is it a gzip bomb? split a real log into parts",
                    )
                if len(raw) > MAX_LINE_BYTES and not raw.endswith(b"\n"):
                    warnings.append(f"{path}:{number}: skipped a line longer than 1 MiB")
                    total += _skip_line(stream)
                    continue
                yield number, raw.decode("utf-8", errors="replace")
    except (EOFError, zlib.error, gzip.BadGzipFile) as exc:
        if number == 0:
            raise LogError(f"corrupt gzip data ({exc})", path=path) from None
        warnings.append(f"{path}:{number + 1}: log is truncated or corrupt after this line ({exc})")
    except OSError as exc:
        raise LogError(f"cannot read log: {exc.strerror or exc}", path=path) from None


def _skip_line(stream: Any) -> int:
    """Read to the end of the current line in bounded pieces; the bytes skipped."""
    skipped = 0
    while True:
        piece = stream.readline(MAX_LINE_BYTES)
        skipped += len(piece)
        if not piece or piece.endswith(b"\n") or skipped > MAX_LOG_BYTES:
            return skipped


def read_carmen(path: str | Path) -> LaserLog:
    """Read a CARMEN log (plain text or gzip, detected from the content).

    Returns:
        The scans (from ``FLASER``, ``RLASER`` and ``ROBOTLASER1`` lines) and
        one warning per skipped line.

    Raises:
        LogError: when the file is missing, not readable, or holds no laser line.
    """
    path = Path(path)
    warnings: list[str] = []
    scans: list[Scan] = []
    offsets = {"FLASER": 0.0, "RLASER": 0.0}
    for number, line in _lines(path, warnings):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        tag = fields[0]
        try:
            if tag == "PARAM" and len(fields) >= 3:
                laser = {"robot_frontlaser_offset": "FLASER", "robot_rearlaser_offset": "RLASER"}
                if fields[1] in laser:
                    offset = float(fields[2])
                    if not math.isfinite(offset):
                        raise _BadLine(f"offset {fields[2]} is not finite")
                    offsets[laser[fields[1]]] = offset
                continue
            if tag in ("FLASER", "RLASER"):
                scan = _old_laser(fields, tag == "RLASER", offsets[tag])
            elif tag == "ROBOTLASER1":
                scan = _robotlaser(fields)
            else:
                continue
        except (_BadLine, ValueError) as exc:
            warnings.append(f"{path}:{number}: skipped {tag} line: {exc}")
            continue
        problem = scan_problem(scan)
        if problem is not None:
            warnings.append(f"{path}:{number}: skipped {tag} line: {problem}")
            continue
        scan.source = f"{path}:{number}"
        scans.append(scan)
    if not scans:
        raise LogError(
            "no laser lines (FLASER, RLASER or ROBOTLASER1) in the log",
            path=path,
            hint="is this a CARMEN log?",
        )
    return LaserLog(path, scans, warnings)


def write_carmen(path: str | Path, scans: list[Scan], *, compress: bool | None = None) -> Path:
    """Write scans as CARMEN ``FLASER`` lines (plus an ``ODOM`` line per scan).

    Each scan must have 180, 181, 360 or 361 beams spread over 180 degrees
    (the layouts ``FLASER`` can express). ``x y theta`` is the scan's
    reference pose when it has one, else its odometry. ``compress`` None
    gzips when the name ends in ``.gz``.

    Raises:
        LogError: when a scan's layout does not fit or the file cannot be written.
    """
    path = Path(path)
    if compress is None:
        compress = path.suffix == ".gz"
    lines = ["# written by workbench.mapping.write_carmen\n"]
    for index, scan in enumerate(scans):
        n = len(scan.ranges)
        if n not in (180, 181, 360, 361):
            raise LogError(f"scan {index} has {n} beams; FLASER needs 180, 181, 360 or 361")
        ranges = np.where(np.isfinite(scan.ranges), scan.ranges, CARMEN_MAX_RANGE + 0.5)
        pose = scan.reference if scan.reference is not None else scan.odom
        o = scan.odom
        t = f"{scan.stamp:.6f}"
        lines.append(f"ODOM {o[0]:.6f} {o[1]:.6f} {o[2]:.6f} 0 0 0 {t} workbench {t}\n")
        lines.append(
            f"FLASER {n} "
            + " ".join(f"{r:.4f}" for r in ranges)
            + f" {pose[0]:.6f} {pose[1]:.6f} {pose[2]:.6f}"
            + f" {o[0]:.6f} {o[1]:.6f} {o[2]:.6f} {t} workbench {t}\n"
        )
    text = "".join(lines).encode()
    try:
        if compress:
            with gzip.open(path, "wb") as stream:
                stream.write(text)
        else:
            path.write_bytes(text)
    except OSError as exc:
        raise LogError(f"cannot write log: {exc.strerror}", path=path) from None
    return path
