"""MRPT rawlog files (action/observation format) from workbench laser scans.

MRPT's ``icp-slam`` and ``rbpf-slam`` read a rawlog: a stream of serialized
objects alternating a ``CActionCollection`` (one ``CActionRobotMovement2D``,
the odometry increment since the previous scan) and a ``CSensoryFrame`` (one
``CObservation2DRangeScan``). The layout below is MRPT 2.5.8's (the version
Debian's ``mrpt-apps`` ships), read from its sources:

- every object (``CArchive::WriteObject``, libs/serialization/src/CArchive.cpp):
  ``uint8 len | 0x80``, the class name with its namespace
  (``mrpt::obs::CSensoryFrame``: ``IMPLEMENTS_SERIALIZABLE``), ``uint8`` version,
  the payload, and the end-of-object byte ``0x88``; numbers little-endian;
- a ``std::string``: ``uint32`` length and the bytes; a ``bool``: one byte;
- ``mrpt::Clock`` time points: ``uint64`` ticks of 100 ns since 1601-01-01
  (``Clock::fromDouble``: ``uint64(t * 1e7) + 116444736 * 10^9``);
- ``CPose2D`` v1: ``x y phi`` as doubles; ``CPose3D`` v3: ``x y z`` and the
  rotation matrix row by row, twelve doubles;
- ``CActionCollection`` v0 and ``CSensoryFrame`` v2: ``uint32`` count, then
  the objects;
- ``CActionRobotMovement2D`` v7 with ``estimationMethod = emOdometry``:
  ``uint32`` method, the increment as a ``CPose2D`` object, ``uint32``
  ``modelSelection``, the Gaussian model's ``a1 a2 a3 a4 minStdXY minStdPHI``
  as floats, the Thrun model's ``uint32`` particle count and
  ``alfa1..alfa4 additional_std_XY additional_std_phi`` as floats (unused
  with ``mmGaussian``), ``bool``
  hasVelocities, ``bool`` hasEncodersInfo (both false here: nothing follows
  them), the timestamp;
- ``CObservation2DRangeScan`` v7: ``float`` aperture, ``bool`` rightToLeft,
  ``float`` maxRange, the sensor pose as a ``CPose3D`` object, ``uint32`` N,
  N ``float`` ranges, N ``int8`` validity flags, ``float`` stdError, the
  timestamp, ``float`` beamAperture, the sensor label, ``double``
  deltaPitch, ``bool`` hasIntensity (false: no intensities follow).

Beam geometry: MRPT spaces a scan's N beams ``aperture / (N - 1)`` apart,
from ``-aperture / 2`` (``CObservation2DRangeScan::getScanAngle``,
``CSinCosLookUpTableFor2DScans``: what ICP, point maps and likelihood fields
use), counter-clockwise when ``rightToLeft``. A CARMEN scan's beams (n beams
``fov / n`` apart from ``-fov / 2``, so not centred) are matched exactly by
``aperture = (n - 1) * step`` and a sensor pose turned by the mean of the first
and last beam's angles; MRPT's robot frame is then the scan's own sensor
frame, and odometry increments are those of the sensor poses. (MRPT's
occupancy-grid insertion, ``COccupancyGridMap2D_insert.cpp``, spaces rays
``aperture / N`` instead: in rbpf-slam's grids beam ``i`` lands ``i / N``
of a step clockwise of where its point is matched, up to one step, 1 degree
for these scans. No aperture serves both; the mismatch turns rbpf-slam's
heading clockwise keyframe by keyframe: 47 degrees over the corridor log's
two laps (seed 0, ``gridmapping_intel.ini``), and counter-clockwise instead
with the beams written clockwise, ``rightToLeft`` false.)
Readings that are no return (at or beyond the scan's ``max_range``, NaN,
inf, too short) are flagged invalid and stored as ``maxRange``.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workbench.mapping.errors import LogError
from workbench.mapping.geometry import between
from workbench.mapping.scan import Scan

#: ``CArchive``'s end-of-object byte (``SERIALIZATION_END_FLAG``).
END_FLAG = 0x88
#: 100 ns ticks from 1601-01-01 to 1970-01-01 (``mrpt::Clock``).
UNIX_EPOCH_TICKS = 116444736 * 10**9
#: ``CActionRobotMovement2D::emOdometry`` and ``mmGaussian``.
EM_ODOMETRY, MM_GAUSSIAN = 0, 0
#: MRPT 2.5.8's default Thrun model ``nParticlesCount``, ``alfa1..alfa4``,
#: ``additional_std_XY``, ``additional_std_phi`` (written although unused, as MRPT does).
THRUN_DEFAULTS = (300, 0.05, np.radians(4.0), 0.01, np.degrees(0.0001), 0.001, np.radians(0.05))
#: Serialization versions written (MRPT 2.5.8's current ones).
VERSIONS = {
    "mrpt::obs::CActionCollection": 0,
    "mrpt::obs::CActionRobotMovement2D": 7,
    "mrpt::obs::CSensoryFrame": 2,
    "mrpt::obs::CObservation2DRangeScan": 7,
    "mrpt::poses::CPose2D": 1,
    "mrpt::poses::CPose3D": 3,
}
#: Beams whose spacing differs from the mean by more than this are refused (rad).
SPACING_TOLERANCE = 1e-6


@dataclass(frozen=True)
class MotionModel:
    """MRPT's Gaussian odometry motion model (``computeFromOdometry_modelGaussian``).

    For an increment of ``d`` metres and ``phi`` radians MRPT takes standard
    deviations ``min_std_xy + a1 d + a2 |phi|`` (m) in x and y and
    ``min_std_phi + a3 d + a4 |phi|`` (rad) in heading. (Its Thrun model is
    not used: MRPT reads it as 300 drawn samples whose mean, not the
    increment, becomes the odometry, and that mean wanders off by metres
    over a long log.)

    Attributes:
        a1: m/m.
        a2: m/rad.
        a3: rad/m.
        a4: rad/rad.
        min_std_xy: m (MRPT's default).
        min_std_phi: rad (MRPT's default).
    """

    a1: float
    a2: float
    a3: float
    a4: float
    min_std_xy: float = 0.01
    min_std_phi: float = float(np.radians(0.2))

    @classmethod
    def from_odometry_noise(cls, alphas: tuple[float, float, float, float]) -> MotionModel:
        """The Gaussian model that covers odometry noise of the benchmark's form.

        ``alphas`` are ``(a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad)`` of
        ``workbench.mapping.evaluate.noisy_odometry``: a translation of ``t``
        after turns ``r1``, ``r2`` errs by ``a3 t + a4 (|r1| + |r2|)`` (m) and
        the heading by about ``a1 |phi| + sqrt(2) a2 t`` (rad), one std dev.
        """
        r_r, r_t, t_t, t_r = alphas
        return cls(a1=t_t, a2=t_r, a3=float(np.sqrt(2.0)) * r_t, a4=r_r)


def mrpt_time(seconds: float) -> int:
    """``mrpt::Clock`` ticks (100 ns since 1601) of a UNIX time in seconds."""
    return int(seconds * 1e7) + UNIX_EPOCH_TICKS


def text(value: str) -> bytes:
    """A ``std::string`` as ``CArchive`` writes it: ``uint32`` length and the bytes."""
    raw = value.encode()
    return struct.pack("<I", len(raw)) + raw


def serialized(class_name: str, payload: bytes) -> bytes:
    """One object: flagged name length, name, version, payload, end-of-object byte."""
    name = class_name.encode()
    return (
        struct.pack("<B", 0x80 | len(name))
        + name
        + struct.pack("<B", VERSIONS[class_name])
        + payload
        + bytes([END_FLAG])
    )


def pose2d(x: float, y: float, phi: float) -> bytes:
    """A ``CPose2D`` object."""
    return serialized("mrpt::poses::CPose2D", struct.pack("<3d", x, y, phi))


def pose3d_yaw(x: float, y: float, z: float, yaw: float) -> bytes:
    """A ``CPose3D`` object turned by ``yaw`` (rad) about z: position, then R row by row."""
    c, s = np.cos(yaw), np.sin(yaw)
    rotation = (c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
    return serialized("mrpt::poses::CPose3D", struct.pack("<12d", x, y, z, *rotation))


def beam_geometry(angles: np.ndarray, where: str = "") -> tuple[float, float]:
    """MRPT's ``aperture`` and sensor yaw (rad) that reproduce evenly spaced beam ``angles``.

    Raises:
        LogError: Fewer than two beams, or beams not evenly spaced counter-clockwise.
    """
    a = np.asarray(angles, dtype=float)
    if len(a) < 2:
        raise LogError(f"{where}: a scan needs two beams or more for MRPT, this one has {len(a)}")
    step = np.diff(a)
    mean = (a[-1] - a[0]) / (len(a) - 1)
    if mean <= 0 or np.max(np.abs(step - mean)) > SPACING_TOLERANCE:
        raise LogError(
            f"{where}: beams are not evenly spaced counter-clockwise "
            f"(steps {np.degrees(step.min()):.4f} to {np.degrees(step.max()):.4f} deg); "
            "MRPT's 2-D scans need one constant step"
        )
    return float(a[-1] - a[0]), float(0.5 * (a[0] + a[-1]))


def range_scan(scan: Scan, label: str = "LASER", std_error: float = 0.01) -> bytes:
    """A ``CObservation2DRangeScan`` object (v7) of one scan, its no-return readings invalid."""
    aperture, yaw = beam_geometry(scan.angles, scan.source)
    if not np.isfinite(scan.max_range):
        raise LogError(f"{scan.source}: MRPT needs a finite maximum range, the scan has none")
    valid = scan.valid()
    ranges = np.where(valid, scan.ranges, scan.max_range).astype("<f4")
    beam = aperture / (len(ranges) - 1)
    payload = b"".join(
        (
            struct.pack("<f?f", aperture, True, scan.max_range),
            pose3d_yaw(0.0, 0.0, 0.0, yaw),
            struct.pack("<I", len(ranges)),
            ranges.tobytes(),
            valid.astype("<i1").tobytes(),
            struct.pack("<fQf", std_error, mrpt_time(scan.stamp), beam),
            text(label),
            struct.pack("<d?", 0.0, False),
        )
    )
    return serialized("mrpt::obs::CObservation2DRangeScan", payload)


def robot_movement(increment: np.ndarray, stamp: float, model: MotionModel) -> bytes:
    """A ``CActionRobotMovement2D`` object (v7): an odometry increment ``(x, y, theta)``."""
    payload = b"".join(
        (
            struct.pack("<I", EM_ODOMETRY),
            pose2d(*(float(v) for v in increment)),
            struct.pack("<I", MM_GAUSSIAN),
            struct.pack(
                "<6f", model.a1, model.a2, model.a3, model.a4, model.min_std_xy, model.min_std_phi
            ),
            struct.pack("<I6f", *THRUN_DEFAULTS),
            struct.pack("<??Q", False, False, mrpt_time(stamp)),
        )
    )
    return serialized("mrpt::obs::CActionRobotMovement2D", payload)


def collection(class_name: str, items: Sequence[bytes]) -> bytes:
    """A ``CActionCollection`` or ``CSensoryFrame`` object holding ``items``."""
    return serialized(class_name, struct.pack("<I", len(items)) + b"".join(items))


def frame_pair(scan: Scan, increment: np.ndarray, model: MotionModel) -> bytes:
    """One rawlog entry pair: the action (odometry increment), then the scan's sensory frame."""
    action = collection(
        "mrpt::obs::CActionCollection", [robot_movement(increment, scan.stamp, model)]
    )
    frame = collection("mrpt::obs::CSensoryFrame", [range_scan(scan)])
    return action + frame


def write_rawlog(
    path: str | Path, scans: Sequence[Scan], odometry: np.ndarray, model: MotionModel
) -> int:
    """Write ``scans`` with the increments of ``odometry`` (sensor poses ``(N, 3)``) as a rawlog.

    The first action is a zero increment. Returns the number of entries written
    (two per scan).

    Raises:
        LogError: A scan MRPT cannot represent, or odometry of another length.
    """
    odometry = np.asarray(odometry, dtype=float)
    if odometry.shape != (len(scans), 3):
        raise LogError(
            f"{len(scans)} scans need {len(scans)} odometry poses, got shape {odometry.shape}",
            path=path,
        )
    with open(path, "wb") as out:
        for k, scan in enumerate(scans):
            increment = np.zeros(3) if k == 0 else between(odometry[k - 1], odometry[k])
            out.write(frame_pair(scan, increment, model))
    return 2 * len(scans)
