"""AMCL on saved maps: convergence, pose error and update time, against dead reckoning and a loop.

Run ``python benchmarks/amcl.py`` (``--quick`` for shorter routes and fewer timings).
Writes ``benchmarks/results/amcl.json`` and prints two tables with the machine.

* Accuracy: on ``mapping/demo_rooms.yaml`` (0.05 m, a 3.5 m laser as the TurtleBot3's
  LDS) and ``mapping/intel_lab.yaml`` (0.1 m, an 8 m laser), a seeded route through
  free space (clearance 0.35 m; shortest grid paths between random goals), scans
  ray-cast to the map's occupied cells (360 beams, 1 cm noise), odometry 3 % long with noise in
  proportion to each step; amcl's defaults with ``max_particles`` 500/2000/5000 and the
  initial guess 0.5 m and 0.25 rad off (and, with 2000 particles, odometry without the
  3 % scale error: in the lab's long corridors the scans hardly say where along the
  corridor the robot is, so a biased odometry shows there). Reported: the error of each published pose,
  the distance travelled until it first falls below 0.1 m, the mean/p95/max error
  after that, and the error of odometry alone (the baseline) over the same route.
* Speed: wall time of one filter update (motion model, likelihood field with 30 beams,
  resample every second update) with the particle count fixed at 500/2000/5000
  (``min_particles = max_particles``), median and p95; and the likelihood field alone
  against a per-particle, per-beam Python loop written as amcl's ``LikelihoodFieldModel``
  (the baseline: the same numbers, the ratio of times).
"""

from __future__ import annotations

import argparse
import collections
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from machine import describe  # noqa: E402

from workbench.mapping.geometry import between, compose  # noqa: E402
from workbench.mapping.map_server_node import load_map_yaml  # noqa: E402
from workbench.navigation.amcl_laser import LaserScanData, beam_indices, prepare_ranges  # noqa: E402
from workbench.navigation.amcl_localizer import Localizer  # noqa: E402
from workbench.navigation.amcl_map import FREE, AmclMap  # noqa: E402
from workbench.navigation.amcl_params import AmclParams  # noqa: E402
from workbench.navigation.amcl_simulate import noisy_odometry, simulated_ranges  # noqa: E402

MAPS = {
    "demo_rooms": ("mapping/demo_rooms.yaml", 3.5),
    "intel_lab": ("mapping/intel_lab.yaml", 8.0),
}
PARTICLES = (500, 2000, 5000)
BEAMS = 360
ANGLES = -math.pi + np.arange(BEAMS) * (2 * math.pi / BEAMS)
GUESS = np.array([0.5, -0.4, 0.25])
CLEARANCE = 0.35


def load(name: str) -> AmclMap:
    loaded = load_map_yaml(str(ROOT / MAPS[name][0]))
    return AmclMap.from_cells(loaded.cells, loaded.meta.resolution, loaded.meta.origin[:2])


def grid_path(
    ok: np.ndarray, start: tuple[int, int], goal: tuple[int, int]
) -> list[tuple[int, int]]:
    """The shortest 8-connected path between two cells of ``ok`` (breadth first), [] if none."""
    parent = {start: start}
    queue = collections.deque([start])
    rows, cols = ok.shape
    while queue:
        cell = queue.popleft()
        if cell == goal:
            path = [cell]
            while path[-1] != start:
                path.append(parent[path[-1]])
            return path[::-1]
        r, c = cell
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                n = (r + dr, c + dc)
                if 0 <= n[0] < rows and 0 <= n[1] < cols and ok[n] and n not in parent:
                    parent[n] = cell
                    queue.append(n)
    return []


def route(m: AmclMap, length: float, seed: int, step: float = 0.05) -> np.ndarray:
    """Poses every ``step`` m along shortest paths between random goals with clearance."""
    from scipy import ndimage

    rng = np.random.default_rng(seed)
    clear = ndimage.distance_transform_edt(m.states == FREE) * m.resolution >= CLEARANCE
    label, _ = ndimage.label(clear)
    largest = np.argmax(np.bincount(label[label > 0])) if label.max() else 0
    ok = label == largest
    cells = np.argwhere(ok)
    points = [tuple(cells[rng.integers(len(cells))])]
    travelled = 0.0
    while travelled < length:
        goal = tuple(cells[rng.integers(len(cells))])
        path = grid_path(ok, points[-1], goal)
        if len(path) < 20:
            continue
        every = max(int(0.5 / m.resolution), 1)
        points.extend(path[every::every])
        travelled += len(path) * m.resolution
    xy = np.array(
        [
            [m.origin_x + (c + 0.5) * m.resolution, m.origin_y + (r + 0.5) * m.resolution]
            for r, c in points
        ]
    )
    poses: list[np.ndarray] = []
    for a, b in zip(xy[:-1], xy[1:], strict=True):
        heading = math.atan2(b[1] - a[1], b[0] - a[0])
        if poses:  # turn on the spot, at most 0.1 rad per step
            last = poses[-1][2]
            turn = math.atan2(math.sin(heading - last), math.cos(heading - last))
            n = int(abs(turn) / 0.1)
            poses.extend(
                np.array([a[0], a[1], last + f * turn]) for f in np.arange(1, n + 1) / (n + 1)
            )
        n = max(int(np.ceil(np.hypot(*(b - a)) / step)), 1)
        poses.extend(np.array([*(a + t * (b - a)), heading]) for t in np.arange(1, n + 1) / n)
    return np.array(poses)


def scan(m: AmclMap, pose: np.ndarray, range_max: float, rng: np.random.Generator) -> LaserScanData:
    noisy = simulated_ranges(m, pose, ANGLES, range_max, rng)
    return LaserScanData(prepare_ranges(noisy, 0.12, range_max), ANGLES.copy(), range_max)


def accuracy(name: str, particles: int, length: float, seed: int, scale: float = 1.03) -> dict:
    m = load(name)
    range_max = MAPS[name][1]
    truth = route(m, length, seed)
    odom = noisy_odometry(truth, seed, scale)
    start = truth[0] + GUESS
    params = AmclParams(
        max_particles=particles,
        initial_pose_x=start[0],
        initial_pose_y=start[1],
        initial_pose_a=start[2],
    )
    localizer = Localizer(m, params, seed=seed)
    rng = np.random.default_rng(seed + 1)
    travelled = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(truth[:, :2], axis=0).T))])
    errors, where, counts = [], [], []
    for k in range(len(truth)):
        estimate = localizer.process(odom[k], scan(m, truth[k], range_max, rng))
        if estimate.publish:
            errors.append(float(np.hypot(*(estimate.pose[:2] - truth[k][:2]))))
            where.append(k)
            counts.append(localizer.pf.count)
    errors_a = np.array(errors)
    below = np.nonzero(errors_a <= 0.1)[0]
    first = int(below[0]) if len(below) else len(errors_a)
    after = errors_a[first:]
    # dead reckoning from the true start
    dead = np.hypot(*(compose(truth[0], between(odom[0], odom))[:, :2] - truth[:, :2]).T)
    return {
        "map": name,
        "particles": particles,
        "odometry_scale": scale,
        "route_m": float(travelled[-1]),
        "scans": len(truth),
        "estimates": len(errors),
        "first_error_m": float(errors_a[0]),
        "converged_after_m": float(travelled[where[first]]) if first < len(where) else None,
        "mean_error_m": float(after.mean()) if len(after) else None,
        "p95_error_m": float(np.percentile(after, 95)) if len(after) else None,
        "max_error_m": float(after.max()) if len(after) else None,
        "final_particles": counts[-1],
        "odometry_mean_error_m": float(dead.mean()),
        "odometry_max_error_m": float(dead.max()),
    }


def naive_likelihoods(model, poses: np.ndarray, data: LaserScanData) -> np.ndarray:
    """amcl's LikelihoodFieldModel loop, particle by particle and beam by beam."""
    m = model.map
    out = np.empty(len(poses))
    denom = 2 * model.sigma_hit**2
    index = beam_indices(len(data.ranges), model.max_beams)
    for j, (x, y, theta) in enumerate(poses):
        lx, ly = model.laser_pose[:2]
        sx = x + math.cos(theta) * lx - math.sin(theta) * ly
        sy = y + math.sin(theta) * lx + math.cos(theta) * ly
        p = 1.0
        for i in index:
            r = data.ranges[i]
            if not r < data.range_max:
                continue
            hx = sx + r * math.cos(theta + data.bearings[i])
            hy = sy + r * math.sin(theta + data.bearings[i])
            mi = math.floor((hx - m.origin_x) / m.resolution)
            mj = math.floor((hy - m.origin_y) / m.resolution)
            z = m.occ_dist[mj, mi] if 0 <= mi < m.size_x and 0 <= mj < m.size_y else m.max_occ_dist
            pz = model.z_hit * math.exp(-(z * z) / denom) + model.z_rand / data.range_max
            p += pz * pz * pz
        out[j] = p
    return out


def speed(particles: int, updates: int, seed: int) -> dict:
    m = load("demo_rooms")
    truth = route(m, 60.0, seed)
    odom = noisy_odometry(truth, seed)
    params = AmclParams(
        min_particles=particles,
        max_particles=particles,
        initial_pose_x=truth[0][0],
        initial_pose_y=truth[0][1],
        initial_pose_a=truth[0][2],
        update_min_d=0.0,
        update_min_a=0.0,
    )
    localizer = Localizer(m, params, seed=seed)
    rng = np.random.default_rng(seed)
    scans = [scan(m, pose, 3.5, rng) for pose in truth[: updates + 1]]
    times = []
    for k in range(updates + 1):
        begin = time.perf_counter()
        localizer.process(odom[k], scans[k])
        times.append(time.perf_counter() - begin)
    times = np.array(times[1:]) * 1000
    poses = localizer.pf.poses
    model = localizer.laser
    begin = time.perf_counter()
    fast = model.likelihoods(poses, scans[-1])
    vector_ms = (time.perf_counter() - begin) * 1000
    begin = time.perf_counter()
    slow = naive_likelihoods(model, poses, scans[-1])
    loop_ms = (time.perf_counter() - begin) * 1000
    return {
        "particles": particles,
        "update_median_ms": float(np.median(times)),
        "update_p95_ms": float(np.percentile(times, 95)),
        "likelihood_ms": vector_ms,
        "loop_likelihood_ms": loop_ms,
        "loop_ratio": loop_ms / vector_ms,
        "same_values": bool(np.allclose(fast, slow)),
    }


#: (heading, key, format) of the tables' columns.
ACCURACY_COLUMNS = [
    ("map", "map", "<11"),
    ("odom scale", "odometry_scale", ">11.2f"),
    ("particles", "particles", ">10"),
    ("route m", "route_m", ">9.1f"),
    ("first m", "first_error_m", ">9.3f"),
    ("conv. after m", "converged_after_m", ">15.1f"),
    ("mean m", "mean_error_m", ">8.3f"),
    ("p95 m", "p95_error_m", ">8.3f"),
    ("max m", "max_error_m", ">8.3f"),
    ("final n", "final_particles", ">9"),
    ("odom mean m", "odometry_mean_error_m", ">13.3f"),
    ("odom max m", "odometry_max_error_m", ">12.3f"),
]
SPEED_COLUMNS = [
    ("particles", "particles", ">10"),
    ("median ms", "update_median_ms", ">11.2f"),
    ("p95 ms", "update_p95_ms", ">9.2f"),
    ("field ms", "likelihood_ms", ">10.2f"),
    ("loop field ms", "loop_likelihood_ms", ">15.1f"),
    ("ratio", "loop_ratio", ">8.0f"),
    ("same", "same_values", ">6"),
]


def table(columns: list[tuple[str, str, str]], rows: list[dict]) -> str:
    """A plain-text table: a heading line, then one line per row ('-' for a missing value)."""
    width = [int("".join(ch for ch in fmt.split(".")[0] if ch.isdigit())) for _, _, fmt in columns]
    align = [fmt[0] for _, _, fmt in columns]
    lines = [
        "".join(f"{head:{a}{w}}" for (head, _, _), a, w in zip(columns, align, width, strict=True))
    ]
    for row in rows:
        cells = []
        for (_, key, fmt), a, w in zip(columns, align, width, strict=True):
            value = row[key]
            cells.append(
                f"{'-':{a}{w}}"
                if value is None
                else f"{str(value) if isinstance(value, bool) else value:{fmt}}"
            )
        lines.append("".join(cells))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="shorter routes, fewer updates")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "results" / "amcl.json")
    args = parser.parse_args(argv)
    length = 40.0 if args.quick else 150.0
    updates = 50 if args.quick else 300
    machine = describe(("numpy", "scipy"))
    print(
        f"machine: {machine['cpu']}, {machine['usable_cores']} usable cores, Python {machine['python']}; seed {args.seed}"
    )
    rows = [accuracy(name, n, length, args.seed) for name in MAPS for n in PARTICLES]
    rows += [accuracy(name, 2000, length, args.seed, 1.0) for name in MAPS]
    print("\nAccuracy (error of each published amcl_pose; odometry alone as the baseline)")
    print(table(ACCURACY_COLUMNS, rows))
    timings = [speed(n, updates, args.seed) for n in PARTICLES]
    print("\nUpdate time per scan (demo_rooms, 30 of 360 beams, particle count fixed)")
    print(table(SPEED_COLUMNS, timings))
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(
        json.dumps(
            {
                "machine": machine,
                "seed": args.seed,
                "quick": args.quick,
                "accuracy": rows,
                "speed": timings,
            },
            indent=2,
        )
        + "\n"
    )
    print(f"\nwrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
