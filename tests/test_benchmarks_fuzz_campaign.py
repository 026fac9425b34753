"""benchmarks/fuzz_campaign.py: a campaign reruns a fuzz test with a fresh seed, counts its
mutants per surface, and reports a failing test as a failure (not as mutants run)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CAMPAIGN = REPO / "benchmarks" / "fuzz_campaign.py"


def _campaign(tmp_path: Path, *args: str) -> tuple[subprocess.CompletedProcess, dict]:
    out = tmp_path / "campaign.json"
    done = subprocess.run(
        [sys.executable, str(CAMPAIGN), "--json", str(out), *args],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=600,
    )
    return done, json.loads(out.read_text())


def test_a_campaign_counts_fresh_mutants_per_surface(tmp_path):
    done, result = _campaign(
        tmp_path,
        "--seeds",
        "11,12",
        "--scale",
        "0.1",
        "--tests",
        "tests/sim/test_fuzz_world_plans.py",
    )
    assert done.returncode == 0, done.stdout[-3000:]
    plans = result["surfaces"]["world build plans"]
    # 15 mutants per seed (a tenth of the suite's 150), each built or refused
    assert plans["runs"] == 30
    assert plans["built"] + plans["refused"] == 30
    assert result["failures"] == []
    assert "| world build plans | 30 |" in done.stdout


def test_a_failing_fuzz_test_is_a_failure_of_the_campaign(tmp_path):
    failing = tmp_path / "test_fails.py"
    failing.write_text("def test_fails():\n    assert 1 + 1 == 3, 'the fuzzed input broke it'\n")
    done, result = _campaign(tmp_path, "--seeds", "1", "--tests", str(failing))
    assert done.returncode == 1
    assert result["surfaces"] == {}
    assert len(result["failures"]) == 1 and "the fuzzed input broke it" in result["failures"][0]
