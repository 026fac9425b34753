"""SLAM accuracy and speed on a real laser log, against dead reckoning and scan-to-scan ICP.

The log's own poses (for the Intel Research Lab log: a SLAM-corrected
trajectory) are the reference. The odometry fed to every method is made
from the reference increments with seeded noise of the odometry motion
model (Thrun, Burgard and Fox, Probabilistic Robotics, sample_motion_model_odometry):
each step is split into rotate-translate-rotate ``(r1, t, r2)``, and

    r1 += N(0, a1 |r1| + a2 |t|),  t += N(0, a3 |t| + a4 (|r1| + |r2|)),  r2 += N(0, a1 |r2| + a2 |t|)

(``a1`` rad/rad, ``a2`` rad/m, ``a3`` m/m, ``a4`` m/rad; backward motion is
treated as a negative translation). Metrics: absolute trajectory error
(RMSE of positions after the best rigid alignment) and the relative error of
Kummerle et al. (2009): for every scan ``i`` and the first later scan ``j``
at least ``D`` metres further along the reference path, the error of the
estimated relative pose ``x_i^-1 x_j`` against the reference's, reported as
mean ± std of its translation (m) and rotation (deg).

The simulated corridor log (``workbench.mapping.corridors``: a ring of long
2 m corridors driven twice, 360-beam scans with no-return readings,
odometry with a few percent of scale and heading error) is run next to it
with its own seeds, its true poses as the reference; the table adds the
incremental API's cost per scan at live settings (a 5 Hz 360-beam and a
40 Hz 720-beam laser, scans matched only every ``linear_update`` m or
``angular_update`` rad).

Peers, on both logs in the same run and with the same scans and odometry:
MRPT's ``icp-slam`` and ``rbpf-slam`` (Debian's ``mrpt-apps``, MRPT 2.5.8),
fed a rawlog written by ``mrpt_rawlog`` (which says how MRPT places the
beams, and how its grids and its matching disagree on that) and run by
``mrpt_peers`` with configs MRPT ships (``icp-slam_demo_classic.ini``;
``gridmapping_optimal_sampling.ini`` or the one ``--rbpf-config`` names,
e.g. ``gridmapping_intel.ini``), of which only output, display, logging,
range caps and rbpf-slam's ``RANDOM_SEED`` are changed (its localization
thresholds are pinned to its insertion thresholds, as shipped). Their
odometry motion model is the Gaussian one covering the log's noise level
(``MotionModel.from_odometry_noise``; the corridor log uses the middle
level). icp-slam is scored at every scan, rbpf-slam's final most likely path
at its keyframes (one per ``insertionLinDistance`` m or
``insertionAngDistance_deg``: 1 m or 40 degrees by default). rbpf-slam runs
``--rbpf-seeds`` times per log; the summary gives the median and range over
all runs of a method. workbench's SLAM runs as a child process too, so that
CPU time (user + system of the whole process) and peak memory (maximum
resident set size) are measured alike for all three; ``CPU s`` of
scan-to-scan ICP is in-process. Without ``mrpt-apps`` the peers are left out
with a one-line notice.

Run:  python benchmarks/slam.py [--log PATH] [--quick] [--seeds N] [--corridor-seeds N]
      [--rbpf-seeds N] [--rbpf-config INI] [--no-mrpt] [--timeout S]
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from machine import describe  # noqa: E402
from mrpt_peers import RBPF_CONFIG, missing, peer_row, run_peers
from mrpt_rawlog import MotionModel
from scipy.spatial import cKDTree
from slam_child import run_workbench
from slam_tables import label, print_runs, print_summary, summarise

from workbench.errors import WorkbenchError
from workbench.mapping import LikelihoodField, Slam, SlamConfig, build_map, read_log
from workbench.mapping.corridors import corridor_log
from workbench.mapping.evaluate import (
    NOISE_LEVELS,
    noisy_odometry,
    relations,
    relative_error,
)
from workbench.mapping.evaluate import absolute_trajectory_error as ate
from workbench.mapping.geometry import between, compose
from workbench.mapping.matcher import smooth_score
from workbench.mapping.render import save_png
from workbench.mapping.scan import Scan, densify

HERE = Path(__file__).resolve().parent
DEFAULT_LOG = HERE.parent / "mapping" / "logs" / "intel-corrected.log.gz"
#: (a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad) per noise level.
LEVELS = NOISE_LEVELS
RELATION_DISTANCES = (1.0, 5.0)
MEMORY_NOTE = (
    "CPU s: user + system time of the whole process (workbench and MRPT: child processes), "
    "in-process for scan-to-scan ICP; peak MB: maximum resident set size"
)


def icp_step(prev: np.ndarray, cur: np.ndarray, guess: np.ndarray, iterations: int = 30):
    """Point-to-point ICP of scan ``cur`` onto ``prev`` (sensor frames), from ``guess``."""
    if len(prev) < 5 or len(cur) < 5:
        return guess
    tree = cKDTree(prev)
    x = guess.copy()
    for _ in range(iterations):
        c, s = np.cos(x[2]), np.sin(x[2])
        moved = cur @ np.array([[c, s], [-s, c]]) + x[:2]
        dist, idx = tree.query(moved, distance_upper_bound=0.5)
        ok = np.isfinite(dist)
        if ok.sum() < 5:
            break
        src, dst = moved[ok], prev[idx[ok]]
        mu_s, mu_d = src.mean(0), dst.mean(0)
        a, b = src - mu_s, dst - mu_d
        dtheta = np.arctan2((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum(), (a * b).sum())
        c2, s2 = np.cos(dtheta), np.sin(dtheta)
        t = mu_d - np.array([c2 * mu_s[0] - s2 * mu_s[1], s2 * mu_s[0] + c2 * mu_s[1]])
        x = np.array([c2 * x[0] - s2 * x[1] + t[0], s2 * x[0] + c2 * x[1] + t[1], x[2] + dtheta])
        if np.hypot(*t) < 1e-5 and abs(dtheta) < 1e-6:
            break
    return x


def run_icp(scans, odom: np.ndarray) -> np.ndarray:
    """Chain of scan-to-scan ICP increments, each started from the odometry increment."""
    points = [s.points(20.0) for s in scans]
    poses = [odom[0].copy()]
    for k in range(1, len(scans)):
        guess = between(odom[k - 1], odom[k])
        step = icp_step(points[k - 1], points[k], guess)
        poses.append(compose(poses[-1], step))
    return np.array(poses)


def alignment_likelihood(scans, poses: np.ndarray) -> float:
    """Mean likelihood of each scan in the field of the scan before it, at the relative pose
    given by ``poses`` (higher = the poses align the raw scans better)."""
    scores = []
    for k in range(1, len(scans)):
        field = LikelihoodField(densify(scans[k - 1].points(20.0)), 0.05, 0.05)
        rel = between(poses[k - 1], poses[k])
        scores.append(smooth_score(field, scans[k].points(20.0), rel))
    return float(np.mean(scores))


@dataclass
class Peers:
    """Settings of the MRPT peers' runs (None in their place: not run).

    Attributes:
        workdir: Where rawlogs, configs and outputs go.
        rbpf_seeds: rbpf-slam's ``RANDOM_SEED`` values, one run each per log.
        timeout: Seconds a program may run before it is stopped and reported.
        rbpf_shipped: The shipped rbpf-slam config its config is made from.
    """

    workdir: Path
    rbpf_seeds: list[int]
    timeout: float
    rbpf_shipped: Path


def peer_rows(
    scans: list[Scan],
    odom: np.ndarray,
    reference: np.ndarray,
    alphas: tuple[float, float, float, float],
    peers: Peers,
    name: str,
    ours: np.ndarray,
) -> list[dict]:
    """Rows of MRPT's icp-slam and rbpf-slam on ``scans`` with ``odom``, workbench's ATE at the
    same scans alongside (``ours``: its poses); rbpf-slam's first map kept as a PNG."""
    model = MotionModel.from_odometry_noise(alphas)
    runs = run_peers(
        scans,
        odom,
        model,
        peers.workdir / name,
        peers.rbpf_seeds,
        peers.timeout,
        peers.rbpf_shipped,
    )
    rows = []
    for run in runs:
        row = peer_row(run, reference, RELATION_DISTANCES)
        if run.indices is not None:
            row["workbench_ate_same_scans"] = ate(ours[run.indices], reference[run.indices])
        rows.append(row)
    return rows


def keep_rbpf_map(peers: Peers, name: str, target: Path) -> None:
    """Copy rbpf-slam's final map of run ``name`` (first seed) to ``target`` if it was written."""
    found = sorted((peers.workdir / name).glob("rbpf-slam-*/out/finalMap_*.png"))
    if found:
        shutil.copyfile(found[0], target)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--log", type=Path, default=DEFAULT_LOG, help="CARMEN log or ROS bag")
    parser.add_argument("--seeds", type=int, default=3, help="noise seeds per level")
    parser.add_argument("--quick", action="store_true", help="one seed, first 300 scans")
    parser.add_argument("--levels", default="low,middle,high", help="comma-separated levels")
    parser.add_argument("--out", type=Path, default=HERE / "results" / "slam.json")
    parser.add_argument("--corridor-seeds", type=int, default=3, help="corridor log seeds")
    parser.add_argument("--only", choices=("intel", "corridor"), help="run one log only")
    parser.add_argument("--no-mrpt", action="store_true", help="leave MRPT's programs out")
    parser.add_argument("--rbpf-seeds", type=int, default=3, help="rbpf-slam runs per log")
    parser.add_argument(
        "--rbpf-config",
        type=Path,
        default=RBPF_CONFIG,
        help="shipped rbpf-slam config to start from (default: %(default)s)",
    )
    parser.add_argument(
        "--timeout",
        type=float,
        default=1800.0,
        help="seconds per SLAM process before it is stopped",
    )
    args = parser.parse_args(argv)
    if not args.no_mrpt and not args.rbpf_config.is_file() and RBPF_CONFIG.is_file():
        parser.error(f"--rbpf-config {args.rbpf_config}: no such file")
    with tempfile.TemporaryDirectory(prefix="slam-benchmark-") as tmp:
        peers = None
        if not args.no_mrpt:
            notice = missing()
            if notice:
                print(notice)
            else:
                seeds = list(range(args.rbpf_seeds))
                peers = Peers(Path(tmp), seeds, args.timeout, args.rbpf_config)
        return run(args, Path(tmp), peers)


def run(args: argparse.Namespace, tmp: Path, peers: Peers | None) -> int:
    """The benchmark proper, with its scratch directory ``tmp``."""
    args.out.parent.mkdir(parents=True, exist_ok=True)
    corridor_out = args.out.with_name("slam_corridor.json")
    if args.only == "corridor":
        corridor = run_corridor(args.corridor_seeds, args.out, tmp, args.timeout, peers)
        corridor_out.write_text(json.dumps(corridor, indent=1))
        return 0
    try:
        log = read_log(args.log)
    except WorkbenchError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    scans = log.scans[:300] if args.quick else log.scans
    reference = log.references()
    if reference is None:
        print("the log has no reference poses; using its odometry as the reference")
        reference = log.odometry()
    reference = reference[: len(scans)]
    duration = float(max(s.stamp for s in scans) - min(s.stamp for s in scans))
    seeds = 1 if args.quick else args.seeds
    levels = [name.strip() for name in args.levels.split(",")]
    info = describe(("numpy", "scipy"), mrpt=mrpt_version())
    config = SlamConfig()
    rows = []
    print(f"log: {args.log} ({len(scans)} scans, {duration:.1f} s)")
    print(
        f"machine: {info['cpu']}, {info['cores']} cores ({info['usable_cores']} usable), "
        f"load {info['load_average']}; python {info['python']}, numpy {info['numpy']}, "
        f"scipy {info['scipy']}; MRPT {info['mrpt']}"
    )
    for level in levels:
        alphas = LEVELS[level]
        for seed in range(seeds):
            odom = noisy_odometry(reference, alphas, seed)
            for scan, o in zip(scans, odom, strict=True):
                scan.odom = o
            ours = run_workbench(scans, config, tmp / f"workbench-{level}-{seed}", args.timeout)
            icp_cpu = time.process_time()
            icp_wall = time.perf_counter()
            icp = run_icp(scans, odom)
            icp_wall, icp_cpu = time.perf_counter() - icp_wall, time.process_time() - icp_cpu
            new = []
            for method, est, seconds, cpu_s, peak in (
                ("workbench", ours.poses, ours.slam_wall_s, ours.cpu_s, ours.peak_mb),
                ("dead reckoning", odom, 0.0, None, None),
                ("scan-to-scan ICP", icp, icp_wall, icp_cpu, None),
            ):
                row = {"method": method, "ate": ate(est, reference)}
                for d in RELATION_DISTANCES:
                    row[f"rel_{d:g}m"] = relative_error(est, reference, relations(reference, d))
                row.update(wall_s=seconds, cpu_s=cpu_s, peak_mb=peak)
                if method == "workbench":
                    row["loop_closures"] = ours.loop_closures
                    row["alignment_likelihood"] = alignment_likelihood(scans, est)
                    row["slam_cpu_s"] = ours.slam_cpu_s
                    row["cpu_realtime_factor"] = duration / ours.slam_cpu_s
                new.append(row)
            if peers is not None:
                name = f"intel-{level}-{seed}"
                new += peer_rows(scans, odom, reference, alphas, peers, name, ours.poses)
                if seed == 0:
                    keep_rbpf_map(peers, name, args.out.with_name(f"slam_{level}_rbpf.png"))
            for row in new:
                row.update(level=level, seed=seed)
                wall = row.get("wall_s")
                row["realtime_factor"] = (
                    duration / wall if wall and row["ate"] is not None else None
                )
            rows += new
            if seed == 0:
                grid = build_map(scans, ours.poses, 0.05).to_map()
                save_png(
                    grid, args.out.with_name(f"slam_{level}.png"), [(ours.poses, (220, 30, 30))]
                )
            took = ", ".join(f"{label(r)} {r['wall_s']:.1f} s" for r in new if r.get("wall_s"))
            print(f"  {level} seed {seed}: {took} (wall)", flush=True)
    reference_alignment = alignment_likelihood(scans, reference)
    print()
    print_runs(rows)
    summary = summarise(rows, "level")
    print()
    print_summary(summary, "level")
    print(MEMORY_NOTE)
    ours = np.mean([r["alignment_likelihood"] for r in rows if r["method"] == "workbench"])
    print(
        f"\nscan-to-scan alignment likelihood (higher is better): reference poses "
        f"{reference_alignment:.3f}, workbench poses {ours:.3f} (mean over runs)"
    )
    args.out.write_text(
        json.dumps(
            {
                "log": str(args.log),
                "scans": len(scans),
                "duration_s": duration,
                "noise_levels": {k: LEVELS[k] for k in levels},
                "noise_parameters": "a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad",
                "seeds": list(range(seeds)),
                "rbpf_seeds": peers.rbpf_seeds if peers else [],
                "rbpf_config": str(peers.rbpf_shipped) if peers else None,
                "machine": info,
                "config": config.__dict__,
                "rows": rows,
                "summary": summary,
                "reference_alignment_likelihood": reference_alignment,
            },
            indent=1,
            default=float,
        )
    )
    print(f"\nwrote {args.out}")
    if args.only != "intel":
        seeds = 1 if args.quick else args.corridor_seeds
        corridor = run_corridor(seeds, args.out, tmp, args.timeout, peers)
        corridor_out.write_text(json.dumps(corridor, indent=1))
        print(f"wrote {corridor_out}")
    return 0


def mrpt_version() -> str:
    """The installed mrpt-apps package version (dpkg), or ``not installed``."""
    try:
        done = subprocess.run(
            ["dpkg-query", "-W", "-f=${Version}", "mrpt-apps"], capture_output=True, text=True
        )
    except OSError:
        return "not installed"
    return done.stdout.strip() if done.returncode == 0 and done.stdout.strip() else "not installed"


def live_cost(seed: int, beams: int, rate: float, speed: float, config: SlamConfig) -> dict:
    """Milliseconds per scan of the incremental API on a corridor log at a live scan rate."""
    log = corridor_log(seed, beams=beams, step=speed / rate, rate=rate)
    slam = Slam(config)
    times = []
    for scan in log.scans:
        start = time.process_time()
        slam.add_scan(scan)
        times.append(1000.0 * (time.process_time() - start))
    t = np.array(times)
    return {
        "beams": beams,
        "rate_hz": rate,
        "speed_m_s": speed,
        "scans": len(t),
        "matched": int(np.isfinite(slam.scores).sum()),
        "ms_mean": float(t.mean()),
        "ms_p99": float(np.percentile(t, 99)),
        "ms_max": float(t.max()),
        "budget_ms": 1000.0 / rate,
        "ate": ate(slam.poses(), log.truth),
    }


def run_corridor(seeds: int, out: Path, tmp: Path, timeout: float, peers: Peers | None) -> dict:
    """workbench, dead reckoning, scan-to-scan ICP and the MRPT peers on the corridor log."""
    print("\ncorridor log (workbench.mapping.corridors), 360 beams, 30 m range, two laps")
    rows = []
    for seed in range(seeds):
        log = corridor_log(seed)
        odom, truth = log.odometry, log.truth
        ours = run_workbench(log.scans, SlamConfig(), tmp / f"workbench-corridor-{seed}", timeout)
        icp_cpu = time.process_time()
        icp = run_icp(log.scans, odom)
        icp_cpu = time.process_time() - icp_cpu
        new = []
        for method, est, c, m in (
            ("workbench", ours.poses, ours.cpu_s, ours.peak_mb),
            ("dead reckoning", odom, None, None),
            ("scan-to-scan ICP", icp, icp_cpu, None),
        ):
            row = {"method": method, "ate": ate(est, truth), "cpu_s": c, "peak_mb": m}
            for d in RELATION_DISTANCES:
                row[f"rel_{d:g}m"] = relative_error(est, truth, relations(truth, d))
            new.append(row)
        if peers is not None:
            name = f"corridor-{seed}"
            new += peer_rows(log.scans, odom, truth, LEVELS["middle"], peers, name, ours.poses)
            if seed == 0:
                keep_rbpf_map(peers, name, out.with_name("slam_corridor_rbpf.png"))
        for row in new:
            row["seed"] = seed
        rows += new
        if seed == 0:
            grid = build_map(log.scans, ours.poses, 0.05).to_map()
            save_png(grid, out.with_name("slam_corridor.png"), [(ours.poses, (220, 30, 30))])
        ates = ", ".join(
            f"{label(r)} {r['ate']:.3f} m" if r["ate"] is not None else f"{label(r)} {r['status']}"
            for r in new
        )
        print(
            f"  seed {seed} ({len(log.scans)} scans, odometry errors {log.errors}): ATE {ates}",
            flush=True,
        )
    summary = summarise(rows)
    print_summary(summary)
    print(MEMORY_NOTE)
    live = SlamConfig(linear_update=0.25, angular_update=0.25)
    costs = [live_cost(0, 360, 5.0, 0.5, live), live_cost(0, 720, 40.0, 0.5, live)]
    for c in costs:
        print(
            f"live: {c['beams']} beams at {c['rate_hz']:g} Hz, {c['speed_m_s']} m/s: "
            f"{c['ms_mean']:.1f} ms/scan mean, p99 {c['ms_p99']:.0f} ms, max {c['ms_max']:.0f} ms "
            f"(budget {c['budget_ms']:.0f} ms), {c['matched']}/{c['scans']} matched, "
            f"ATE {c['ate']:.3f} m"
        )
    return {
        "rows": rows,
        "summary": summary,
        "live": costs,
        "rbpf_seeds": peers.rbpf_seeds if peers else [],
        "rbpf_config": str(peers.rbpf_shipped) if peers else None,
        "machine": describe(("numpy", "scipy"), mrpt=mrpt_version()),
    }


if __name__ == "__main__":
    sys.exit(main())
