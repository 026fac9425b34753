"""benchmarks/navigation.py on two goals: the burger in the simulated house, localised by amcl
on the saved map, driven by move_base to goals drawn as the benchmark draws them; and the
true map's shortest paths the driven paths are compared with."""

from __future__ import annotations

import math

import numpy as np
import pytest
from benchmark_modules import benchmark_modules

pytest.importorskip("pydrake")


@pytest.fixture(scope="module")
def modules():  # type: ignore[no-untyped-def]
    with benchmark_modules("navigation", "navigation_truth") as loaded:
        yield loaded


def test_shortest_paths_on_the_true_map_go_through_doors(modules) -> None:  # type: ignore[no-untyped-def]
    _, truth_module = modules
    truth = truth_module.house_true_map(0.105)
    assert truth.clearance_at(0.0, 0.0) > 0.5  # the living room's middle
    assert truth.clearance_at(1.0, -1.5) == 0.0  # inside the kitchen wall
    paths = truth_module.ShortestPaths(truth)
    _, pred, source = paths.from_point(0.0, 0.0)
    straight, _ = paths.path_length(pred, source, 0.0, -2.0)
    assert straight == pytest.approx(2.0, abs=0.01)
    # into the kitchen (x > 1) only through its door (x = 1, y from -1.1 to 0.1)
    length, corners = paths.path_length(pred, source, 2.0, -2.6)
    assert math.isfinite(length) and length > math.hypot(2.0, 2.6) + 0.01
    assert any(abs(x - 1.0) < 0.6 and -1.1 < y < 0.1 for x, y in corners)


@pytest.mark.slow
def test_two_goals_are_reached_without_contacts(modules) -> None:  # type: ignore[no-untyped-def]
    navigation, _ = modules
    saved = navigation.saved_map_clearance(navigation.default_map())
    stack = navigation.Stack(navigation.default_map())
    try:
        run = navigation.navigate(stack, 2, 0, saved)
        commands, end = stack.commands, stack.world.time
    finally:
        stack.close()
    alone = navigation.replay(commands, run["start_s"], end)
    summary = navigation.summarise(run, alone)
    assert summary["goals"] == 2
    assert summary["reached"] >= 1, run["rows"]
    assert summary["collisions"] == 0
    for row in run["rows"]:
        assert row["shortest_m"] >= navigation.MIN_DISTANCE - 0.05
        if row["success"]:
            assert row["driven_m"] >= row["shortest_m"] * 0.97  # never shorter than possible
            assert row["final_error_m"] <= 0.05 + navigation.SLACK
    amcl = summary["amcl"]
    assert amcl["samples"] > 10
    assert amcl["all"]["median_m"] < 0.2
    assert summary["navfn_ms"]["median"] > 0 and summary["astar_ms"]["median"] > 0
    assert np.isfinite(summary["rtf_full_stack"]) and np.isfinite(summary["rtf_sim_alone"])
