"""benchmarks/navfn_planning.py, small: on the saved demo rooms every pair gets a plan from
each planner, and navfn's paths are as long as the baseline A*'s (same graph, same costs)."""

from __future__ import annotations

from benchmark_modules import benchmark_modules


def test_navfn_and_the_baseline_plan_every_pair_equally_long() -> None:
    with benchmark_modules("navfn_planning") as (bench,):
        row = bench.run_map("demo_rooms", 4, seed=3)
    assert row["pairs"] == 4 and row["failures"] == 0
    assert row["cells"] == [203, 163]
    for key in ("navfn", "navfn new", "navfn A*", "heapq A*"):
        assert row[key]["mean_path_m"] > 1.0
        assert row[key]["max_length_difference"] < 0.05, (key, row[key])
