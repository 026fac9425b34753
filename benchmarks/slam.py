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
with its own seeds, its true poses as the reference. For it the table adds
CPU time and peak memory (``tracemalloc``), and the incremental API's cost
per scan at live settings (a 5 Hz 360-beam and a 40 Hz 720-beam laser,
scans matched only every ``linear_update`` m or ``angular_update`` rad).

MRPT's icp-slam and rbpf-slam are not run: see the project's notes on the
rawlog format they need.

Run:  python benchmarks/slam.py [--log PATH] [--quick] [--seeds N] [--corridor-seeds N]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np
from machine import describe  # noqa: E402
from scipy.spatial import cKDTree

from workbench.errors import WorkbenchError
from workbench.mapping import LikelihoodField, Slam, SlamConfig, build_map, read_log, run_slam
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
from workbench.mapping.scan import densify

HERE = Path(__file__).resolve().parent
DEFAULT_LOG = HERE.parent / "mapping" / "logs" / "intel-corrected.log.gz"
#: (a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad) per noise level.
LEVELS = NOISE_LEVELS
RELATION_DISTANCES = (1.0, 5.0)


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


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--log", type=Path, default=DEFAULT_LOG, help="CARMEN log or ROS bag")
    parser.add_argument("--seeds", type=int, default=3, help="noise seeds per level")
    parser.add_argument("--quick", action="store_true", help="one seed, first 300 scans")
    parser.add_argument("--levels", default="low,middle,high", help="comma-separated levels")
    parser.add_argument("--out", type=Path, default=HERE / "results" / "slam.json")
    parser.add_argument("--corridor-seeds", type=int, default=3, help="corridor log seeds")
    parser.add_argument("--only", choices=("intel", "corridor"), help="run one log only")
    args = parser.parse_args(argv)
    if args.only == "corridor":
        corridor = run_corridor(args.corridor_seeds, args.out)
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.with_name("slam_corridor.json").write_text(json.dumps(corridor, indent=1))
        return 0
    try:
        log = read_log(args.log)
    except WorkbenchError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    args.out.parent.mkdir(parents=True, exist_ok=True)
    scans = log.scans[:300] if args.quick else log.scans
    reference = log.references()
    if reference is None:
        print("the log has no reference poses; using its odometry as the reference")
        reference = log.odometry()
    reference = reference[: len(scans)]
    duration = float(max(s.stamp for s in scans) - min(s.stamp for s in scans))
    seeds = 1 if args.quick else args.seeds
    levels = [name.strip() for name in args.levels.split(",")]
    info = describe(("numpy", "scipy"))
    config = SlamConfig()
    rows = []
    print(f"log: {args.log} ({len(scans)} scans, {duration:.1f} s)")
    print(
        f"machine: {info['cpu']}, {info['cores']} cores ({info['usable_cores']} usable), "
        f"load {info['load_average']}; python {info['python']}, numpy {info['numpy']}, "
        f"scipy {info['scipy']}"
    )
    for level in levels:
        alphas = LEVELS[level]
        for seed in range(seeds):
            odom = noisy_odometry(reference, alphas, seed)
            for scan, o in zip(scans, odom, strict=True):
                scan.odom = o
            wall, cpu = time.perf_counter(), time.process_time()
            result = run_slam(scans, config)
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            icp_wall = time.perf_counter()
            icp = run_icp(scans, odom)
            icp_wall = time.perf_counter() - icp_wall
            for method, est, seconds, cpu_s in (
                ("workbench", result.poses, wall, cpu),
                ("dead reckoning", odom, 0.0, 0.0),
                ("scan-to-scan ICP", icp, icp_wall, None),
            ):
                row = {"level": level, "seed": seed, "method": method, "ate": ate(est, reference)}
                for d in RELATION_DISTANCES:
                    row[f"rel_{d:g}m"] = relative_error(est, reference, relations(reference, d))
                row["wall_s"] = seconds
                row["cpu_s"] = cpu_s
                row["realtime_factor"] = duration / seconds if seconds else None
                if method == "workbench":
                    row["loop_closures"] = len(result.loop_closures)
                    row["alignment_likelihood"] = alignment_likelihood(scans, est)
                    row["cpu_realtime_factor"] = duration / cpu
                rows.append(row)
            if seed == 0:
                grid = build_map(scans, result.poses, 0.05).to_map()
                save_png(
                    grid, args.out.with_name(f"slam_{level}.png"), [(result.poses, (220, 30, 30))]
                )
            print(f"  {level} seed {seed}: done in {wall:.1f} s wall / {cpu:.1f} s CPU", flush=True)
    reference_alignment = alignment_likelihood(scans, reference)
    print()
    print_table(rows)
    summary = summarise(rows)
    print()
    print_summary(summary)
    ours = np.mean([r["alignment_likelihood"] for r in rows if r["method"] == "workbench"])
    print(
        f"\nscan-to-scan alignment likelihood (higher is better): reference poses "
        f"{reference_alignment:.3f}, workbench poses {ours:.3f} (mean over runs)"
    )
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(
        json.dumps(
            {
                "log": str(args.log),
                "scans": len(scans),
                "duration_s": duration,
                "noise_levels": {k: LEVELS[k] for k in levels},
                "noise_parameters": "a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad",
                "seeds": list(range(seeds)),
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
        corridor = run_corridor(1 if args.quick else args.corridor_seeds, args.out)
        args.out.with_name("slam_corridor.json").write_text(json.dumps(corridor, indent=1))
        print(f"wrote {args.out.with_name('slam_corridor.json')}")
    return 0


def measured(function, *args, **kwargs):
    """``function(*args, **kwargs)``, its CPU seconds and its peak traced memory (MB)."""
    tracemalloc.start()
    cpu = time.process_time()
    value = function(*args, **kwargs)
    cpu = time.process_time() - cpu
    peak = tracemalloc.get_traced_memory()[1] / 1e6
    tracemalloc.stop()
    return value, cpu, peak


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


def run_corridor(seeds: int, out: Path) -> dict:
    """Workbench, dead reckoning and scan-to-scan ICP on the corridor log, per seed."""
    print("\ncorridor log (workbench.mapping.corridors), 360 beams, 30 m range, two laps")
    rows = []
    for seed in range(seeds):
        log = corridor_log(seed)
        odom, truth = log.odometry, log.truth
        result, cpu, peak = measured(run_slam, log.scans)
        icp, icp_cpu, icp_peak = measured(run_icp, log.scans, odom)
        for method, est, c, m in (
            ("workbench", result.poses, cpu, peak),
            ("dead reckoning", odom, 0.0, 0.0),
            ("scan-to-scan ICP", icp, icp_cpu, icp_peak),
        ):
            row = {"seed": seed, "method": method, "ate": ate(est, truth), "cpu_s": c, "peak_mb": m}
            for d in RELATION_DISTANCES:
                row[f"rel_{d:g}m"] = relative_error(est, truth, relations(truth, d))
            rows.append(row)
        if seed == 0:
            grid = build_map(log.scans, result.poses, 0.05).to_map()
            save_png(grid, out.with_name("slam_corridor.png"), [(result.poses, (220, 30, 30))])
        print(
            f"  seed {seed} ({len(log.scans)} scans, odometry errors {log.errors}): "
            f"ATE {rows[-3]['ate']:.3f} m, {cpu:.1f} s CPU",
            flush=True,
        )
    print(
        f"{'method':18} {'ATE m (median)':>14} {'rel 1m m':>9} {'rel 1m deg':>10} {'CPU s':>7} {'peak MB':>8}"
    )
    summary = []
    for method in ("workbench", "dead reckoning", "scan-to-scan ICP"):
        sel = [r for r in rows if r["method"] == method]
        entry = {
            "method": method,
            "ate_median": float(np.median([r["ate"] for r in sel])),
            "ate_max": float(np.max([r["ate"] for r in sel])),
            "rel_1m_trans": float(np.mean([r["rel_1m"]["trans_mean"] for r in sel])),
            "rel_1m_rot": float(np.mean([r["rel_1m"]["rot_mean"] for r in sel])),
            "cpu_s": float(np.mean([r["cpu_s"] for r in sel])),
            "peak_mb": float(np.max([r["peak_mb"] for r in sel])),
        }
        summary.append(entry)
        print(
            f"{method:18} {entry['ate_median']:14.3f} {entry['rel_1m_trans']:9.3f} "
            f"{entry['rel_1m_rot']:10.2f} {entry['cpu_s']:7.1f} {entry['peak_mb']:8.0f}"
        )
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
        "machine": describe(("numpy", "scipy")),
    }


def print_table(rows) -> None:
    head = f"{'level':7} {'seed':>4} {'method':18} {'ATE m':>7} {'rel 1m: trans m':>17} {'rot deg':>13} {'rel 5m: trans m':>17} {'wall s':>7} {'x real time':>11}"
    print(head)
    print("-" * len(head))
    for r in rows:
        a, b = r["rel_1m"], r["rel_5m"]
        rtf = f"{r['realtime_factor']:.0f}" if r["realtime_factor"] else "-"
        print(
            f"{r['level']:7} {r['seed']:4d} {r['method']:18} {r['ate']:7.3f} "
            f"{a['trans_mean']:8.3f} ± {a['trans_std']:5.3f} {a['rot_mean']:5.2f} ± {a['rot_std']:5.2f} "
            f"{b['trans_mean']:8.3f} ± {b['trans_std']:5.3f} {r['wall_s']:7.1f} {rtf:>11}"
        )


def summarise(rows):
    out = []
    for level in dict.fromkeys(r["level"] for r in rows):
        base = {}
        for method in ("workbench", "dead reckoning", "scan-to-scan ICP"):
            sel = [r for r in rows if r["level"] == level and r["method"] == method]
            entry = {
                "level": level,
                "method": method,
                "ate": float(np.mean([r["ate"] for r in sel])),
                "rel_1m_trans": float(np.mean([r["rel_1m"]["trans_mean"] for r in sel])),
                "rel_1m_rot": float(np.mean([r["rel_1m"]["rot_mean"] for r in sel])),
                "rel_5m_trans": float(np.mean([r["rel_5m"]["trans_mean"] for r in sel])),
            }
            if method == "workbench":
                entry["realtime_factor"] = float(np.mean([r["realtime_factor"] for r in sel]))
                entry["cpu_realtime_factor"] = float(
                    np.mean([r["cpu_realtime_factor"] for r in sel])
                )
                base = entry
            else:
                entry["ate_ratio_to_workbench"] = entry["ate"] / base["ate"]
                entry["rel_1m_ratio_to_workbench"] = entry["rel_1m_trans"] / base["rel_1m_trans"]
            out.append(entry)
    return out


def print_summary(summary) -> None:
    print(
        f"{'level':7} {'method':18} {'ATE m':>7} {'rel 1m m':>9} {'rel 1m deg':>10} {'rel 5m m':>9} {'vs workbench':>13} {'x real time (wall/CPU)':>23}"
    )
    for s in summary:
        ratio = f"{s['ate_ratio_to_workbench']:.1f}x ATE" if "ate_ratio_to_workbench" in s else ""
        rtf = (
            f"{s['realtime_factor']:.0f} / {s['cpu_realtime_factor']:.0f}"
            if "realtime_factor" in s
            else ""
        )
        print(
            f"{s['level']:7} {s['method']:18} {s['ate']:7.3f} {s['rel_1m_trans']:9.3f} {s['rel_1m_rot']:10.2f} "
            f"{s['rel_5m_trans']:9.3f} {ratio:>13} {rtf:>23}"
        )


if __name__ == "__main__":
    sys.exit(main())
