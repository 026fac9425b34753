"""benchmarks/mrpt_rawlog.py's bytes, field by field, against MRPT 2.5.8's serialization; and
benchmarks/mrpt_peers.py's config editing and output reading. Needs no MRPT program.

Layout sources (MRPT tag 2.5.8):
- libs/serialization/src/CArchive.cpp, ``CArchive::WriteObject``: ``uint8 len | 0x80``,
  class name, ``uint8`` version, payload, end byte ``0x88``; ``std::string``: ``uint32`` + bytes;
- libs/rtti/include/mrpt/rtti/CObject.h, ``IMPLEMENTS_MRPT_OBJECT``: names are
  ``Namespace::Class``;
- libs/core/src/Clock.cpp, ``Clock::fromDouble``: ``uint64(t * 1e7) + 116444736 * 10^9``;
- libs/poses/src/CPose2D.cpp v1: ``x y phi`` doubles; libs/poses/src/CPose3D.cpp v3:
  ``x y z`` and the rotation matrix row-major, doubles;
- libs/obs/src/CActionCollection.cpp v0 and CSensoryFrame.cpp v2: ``uint32`` count, objects;
- libs/obs/src/CActionRobotMovement2D.cpp v7 ``serializeTo``: ``uint32`` estimationMethod,
  CPose2D object, ``uint32`` modelSelection, 6 ``float`` (a1 a2 a3 a4 minStdXY minStdPHI),
  ``uint32`` nParticlesCount, 6 ``float`` (alfa1..alfa4, additional_std_XY/phi),
  ``bool`` hasVelocities, ``bool`` hasEncodersInfo, ``uint64`` timestamp;
- libs/obs/src/CObservation2DRangeScan.cpp v7 ``serializeTo``: ``float`` aperture,
  ``bool`` rightToLeft, ``float`` maxRange, CPose3D object, ``uint32`` N, N ``float``,
  N ``char`` valid, ``float`` stdError, ``uint64`` timestamp, ``float`` beamAperture,
  string sensorLabel, ``double`` deltaPitch, ``bool`` hasIntensity;
- libs/obs/src/CObservation2DRangeScan.cpp ``getScanAngle``: beam i at
  ``-aperture/2 + i aperture/(N-1)`` (counter-clockwise when rightToLeft), then the sensor yaw.
"""

from __future__ import annotations

import math
import struct
from pathlib import Path

import numpy as np
import pytest
from benchmark_modules import benchmark_modules

from workbench.mapping.errors import LogError
from workbench.mapping.scan import Scan

EPOCH_1970 = 116444736 * 10**9


@pytest.fixture(scope="module")
def modules():  # type: ignore[no-untyped-def]
    with benchmark_modules("mrpt_rawlog", "mrpt_peers") as modules:
        yield modules


@pytest.fixture
def rawlog(modules):  # type: ignore[no-untyped-def]
    return modules[0]


@pytest.fixture
def peers(modules):  # type: ignore[no-untyped-def]
    return modules[1]


class Reader:
    """Reads little-endian fields from bytes, in order."""

    def __init__(self, data: bytes) -> None:
        self.data, self.at = data, 0

    def take(self, fmt: str) -> tuple:
        values = struct.unpack_from("<" + fmt, self.data, self.at)
        self.at += struct.calcsize("<" + fmt)
        return values

    def one(self, fmt: str):  # type: ignore[no-untyped-def]
        return self.take(fmt)[0]

    def header(self) -> tuple[str, int]:
        length = self.one("B")
        assert length & 0x80, "the class-name length byte has its top bit set"
        name = self.data[self.at : self.at + (length & 0x7F)].decode()
        self.at += length & 0x7F
        return name, self.one("B")

    def end(self) -> None:
        assert self.one("B") == 0x88


def carmen_scan() -> Scan:
    """Four beams CARMEN-style (fov/n apart from -fov/2), one no return, one NaN."""
    return Scan(
        stamp=12.5,
        ranges=np.array([1.0, 81.83, np.nan, 2.5]),
        angles=-math.pi / 2 + (math.pi / 4) * np.arange(4),
        odom=np.zeros(3),
        max_range=81.0,
        source="test:1",
    )


def skip_frame(r: Reader) -> int:
    """Read past a sensory frame holding one range scan; its timestamp."""
    assert r.header() == ("mrpt::obs::CSensoryFrame", 2)
    assert r.one("I") == 1
    assert r.header() == ("mrpt::obs::CObservation2DRangeScan", 7)
    r.take("f?f")
    assert r.header() == ("mrpt::poses::CPose3D", 3)
    r.take("12d")
    r.end()
    n = r.one("I")
    r.take(f"{n}f{n}b")
    stamp = r.take("fQf")[1]
    label = r.one("I")
    r.at += label
    r.take("d?")
    r.end()
    r.end()
    return stamp


def test_one_frame_pair_field_by_field(rawlog) -> None:  # type: ignore[no-untyped-def]
    model = rawlog.MotionModel(a1=0.05, a2=0.02, a3=0.03, a4=0.04)
    data = rawlog.frame_pair(carmen_scan(), np.array([0.3, -0.1, 0.2]), model)
    r = Reader(data)
    # The action collection, one CActionRobotMovement2D.
    assert r.header() == ("mrpt::obs::CActionCollection", 0)
    assert r.one("I") == 1
    assert r.header() == ("mrpt::obs::CActionRobotMovement2D", 7)
    assert r.one("I") == 0  # emOdometry
    assert r.header() == ("mrpt::poses::CPose2D", 1)
    assert r.take("3d") == (0.3, -0.1, 0.2)
    r.end()
    assert r.one("I") == 0  # mmGaussian
    gaussian = r.take("6f")
    assert gaussian == pytest.approx((0.05, 0.02, 0.03, 0.04, 0.01, math.radians(0.2)), rel=1e-6)
    assert r.one("I") == 300  # Thrun model's defaults, unused with mmGaussian
    thrun = r.take("6f")
    expected = (0.05, math.radians(4.0), 0.01, math.degrees(0.0001), 0.001, math.radians(0.05))
    assert thrun == pytest.approx(expected, rel=1e-6)
    assert r.take("??") == (False, False)  # no velocities, no encoders: nothing follows
    assert r.one("Q") == 125_000_000 + EPOCH_1970
    r.end()  # the movement
    r.end()  # the collection
    # The sensory frame, one CObservation2DRangeScan.
    assert r.header() == ("mrpt::obs::CSensoryFrame", 2)
    assert r.one("I") == 1
    assert r.header() == ("mrpt::obs::CObservation2DRangeScan", 7)
    aperture, right_to_left, max_range = r.take("f?f")
    assert aperture == pytest.approx(3 * math.pi / 4, rel=1e-7)
    assert right_to_left is True
    assert max_range == 81.0
    assert r.header() == ("mrpt::poses::CPose3D", 3)
    x, y, z, *rotation = r.take("12d")
    yaw = -math.pi / 8  # midway between the first beam (-90 deg) and the last (+45 deg)
    assert (x, y, z) == (0.0, 0.0, 0.0)
    c, s = math.cos(yaw), math.sin(yaw)
    assert rotation == pytest.approx([c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0], abs=1e-15)
    r.end()
    assert r.one("I") == 4
    assert r.take("4f") == (1.0, 81.0, 81.0, 2.5)  # invalid readings stored as maxRange
    assert r.take("4b") == (1, 0, 0, 1)
    std_error, stamp, beam_aperture = r.take("fQf")
    assert std_error == pytest.approx(0.01)
    assert stamp == 125_000_000 + EPOCH_1970
    assert beam_aperture == pytest.approx(math.pi / 4, rel=1e-6)
    assert r.one("I") == 5 and r.data[r.at : r.at + 5] == b"LASER"
    r.at += 5
    assert r.take("d?") == (0.0, False)  # deltaPitch, no intensities
    r.end()  # the scan
    r.end()  # the frame
    assert r.at == len(data)


@pytest.mark.parametrize(
    ("n", "fov"), [(180, math.pi), (181, math.pi), (360, 2 * math.pi), (4, math.pi)]
)
def test_mrpt_beam_angles_are_the_scans(rawlog, n: int, fov: float) -> None:  # type: ignore[no-untyped-def]
    step = fov / (n - 1) if n == 181 else fov / n
    angles = -fov / 2 + step * np.arange(n)
    aperture, yaw = rawlog.beam_geometry(angles)
    aperture = float(np.float32(aperture))  # as written
    mrpt = yaw - aperture / 2 + np.arange(n) * aperture / (n - 1)
    assert np.max(np.abs(mrpt - angles)) < 1e-6


def test_mrpt_time_is_clock_from_double(rawlog) -> None:  # type: ignore[no-untyped-def]
    assert rawlog.mrpt_time(0.0) == EPOCH_1970
    assert rawlog.mrpt_time(1.0000001) == EPOCH_1970 + 10_000_001


def test_rawlog_alternates_actions_and_frames(rawlog, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    scans = [carmen_scan() for _ in range(3)]
    odometry = np.array([[1.0, 2.0, 0.5], [1.5, 2.0, 0.5], [1.5, 2.0, 1.0]])
    path = tmp_path / "three.rawlog"
    assert rawlog.write_rawlog(path, scans, odometry, rawlog.MotionModel(0.1, 0.1, 0.1, 0.1)) == 6
    r = Reader(path.read_bytes())
    increments, stamps = [], []
    for _ in range(3):
        assert r.header() == ("mrpt::obs::CActionCollection", 0)
        assert r.one("I") == 1
        assert r.header() == ("mrpt::obs::CActionRobotMovement2D", 7)
        r.take("I")
        assert r.header() == ("mrpt::poses::CPose2D", 1)
        increments.append(r.take("3d"))
        r.end()
        r.take("I6fI6f??Q")
        r.end()
        r.end()
        stamps.append(skip_frame(r))
    assert r.at == len(r.data)
    assert stamps == [125_000_000 + EPOCH_1970] * 3
    assert increments[0] == (0.0, 0.0, 0.0)
    c, s = math.cos(0.5), math.sin(0.5)
    assert increments[1] == pytest.approx((0.5 * c, -0.5 * s, 0.0))
    assert increments[2] == pytest.approx((0.0, 0.0, 0.5))


def test_scans_mrpt_cannot_take_are_refused(rawlog, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    uneven = carmen_scan()
    uneven.angles = np.array([-1.0, -0.5, 0.2, 0.7])
    with pytest.raises(LogError, match=r"test:1: beams are not evenly spaced"):
        rawlog.range_scan(uneven)
    endless = carmen_scan()
    endless.max_range = math.inf
    with pytest.raises(LogError, match="finite maximum range"):
        rawlog.range_scan(endless)
    model = rawlog.MotionModel(0.1, 0.1, 0.1, 0.1)
    with pytest.raises(LogError, match=r"2 scans need 2 odometry poses"):
        rawlog.write_rawlog(tmp_path / "x.rawlog", [carmen_scan()] * 2, np.zeros((3, 3)), model)


def test_gaussian_model_covers_the_benchmark_noise(rawlog) -> None:  # type: ignore[no-untyped-def]
    model = rawlog.MotionModel.from_odometry_noise((0.05, 0.02, 0.1, 0.03))
    assert (model.a1, model.a2, model.a4) == (0.1, 0.03, 0.05)
    assert model.a3 == pytest.approx(math.sqrt(2) * 0.02)


def test_set_options_replaces_and_appends_in_the_section(peers) -> None:  # type: ignore[no-untyped-def]
    text = "[A]\nx = 1 // comment\ny=2\n[B]\nx = 5\n"
    out = peers.set_options(text, "A", {"x": 7, "z": "w"})
    assert out == "[A]\nx = 7\ny=2\nz = w\n[B]\nx = 5\n"
    assert peers.set_options("[A]\n", "C", {"k": 1}) == "[A]\n[C]\nk = 1\n"


def test_rbpf_path_is_matched_to_the_inserted_steps(peers, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "log_times.txt").write_text(
        "% time_step ...\n%---\n0 1.0 1 1\n1 1.0 1 0\n2 1.0 2 1\n3 1.0 2 0\n"
    )
    (tmp_path / "most_likely_path.txt").write_text(
        "0.000 0.000 0.000\n0.010 0.000 0.000\n1.000 0.500 0.100\n"
    )
    poses, indices = peers.read_rbpf_path(tmp_path, 4)
    assert indices.tolist() == [0, 2]
    assert poses.tolist() == [[0.01, 0.0, 0.0], [1.0, 0.5, 0.1]]
    with pytest.raises(peers.PeerError, match="3 steps for 4 scans"):
        (tmp_path / "log_times.txt").write_text("0 1 1 1\n1 1 1 0\n2 1 2 1\n")
        peers.read_rbpf_path(tmp_path, 4)


def test_icp_path_needs_every_step(peers, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "log_estimated_path.txt").write_text("0 0.0 0.0 0.0\n1 0.5 0.0 0.1\n")
    poses, indices = peers.read_icp_path(tmp_path, 2)
    assert poses.tolist() == [[0.0, 0.0, 0.0], [0.5, 0.0, 0.1]]
    assert indices.tolist() == [0, 1]
    with pytest.raises(peers.PeerError, match="2 steps for 3 scans"):
        peers.read_icp_path(tmp_path, 3)
    with pytest.raises(peers.PeerError, match="was not written"):
        peers.read_icp_path(tmp_path / "none", 3)


def test_missing_programs_are_one_line_naming_the_package(peers, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setattr(peers.shutil, "which", lambda name: None)
    notice = peers.missing()
    assert notice is not None and "\n" not in notice
    assert "icp-slam, rbpf-slam" in notice and "apt-get install mrpt-apps mrpt-common" in notice


def test_a_log_mrpt_cannot_take_gives_failed_runs(peers, rawlog, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    endless = carmen_scan()
    endless.max_range = math.inf
    model = rawlog.MotionModel(0.1, 0.1, 0.1, 0.1)
    runs = peers.run_peers([endless], np.zeros((1, 3)), model, tmp_path, [0, 1], timeout=1)
    assert [(r.method, r.seed) for r in runs] == [
        ("MRPT icp-slam", None),
        ("MRPT rbpf-slam", 0),
        ("MRPT rbpf-slam", 1),
    ]
    assert all(r.status.startswith("failed: no rawlog: test:1: MRPT needs a finite") for r in runs)
    row = peers.peer_row(runs[1], np.zeros((1, 3)), (1.0,))
    assert row["ate"] is None and row["rel_1m"] is None and row["status"] == runs[1].status


def test_rbpf_config_is_the_shipped_one_seeded_and_capped(peers, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    shipped = tmp_path / "shipped.ini"
    shipped.write_text(
        "[MappingApplication]\nlogOutput_dir=LOG\nSHOW_PROGRESS_IN_WINDOW=1\n"
        "insertionLinDistance=0.7 // m\ninsertionAngDistance_deg=30.0\n"
        "localizeLinDistance = 0.2\nsampleSize=20\n"
        "[MappingApplication_occupancyGrid_00_insertOpts]\nmaxDistanceInsertion=30\n"
        "[MappingApplication_occupancyGrid_00_likelihoodOpts]\nLF_maxRange=30\nLF_stdHit=0.05\n"
    )
    text = peers.rbpf_config(tmp_path / "out", 7, 12.5, shipped)
    lines = set(text.splitlines())
    for line in (
        f"logOutput_dir = {tmp_path / 'out'}",
        "SHOW_PROGRESS_IN_WINDOW = 0",
        "RANDOM_SEED = 7",
        "localizeLinDistance = 0.7",
        "localizeAngDistance_deg = 30.0",
        "sampleSize=20",
        "maxDistanceInsertion = 12.5",
        "LF_maxRange = 12.5",
        "LF_stdHit=0.05",
    ):
        assert line in lines, line
    assert text.index("maxDistanceInsertion = 12.5") > text.index("_insertOpts]")
