"""Global planning time: navfn (Dijkstra potential, scipy.sparse.csgraph) against a plain heapq A*.

Run ``python benchmarks/navfn_planning.py`` (``--quick`` for a short run). Each saved map
(``mapping/intel_lab.yaml``, ``mapping/demo_rooms.yaml``, read with map_server's YAML
reader) becomes a global costmap as move_base's would be: the static layer's reading of
the map (unknown tracked) inflated with costmap_2d's defaults for the lab's footprint
(inscribed radius 0.21 m, ``inflation_radius`` 0.55 m, ``cost_scaling_factor`` 10). 50
start/goal pairs (seeded) are drawn among the free cells, kept when the goal is
reachable and at least 1 m away. Each pair is planned by

* ``navfn``: :func:`workbench.navigation.navfn.navfn_plan` (navfn's cell costs, Dijkstra
  potential from the robot spread until the goal window is settled, predecessor path,
  goal window search); the search graph of a costmap is kept while the costmap does not
  change, as between the global costmap's updates;
* ``navfn new``: the same with the graph built for every plan (a costmap that changed);
* ``navfn A*``: the same with ``use_dijkstra=False``;
* ``heapq A*``: :func:`workbench.navigation.astar_baseline.astar` on the same cell
  costs (computed inside the timing as navfn computes them), what one writes by hand.

Reported: median and p95 planning time (ms), the ratio, and the mean path length of
each (m) with the largest relative difference. Prints a table with the machine and
writes ``benchmarks/results/navfn_planning.json``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from machine import describe  # noqa: E402

from workbench.mapping.map_server_node import load_map_yaml  # noqa: E402
from workbench.navigation.astar_baseline import astar  # noqa: E402
from workbench.navigation.costmap_grid import Costmap2D  # noqa: E402
from workbench.navigation.costmap_inflation import inflate  # noqa: E402
from workbench.navigation.costmap_static import interpret_values  # noqa: E402
from workbench.navigation.navfn import navfn_plan, path_length  # noqa: E402
from workbench.navigation.navfn_grid import (  # noqa: E402
    POT_HIGH,
    cell_costs,
    clear_graph_cache,
    potential,
)

SEED = 0
MAPS = ("intel_lab", "demo_rooms")
INSCRIBED = 0.21
INFLATION_RADIUS = 0.55
COST_SCALING = 10.0


def load_costmap(name: str) -> Costmap2D:
    """The global costmap of ``mapping/<name>.yaml``."""
    loaded = load_map_yaml(str(ROOT / "mapping" / f"{name}.yaml"))
    costs = interpret_values(loaded.cells)
    res = loaded.meta.resolution
    inflate(costs, res, INFLATION_RADIUS, INSCRIBED, COST_SCALING)
    return Costmap2D(costs, res, loaded.meta.origin[0], loaded.meta.origin[1], "map")


def random_pairs(costmap: Costmap2D, count: int, seed: int) -> list[tuple[tuple, tuple]]:
    """``count`` reachable (start, goal) cell pairs at least 1 m apart."""
    rng = np.random.default_rng(seed)
    free = np.argwhere(costmap.costs == 0)[:, ::-1]  # (mx, my)
    cost = cell_costs(costmap.costs)
    pairs: list[tuple[tuple, tuple]] = []
    while len(pairs) < count:
        a, b = free[rng.integers(len(free), size=2)]
        if np.hypot(*(a - b)) * costmap.resolution < 1.0:
            continue
        pot, _ = potential(cost, (int(a[0]), int(a[1])))
        if pot[b[1] * costmap.size_x + b[0]] >= POT_HIGH:
            continue
        pairs.append(((int(a[0]), int(a[1])), (int(b[0]), int(b[1]))))
    return pairs


def timed(function, *args, **kwargs):
    start = time.perf_counter()
    result = function(*args, **kwargs)
    return result, (time.perf_counter() - start) * 1e3


def run_map(name: str, count: int, seed: int) -> dict:
    costmap = load_costmap(name)
    pairs = random_pairs(costmap, count, seed)
    times: dict[str, list[float]] = {"navfn": [], "navfn new": [], "navfn A*": [], "heapq A*": []}
    lengths: dict[str, list[float]] = {key: [] for key in times}
    failures = 0
    for a, b in pairs:
        start, goal = costmap.map_to_world(*a), costmap.map_to_world(*b)
        path, ms = timed(navfn_plan, costmap, start, goal)
        times["navfn"].append(ms)
        lengths["navfn"].append(path_length(path))
        clear_graph_cache()
        path, ms = timed(navfn_plan, costmap, start, goal)
        times["navfn new"].append(ms)
        lengths["navfn new"].append(path_length(path))
        path, ms = timed(navfn_plan, costmap, start, goal, use_dijkstra=False)
        times["navfn A*"].append(ms)
        lengths["navfn A*"].append(path_length(path))
        t0 = time.perf_counter()
        cells, _ = astar(cell_costs(costmap.costs), a, b)
        times["heapq A*"].append((time.perf_counter() - t0) * 1e3)
        baseline = [costmap.map_to_world(*c) for c in cells] + [goal]
        lengths["heapq A*"].append(path_length(baseline))
        failures += int(not path or not cells)
    reference = np.array(lengths["heapq A*"])
    row = {
        "map": name,
        "cells": [costmap.size_x, costmap.size_y],
        "resolution": costmap.resolution,
        "pairs": len(pairs),
        "failures": failures,
    }
    for key in times:
        t = np.array(times[key])
        row[key] = {
            "median_ms": float(np.median(t)),
            "p95_ms": float(np.percentile(t, 95)),
            "mean_path_m": float(np.mean(lengths[key])),
            "max_length_difference": float(
                np.max(np.abs(np.array(lengths[key]) - reference) / reference)
            ),
        }
    row["speedup_median"] = row["heapq A*"]["median_ms"] / row["navfn"]["median_ms"]
    row["speedup_p95"] = row["heapq A*"]["p95_ms"] / row["navfn"]["p95_ms"]
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="5 pairs per map")
    parser.add_argument("--pairs", type=int, default=50)
    parser.add_argument("--seed", type=int, default=SEED)
    args = parser.parse_args()
    count = 5 if args.quick else args.pairs
    machine = describe(("numpy", "scipy"), seed=args.seed, pairs=count)
    rows = [run_map(name, count, args.seed) for name in MAPS]
    print(f"machine: {machine['cpu']}, {machine['usable_cores']} usable cores, seed {args.seed}")
    header = f"{'map':<11} {'cells':>9} {'planner':<9} {'median ms':>9} {'p95 ms':>8} {'path m':>7}"
    print(header + f" {'vs A* len':>9}")
    for row in rows:
        for key in ("navfn", "navfn new", "navfn A*", "heapq A*"):
            r = row[key]
            cells = "x".join(str(c) for c in row["cells"])
            print(
                f"{row['map']:<11} {cells:>9} {key:<9} {r['median_ms']:>9.1f} "
                f"{r['p95_ms']:>8.1f} {r['mean_path_m']:>7.2f} "
                f"{100 * r['max_length_difference']:>8.1f}%"
            )
        print(
            f"{'':<11} {'':>9} heapq A* / navfn: {row['speedup_median']:.1f}x (median), "
            f"{row['speedup_p95']:.1f}x (p95); {row['pairs']} pairs, {row['failures']} "
            "without a plan"
        )
    out = ROOT / "benchmarks" / "results" / "navfn_planning.json"
    if not args.quick:
        out.write_text(json.dumps({"machine": machine, "results": rows}, indent=2) + "\n")
        print(f"wrote {out.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
