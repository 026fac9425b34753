"""MRPT's own programs (Debian's mrpt-apps) read what benchmarks/mrpt_rawlog.py writes, and
benchmarks/mrpt_peers.py runs them: rawlog-edit lists every entry, icp-slam turns a scan into
exactly the points workbench does, icp-slam and rbpf-slam follow a short corridor drive."""

from __future__ import annotations

import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from benchmark_modules import benchmark_modules
from skipping import skip_or_fail

from workbench.mapping.corridors import corridor_world
from workbench.mapping.evaluate import absolute_trajectory_error
from workbench.mapping.scan import Scan
from workbench.mapping.simulate import raycast


@pytest.fixture(scope="module")
def modules():  # type: ignore[no-untyped-def]
    for program in ("rawlog-edit", "icp-slam", "rbpf-slam"):
        if shutil.which(program) is None:
            skip_or_fail(f"MRPT's {program} is not installed (apt-get install mrpt-apps)")
    config = Path("/usr/share/mrpt/config_files/rbpf-slam/gridmapping_optimal_sampling.ini")
    if not config.is_file():
        skip_or_fail(
            f"MRPT's shipped configs are not installed: no {config} (apt-get install mrpt-common)"
        )
    with benchmark_modules("mrpt_rawlog", "mrpt_peers") as modules:
        yield modules


def drive(count: int, beams: int, fov: float, step: float = 0.1) -> list[Scan]:
    """Scans every ``step`` m along the corridor world's bottom corridor, from x = 5 m."""
    world = corridor_world()
    if fov >= 2 * math.pi:
        angles = -math.pi + 2 * math.pi * np.arange(beams) / beams
    else:
        angles = -fov / 2 + (fov / beams) * np.arange(beams)  # CARMEN's FLASER spacing
    scans = []
    for k in range(count):
        pose = np.array([5.0 + step * k, 1.0, 0.0])
        scans.append(
            Scan(
                stamp=100.0 + 0.2 * k,
                ranges=raycast(world.segments, pose, angles, 30.0),
                angles=angles.copy(),
                odom=pose,
                max_range=30.0,
                reference=pose.copy(),
                source=f"drive[{k}]",
            )
        )
    return scans


def test_rawlog_edit_reads_every_entry(modules, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    rawlog, _ = modules
    scans = drive(3, 180, math.pi)
    path = tmp_path / "three.rawlog"
    model = rawlog.MotionModel(0.05, 0.02, 0.03, 0.05)
    rawlog.write_rawlog(path, scans, np.array([s.odom for s in scans]), model)
    info = subprocess.run(
        ["rawlog-edit", "--info", "-i", str(path)], capture_output=True, text=True, cwd=tmp_path
    )
    assert info.returncode == 0, info.stderr
    assert " ".join(info.stdout.split()).count("Overall number of objects : 6") == 1
    assert "Actions/SensoryFrame format : Yes" in " ".join(info.stdout.split())
    listed = subprocess.run(
        ["rawlog-edit", "--list-timestamps", "-i", str(path)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert listed.returncode == 0, listed.stderr
    lines = (tmp_path / "out.txt").read_text().split("\n")
    assert [ln.split()[:2] for ln in lines if ln] == [
        ["100.000000", "LASER"],
        ["100.200000", "LASER"],
        ["100.400000", "LASER"],
    ]


@pytest.mark.parametrize(("beams", "fov"), [(180, math.pi), (360, 2 * math.pi)])
def test_icp_slam_points_are_workbenchs(modules, tmp_path: Path, beams: int, fov: float) -> None:  # type: ignore[no-untyped-def]
    rawlog, peers = modules
    scan = drive(1, beams, fov)[0]
    assert 0 < scan.valid().sum() < beams  # some beams see no wall within 30 m
    path = tmp_path / "one.rawlog"
    rawlog.write_rawlog(path, [scan], np.zeros((1, 3)), rawlog.MotionModel(0.1, 0.1, 0.1, 0.1))
    config = peers.icp_config(tmp_path / "out")
    section = "MappingApplication_pointsMap_00_insertOpts"
    config = peers.set_options(config, section, {"minDistBetweenLaserPoints": 0})
    (tmp_path / "icp.ini").write_text(config)
    done = subprocess.run(
        ["icp-slam", str(tmp_path / "icp.ini"), str(path)], capture_output=True, cwd=tmp_path
    )
    assert done.returncode == 0, done.stderr[-500:]
    points = np.loadtxt(tmp_path / "out" / "_finalmaps_.txt_mrpt__maps__CSimplePointsMap_00.txt")
    assert points.shape == (scan.valid().sum(), 3)
    assert np.max(np.abs(points[:, :2] - scan.points())) < 1e-5


def test_peers_follow_a_short_drive(modules, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    rawlog, peers = modules
    scans = drive(30, 360, 2 * math.pi)
    truth = np.array([s.reference for s in scans])
    model = rawlog.MotionModel(0.05, 0.02, 0.03, 0.05)
    runs = peers.run_peers(scans, truth, model, tmp_path, [0], timeout=600)
    assert [r.method for r in runs] == ["MRPT icp-slam", "MRPT rbpf-slam"]
    icp, rbpf = runs
    assert icp.status == "ok" and rbpf.status == "ok" and rbpf.seed == 0
    assert icp.indices.tolist() == list(range(30))
    assert rbpf.indices[0] == 0 and len(rbpf.indices) == 3
    assert np.all(np.isin(np.diff(rbpf.indices), (10, 11)))  # a keyframe per metre
    # A corridor pins the robot across it, not along it: rbpf-slam's 7 cm grid slips a little.
    for run, bound in ((icp, 0.05), (rbpf, 0.15)):
        assert absolute_trajectory_error(run.poses, truth[run.indices]) < bound
        assert run.cpu_s > 0 and run.peak_mb > 10
    row = peers.peer_row(rbpf, truth, (1.0,))
    assert row["ate"] < 0.15 and row["rel_1m"]["pairs"] > 0 and row["poses"] == len(rbpf.indices)
