"""Timestamped laser scans with the odometry they were taken at."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: Most beams one scan may have (a 0.1 degree lidar has 3600).
MAX_BEAMS = 100_000


@dataclass
class Scan:
    """One planar laser scan.

    Attributes:
        stamp: Time (s).
        ranges: Beam lengths (m); NaN, inf, ``<= min_range`` and ``>= max_range`` mean no return.
        angles: Beam directions in the sensor frame (rad), counter-clockwise, 0 straight ahead.
        odom: Odometric pose ``(x, y, theta)`` of the **sensor** in the odometry frame (m, rad).
        max_range: Readings at or beyond this are "no return" (m).
        min_range: Readings at or below this are invalid (m).
        reference: A reference pose of the sensor in the map frame when the log has one
            (CARMEN's corrected ``x y theta``), else None.
        source: Where the scan came from (``file:line`` or ``bag:topic``), for messages.
    """

    stamp: float
    ranges: np.ndarray
    angles: np.ndarray
    odom: np.ndarray
    max_range: float = np.inf
    min_range: float = 0.0
    reference: np.ndarray | None = None
    source: str = ""

    def valid(self) -> np.ndarray:
        """Boolean mask of readings that are real returns."""
        with np.errstate(invalid="ignore"):
            return (
                np.isfinite(self.ranges)
                & (self.ranges > self.min_range)
                & (self.ranges < self.max_range)
            )

    def points(self, max_range: float = np.inf) -> np.ndarray:
        """The valid returns as points ``(N, 2)`` in the sensor frame, up to ``max_range``."""
        ok = self.valid()
        with np.errstate(invalid="ignore"):
            ok &= self.ranges <= max_range
        r = self.ranges[ok]
        a = self.angles[ok]
        return np.stack([r * np.cos(a), r * np.sin(a)], axis=1)


def scan_problem(scan: Scan) -> str | None:
    """Why ``scan`` cannot be mapped (a non-finite time, pose or angle ...), or None.

    Non-finite *ranges* are fine (no return); everything that places the beams must be finite.
    """
    n = len(scan.ranges)
    if not math.isfinite(scan.stamp):
        return f"its time {scan.stamp} is not finite"
    if np.shape(scan.odom) != (3,) or not np.all(np.isfinite(scan.odom)):
        return f"its odometry {np.asarray(scan.odom).tolist()} is not finite"
    if scan.reference is not None and not np.all(np.isfinite(scan.reference)):
        return "its reference pose is not finite"
    if n == 0 or n > MAX_BEAMS:
        return f"it has {n} beams (1 to {MAX_BEAMS:,} make a scan)"
    if len(scan.angles) != n:
        return f"it has {n} ranges but {len(scan.angles)} angles"
    if not np.all(np.isfinite(scan.angles)):
        return "its beam angles are not finite (angle_min or angle_increment)"
    if math.isnan(scan.max_range) or not math.isfinite(scan.min_range):
        return f"its range limits {scan.min_range}..{scan.max_range} are not numbers"
    return None


def free_ends(scan: Scan, max_range: float) -> np.ndarray:
    """Sensor-frame points ``(N, 2)`` where each beam that marks a map stops: its reading, or
    ``max_range`` for longer and no-return (infinite) readings; NaN, too short and beyond the
    scan's own ``max_range`` (error codes) are left out."""
    r = np.asarray(scan.ranges, dtype=float)
    with np.errstate(invalid="ignore"):
        ok = ~np.isnan(r) & (r > scan.min_range) & ((r <= scan.max_range + 0.01) | (r == np.inf))
    r = np.minimum(np.where(np.isfinite(r), r, max_range), max_range)[ok]
    a = scan.angles[ok]
    return np.stack([r * np.cos(a), r * np.sin(a)], axis=1)


def densify(
    points: np.ndarray,
    spacing: float = 0.025,
    max_gap: float = 0.3,
    bridge: float = 0.0,
    tolerance: float = 0.03,
) -> np.ndarray:
    """Points ``(N, 2)`` plus points every ``spacing`` metres between consecutive points closer
    than ``max_gap`` (they most likely lie on one surface), so a sparse far wall becomes a line.

    A longer gap, up to ``bridge`` metres, is filled too when the points either
    side of it continue its line (within ``tolerance`` m): beams that graze a
    wall far down a corridor hit it metres apart, and without the line between
    them a scan would match its own sparse points best at zero motion.
    """
    if len(points) < 2:
        return points
    gaps = np.diff(points, axis=0)
    length = np.hypot(gaps[:, 0], gaps[:, 1])
    fill = (length < max_gap) & (length > spacing)
    if bridge > max_gap and len(points) >= 4:
        fill |= _collinear_gaps(points, length, tolerance) & (length < bridge)
    counts = np.where(fill, np.floor(length / spacing).astype(np.int64), 0)
    if counts.sum() == 0:
        return points
    seg = np.repeat(np.arange(len(gaps)), counts)
    k = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts) + 1
    t = k / (counts[seg] + 1.0)
    extra = points[seg] + gaps[seg] * t[:, None]
    return np.concatenate([points, extra])


def _collinear_gaps(points: np.ndarray, length: np.ndarray, tolerance: float) -> np.ndarray:
    """Per gap ``k`` (between points ``k`` and ``k + 1``): whether points ``k - 1`` and
    ``k + 2`` lie on its line, before and after it."""
    out = np.zeros(len(length), dtype=bool)
    k = np.arange(1, len(points) - 2)
    a, b = points[k], points[k + 1]
    unit = (b - a) / np.maximum(length[k], 1e-9)[:, None]
    before, after = points[k - 1] - a, points[k + 2] - a
    off_before = np.abs(unit[:, 0] * before[:, 1] - unit[:, 1] * before[:, 0])
    off_after = np.abs(unit[:, 0] * after[:, 1] - unit[:, 1] * after[:, 0])
    along_before = (unit * before).sum(1)
    along_after = (unit * after).sum(1)
    out[k] = (
        (off_before < tolerance)
        & (off_after < tolerance)
        & (along_before < 0)
        & (along_after > length[k])
    )
    return out


@dataclass
class LaserLog:
    """A laser log read into memory.

    Attributes:
        path: The file it came from.
        scans: Scans in file order.
        warnings: One line per skipped or repaired line (``path:line: what``).
    """

    path: Path
    scans: list[Scan]
    warnings: list[str] = field(default_factory=list)

    @property
    def duration(self) -> float:
        """Seconds from the first to the last scan (0 for one scan)."""
        if len(self.scans) < 2:
            return 0.0
        stamps = [s.stamp for s in self.scans]
        return float(max(stamps) - min(stamps))

    def odometry(self) -> np.ndarray:
        """Sensor odometry poses ``(N, 3)`` of all scans."""
        return np.array([s.odom for s in self.scans], dtype=float).reshape(-1, 3)

    def references(self) -> np.ndarray | None:
        """Reference poses ``(N, 3)`` when every scan has one, else None."""
        if not self.scans or any(s.reference is None for s in self.scans):
            return None
        return np.array([s.reference for s in self.scans], dtype=float)
