"""benchmarks/amcl.py, small: its route stays in free space, the vectorised likelihood field
equals amcl's loop, and a short run on each map converges and writes its JSON."""

from __future__ import annotations

import json

import numpy as np
from benchmark_modules import benchmark_modules

from workbench.navigation.amcl_map import FREE


def test_the_route_keeps_its_clearance_in_free_space():
    with benchmark_modules("amcl") as (bench,):
        m = bench.load("intel_lab")
        truth = bench.route(m, 20.0, seed=2)
    i, j, valid = m.cells_of(truth[:, 0], truth[:, 1])
    assert valid.all() and (m.states[j, i] == FREE).all()
    steps = np.hypot(*np.diff(truth[:, :2], axis=0).T)
    assert steps.max() <= 0.051 and steps.sum() >= 20.0


def test_a_short_run_converges_and_the_loop_agrees(tmp_path, capsys, monkeypatch):
    out = tmp_path / "amcl.json"
    with benchmark_modules("amcl") as (bench,):
        monkeypatch.setattr(bench, "MAPS", {"demo_rooms": bench.MAPS["demo_rooms"]})
        monkeypatch.setattr(bench, "PARTICLES", (500,))
        assert bench.main(["--quick", "--out", str(out)]) == 0
    result = json.loads(out.read_text())
    biased, unbiased = result["accuracy"]
    assert (biased["odometry_scale"], unbiased["odometry_scale"]) == (1.03, 1.0)
    for row in (biased, unbiased):
        assert row["first_error_m"] > 0.5 and row["converged_after_m"] < 5.0
        assert row["mean_error_m"] <= 0.1 and row["odometry_max_error_m"] > row["max_error_m"]
    (timing,) = result["speed"]
    assert timing["same_values"] and timing["loop_ratio"] > 1.0
    assert "Update time per scan" in capsys.readouterr().out
