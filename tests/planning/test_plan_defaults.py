"""`workbench plan` defaults a student expects (issue 14, item 14): a plan to home starts
elsewhere, and --to random without --seed draws a new goal each run and prints its seed."""

from __future__ import annotations

import re

import pytest


@pytest.mark.slow
def test_to_home_starts_elsewhere_and_random_goals_differ(tmp_path, run_cli):
    home = run_cli("plan", "arm3", "--to", "home", "--seed", "2", cwd=tmp_path)
    assert home.returncode == 0, home.stderr
    assert "start: random (the goal is home, the default start)" in home.stdout
    duration = float(re.search(r"duration\s+([0-9.]+) s", home.stdout).group(1))
    assert duration > 0.1  # not the zero-length path from home to home
    seeds, goals = [], []
    for _ in range(2):
        done = run_cli("plan", "arm3", "--to", "random", cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        seeds.append(
            int(re.search(r"seed: (\d+) \(repeat this run with --seed \d+\)", done.stdout).group(1))
        )
        goals.append(re.search(r"path length\s+(.*)", done.stdout).group(1))
    assert seeds[0] != seeds[1]
    again = run_cli("plan", "arm3", "--to", "random", "--seed", str(seeds[0]), cwd=tmp_path)
    assert re.search(r"path length\s+(.*)", again.stdout).group(1) == goals[0]
    assert "seed:" not in again.stdout
