"""MRPT's ``icp-slam`` and ``rbpf-slam`` (Debian's ``mrpt-apps``) run on a workbench log.

The scans and the odometry the workbench SLAM gets are written as a rawlog
(``mrpt_rawlog``); each program runs as a child process with a config
written from one MRPT ships (``icp-slam_demo_classic.ini``;
``gridmapping_optimal_sampling.ini`` unless another is named, the better of
the shipped grid-mapping configs on both benchmark logs): its algorithm
parameters unchanged, the output directory set, windows, 3-D scenes, map
images and per-step logging off, the grid's insertion and likelihood-field
ranges capped at the sensor's maximum range, and rbpf-slam's ``RANDOM_SEED``
set. rbpf-slam's particle filter runs where its map is updated
(``localizeLinDistance`` and ``localizeAngDistance_deg`` are set to the
insertion thresholds, as the shipped configs have them), so the final most
likely path (``most_likely_path.txt``: the initial pose, then one pose per
keyframe) matches the steps ``log_times.txt`` flags as inserted. icp-slam
writes one pose per scan (``log_estimated_path.txt``). CPU time and peak
memory are the child's own (``os.wait4``: user + system time, maximum
resident set size).
"""

from __future__ import annotations

import re
import shutil
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from child_process import run_measured
from mrpt_rawlog import MotionModel, write_rawlog

from workbench.errors import WorkbenchError
from workbench.mapping.evaluate import absolute_trajectory_error, relations, relative_error
from workbench.mapping.scan import Scan

CONFIGS = Path("/usr/share/mrpt/config_files")
ICP_CONFIG = CONFIGS / "icp-slam" / "icp-slam_demo_classic.ini"
RBPF_CONFIG = CONFIGS / "rbpf-slam" / "gridmapping_optimal_sampling.ini"
PROGRAMS = ("icp-slam", "rbpf-slam")
#: The programs come with mrpt-apps, the shipped configs with mrpt-common (only recommended).
INSTALL = "apt-get install mrpt-apps mrpt-common"
SECTION = "MappingApplication"
#: Settings of both programs: where to write, and no windows, scenes, images or per-step logs.
QUIET = {
    "LOG_FREQUENCY": 0,
    "SAVE_3D_SCENE": 0,
    "SAVE_MAP_IMAGES": 0,
    "SAVE_POSE_LOG": 0,
    "SHOW_PROGRESS_IN_WINDOW": 0,
    "SHOW_PROGRESS_3D_REAL_TIME": 0,
    "SHOW_LASER_SCANS_3D": 0,
    "verbosity": "WARN",
    "verbosity_level": "WARN",
}


class PeerError(Exception):
    """A peer's output cannot be read or matched to the scans."""


@dataclass
class PeerRun:
    """One run of an MRPT program.

    Attributes:
        method: ``MRPT icp-slam`` or ``MRPT rbpf-slam``.
        status: ``ok``, or why there is no trajectory (``failed: ...``, ``timeout after N s``).
        poses: Estimated poses ``(K, 3)`` (m, rad) in MRPT's map frame, or None.
        indices: The scan index of each pose ``(K,)``, or None.
        cpu_s: User + system CPU time of the child (s).
        wall_s: Wall time (s).
        peak_mb: The child's maximum resident set size (MB).
        seed: rbpf-slam's ``RANDOM_SEED``; None for icp-slam.
        rejected: icp-slam's ICP matches rejected as of low quality (None for rbpf-slam).
    """

    method: str
    status: str
    poses: np.ndarray | None
    indices: np.ndarray | None
    cpu_s: float
    wall_s: float
    peak_mb: float
    seed: int | None = None
    rejected: int | None = None


def missing() -> str | None:
    """Why the peers cannot run (programs or shipped configs absent), or None."""
    absent = [p for p in PROGRAMS if shutil.which(p) is None]
    absent += [str(c) for c in (ICP_CONFIG, RBPF_CONFIG) if not c.is_file()]
    if absent:
        return f"MRPT peers not run: {', '.join(absent)} missing ({INSTALL})"
    return None


def set_options(text: str, section: str, values: dict[str, object]) -> str:
    """``text`` (an MRPT .ini) with ``key = value`` set in ``[section]``.

    A key already in the section has its line replaced (comment dropped);
    others are added at the end of the section. Keys compare case-sensitively,
    as MRPT reads them.
    """
    lines = text.splitlines()
    header = re.compile(r"^\s*\[([^\]]+)\]")
    start = next(
        (i for i, ln in enumerate(lines) if (m := header.match(ln)) and m[1] == section), None
    )
    if start is None:
        lines += [f"[{section}]"]
        start = len(lines) - 1
    end = next((i for i in range(start + 1, len(lines)) if header.match(lines[i])), len(lines))
    pending = dict(values)
    for i in range(start + 1, end):
        key = re.match(r"^\s*([A-Za-z0-9_]+)\s*=", lines[i])
        if key and key[1] in pending:
            lines[i] = f"{key[1]} = {pending.pop(key[1])}"
    lines[end:end] = [f"{k} = {v}" for k, v in pending.items()]
    return "\n".join(lines) + "\n"


def icp_config(out_dir: Path) -> str:
    """icp-slam's config: the shipped demo with output to ``out_dir`` and nothing shown."""
    return set_options(
        ICP_CONFIG.read_text(), SECTION, {**QUIET, "logOutput_dir": out_dir, "rawlog_offset": 0}
    )


def rbpf_config(
    out_dir: Path, seed: int, max_range: float, shipped_file: Path = RBPF_CONFIG
) -> str:
    """rbpf-slam's config: a shipped one (``RBPF_CONFIG`` unless ``shipped_file`` is given),
    seeded, ranges capped at ``max_range`` m."""
    text = shipped_file.read_text()

    def shipped(key: str, default: float) -> float:
        found = re.search(rf"^\s*{key}\s*=\s*([-+0-9.eE]+)", text, re.MULTILINE)
        return float(found[1]) if found else default

    options = {
        **QUIET,
        "logOutput_dir": out_dir,
        "rawlog_offset": 0,
        "RANDOM_SEED": seed,
        "localizeLinDistance": shipped("insertionLinDistance", 0.5),
        "localizeAngDistance_deg": shipped("insertionAngDistance_deg", 25.0),
    }
    text = set_options(text, SECTION, options)
    grid = f"{SECTION}_occupancyGrid_00"
    cap = {"maxDistanceInsertion": min(shipped("maxDistanceInsertion", 30.0), max_range)}
    text = set_options(text, f"{grid}_insertOpts", cap)
    cap = {"LF_maxRange": min(shipped("LF_maxRange", 30.0), max_range)}
    return set_options(text, f"{grid}_likelihoodOpts", cap)


def _table(path: Path) -> np.ndarray:
    """A numeric text table (``%`` comment lines skipped) as a 2-D array."""
    if not path.is_file():
        raise PeerError(f"{path.name} was not written")
    rows = [ln.split() for ln in path.read_text().splitlines() if ln.strip() and ln[0] != "%"]
    if not rows:
        raise PeerError(f"{path.name} is empty")
    try:
        return np.array(rows, dtype=float)
    except ValueError as exc:
        raise PeerError(f"{path.name}: {exc}") from None


def read_icp_path(out_dir: Path, scans: int) -> tuple[np.ndarray, np.ndarray]:
    """icp-slam's poses ``(scans, 3)`` from ``log_estimated_path.txt`` (``step x y yaw``) and their
    scan indices."""
    table = _table(out_dir / "log_estimated_path.txt")
    if (
        table.shape[1] < 4
        or len(table) != scans
        or not np.array_equal(table[:, 0], np.arange(scans))
    ):
        raise PeerError(
            f"log_estimated_path.txt has {len(table)} steps for {scans} scans "
            "(the rawlog was not read to its end)"
        )
    return table[:, 1:4], np.arange(scans)


def read_rbpf_path(out_dir: Path, scans: int) -> tuple[np.ndarray, np.ndarray]:
    """rbpf-slam's final most likely path at its keyframes, and the keyframes' scan indices.

    ``log_times.txt`` (``step ms frames inserted``) names the inserted steps;
    ``most_likely_path.txt`` holds the initial pose and one pose (``x y yaw``)
    per inserted step.
    """
    times = _table(out_dir / "log_times.txt")
    if len(times) != scans or times.shape[1] < 4:
        raise PeerError(
            f"log_times.txt has {len(times)} steps for {scans} scans "
            "(the rawlog was not read to its end)"
        )
    inserted = np.flatnonzero(times[:, 3] == 1)
    path = _table(out_dir / "most_likely_path.txt")
    if path.shape[1] != 3 or len(path) != len(inserted) + 1:
        raise PeerError(
            f"most_likely_path.txt has {len(path)} poses for {len(inserted)} keyframes "
            "(expected one more: the initial pose)"
        )
    return path[1:], inserted


def _run(
    method: str,
    config: str,
    rawlog: Path,
    workdir: Path,
    reader,
    scans: int,
    timeout: float,
    seed: int | None = None,
) -> PeerRun:
    workdir.mkdir(parents=True, exist_ok=True)
    out = workdir / "out"
    ini = workdir / "config.ini"
    ini.write_text(config)
    program = method.split()[-1]
    done = run_measured([program, str(ini), str(rawlog)], workdir, timeout)
    run = PeerRun(method, "ok", None, None, done.cpu_s, done.wall_s, done.peak_mb, seed)
    if program == "icp-slam":
        run.rejected = (
            (workdir / "stdout.txt")
            .read_text(errors="replace")
            .count("Ignoring ICP of low quality")
        )
    if done.timed_out:
        run.status = f"timeout after {timeout:g} s"
    elif done.returncode != 0:
        lines = (workdir / "stderr.txt").read_text(errors="replace").strip().splitlines()
        last = lines[-1] if lines else "no message"
        run.status = f"failed: exit code {done.returncode}: {last}"
    else:
        try:
            run.poses, run.indices = reader(out, scans)
        except PeerError as exc:
            run.status = f"failed: {exc}"
    return run


def icp_slam(rawlog: Path, workdir: Path, scans: int, timeout: float) -> PeerRun:
    """Run icp-slam on ``rawlog`` (``scans`` scans) in ``workdir``."""
    return _run(
        "MRPT icp-slam", icp_config(workdir / "out"), rawlog, workdir, read_icp_path, scans, timeout
    )


def rbpf_slam(
    rawlog: Path,
    workdir: Path,
    scans: int,
    max_range: float,
    seed: int,
    timeout: float,
    shipped_file: Path = RBPF_CONFIG,
) -> PeerRun:
    """Run rbpf-slam on ``rawlog`` (``scans`` scans) in ``workdir`` with ``RANDOM_SEED`` ``seed``,
    its config made from ``shipped_file``."""
    config = rbpf_config(workdir / "out", seed, max_range, shipped_file)
    return _run("MRPT rbpf-slam", config, rawlog, workdir, read_rbpf_path, scans, timeout, seed)


def run_peers(
    scans: Sequence[Scan],
    odometry: np.ndarray,
    model: MotionModel,
    workdir: Path,
    rbpf_seeds: Sequence[int],
    timeout: float,
    rbpf_shipped: Path = RBPF_CONFIG,
) -> list[PeerRun]:
    """Write the rawlog of ``scans`` with ``odometry`` into ``workdir``, run icp-slam once and
    rbpf-slam once per seed in ``rbpf_seeds`` (its config made from ``rbpf_shipped``).

    A log MRPT cannot take (see ``mrpt_rawlog``) gives failed runs saying why.
    """
    workdir.mkdir(parents=True, exist_ok=True)
    rawlog = workdir / "log.rawlog"
    try:
        write_rawlog(rawlog, scans, odometry, model)
    except WorkbenchError as exc:
        status = f"failed: no rawlog: {exc}"
        runs = [PeerRun("MRPT icp-slam", status, None, None, 0.0, 0.0, 0.0)]
        return runs + [
            PeerRun("MRPT rbpf-slam", status, None, None, 0.0, 0.0, 0.0, seed)
            for seed in rbpf_seeds
        ]
    max_range = float(min(s.max_range for s in scans))
    runs = [icp_slam(rawlog, workdir / "icp-slam", len(scans), timeout)]
    for seed in rbpf_seeds:
        where = workdir / f"rbpf-slam-{seed}"
        runs.append(rbpf_slam(rawlog, where, len(scans), max_range, seed, timeout, rbpf_shipped))
    return runs


def peer_row(run: PeerRun, reference: np.ndarray, distances: Sequence[float]) -> dict:
    """The benchmark's metrics of one run against ``reference`` poses ``(N, 3)`` at the run's scans.

    ATE and relative errors (``rel_<d>m``) are None for a failed run.
    """
    row: dict = {
        "method": run.method,
        "status": run.status,
        "cpu_s": run.cpu_s,
        "wall_s": run.wall_s,
        "peak_mb": run.peak_mb,
        "rbpf_seed": run.seed,
        "icp_rejected": run.rejected,
        "poses": 0 if run.indices is None else len(run.indices),
        "ate": None,
    }
    for d in distances:
        row[f"rel_{d:g}m"] = None
    if run.poses is not None and run.indices is not None:
        ref = reference[run.indices]
        row["ate"] = absolute_trajectory_error(run.poses, ref)
        for d in distances:
            row[f"rel_{d:g}m"] = relative_error(run.poses, ref, relations(ref, d))
    return row
