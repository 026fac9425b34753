"""A campaign of fresh hostile inputs: the suite's fuzz tests, rerun with new seeds and more mutants.

The fuzz tests in the suite run a few hundred seeded mutants each, the same every run. A
campaign reruns them outside the suite with other seeds (``WORKBENCH_FUZZ_SEED``) and as many
mutants as asked (``WORKBENCH_FUZZ_SCALE`` times each test's own count), so that inputs nobody has seen before go through
the same checks: no traceback, no signal (crash), no hang, no file written or code run outside
the test's folder, and the simulator still stepping and answering after every request::

    python benchmarks/fuzz_campaign.py [--seeds 1,2,3] [--scale 1] [--tests FILE ...]
        [--json OUT]

Each (seed, test file) pair runs in its own pytest process; the tests append their counts to
a report file (``tests/fuzz_helpers.report``). Prints one row per surface: mutants run, how
they ended, and the failures (the first failing input of a test stops that test and is
printed with its assertion). Exit status 1 when any test failed.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: The fuzz tests of the surfaces a simulator, RViz and rosserial expose.
DEFAULT_TESTS = (
    "tests/sim/test_fuzz_worlds.py",
    "tests/sim/test_fuzz_plugin_trust.py",
    "tests/sim/test_fuzz_services.py",
    "tests/rviz/test_fuzz_rviz_configs.py",
    "tests/serial/test_fuzz_streams.py",
    "tests/serial/test_framing.py",
    "tests/sim/test_fuzz_world_plans.py",
)


def _run(test: str, seed: int, scale: float, report: Path, timeout: float) -> tuple[bool, str]:
    env = {k: v for k, v in os.environ.items() if k != "WORKBENCH_FUZZ_RUNS"}
    env.update(
        WORKBENCH_FUZZ_SEED=str(seed),
        WORKBENCH_FUZZ_SCALE=str(scale),
        WORKBENCH_FUZZ_REPORT=str(report),
    )
    command = [
        sys.executable,
        "-m",
        "pytest",
        "-q",
        "-x",
        "-p",
        "no:randomly",
        "-p",
        "no:cacheprovider",
        test,
    ]
    try:
        done = subprocess.run(
            command, cwd=REPO, env=env, capture_output=True, text=True, timeout=timeout
        )
    except subprocess.TimeoutExpired:
        return False, f"{test} seed {seed}: no result within {timeout:.0f} s"
    if done.returncode == 0:
        return True, ""
    failures = [line for line in done.stdout.splitlines() if line.startswith(("E ", "FAILED"))]
    return False, f"{test} seed {seed}: " + " | ".join(failures[:6])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1,2,3", help="comma-separated campaign seeds")
    parser.add_argument(
        "--scale", type=float, default=1.0, help="mutants per test, as a multiple of the suite's"
    )
    parser.add_argument("--tests", nargs="*", default=list(DEFAULT_TESTS))
    parser.add_argument("--timeout", type=float, default=3600.0, help="seconds per pytest run")
    parser.add_argument("--json", type=Path, help="write the rows and failures here")
    args = parser.parse_args(argv)
    seeds = [int(seed) for seed in args.seeds.split(",") if seed.strip()]
    failures: list[str] = []
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="fuzz-campaign-") as scratch:
        report = Path(scratch) / "report.jsonl"
        report.touch()
        for seed in seeds:
            for test in args.tests:
                ok, why = _run(test, seed, args.scale, report, args.timeout)
                print(f"seed {seed} {test}: {'passed' if ok else 'FAILED'}", flush=True)
                if not ok:
                    failures.append(why)
        lines = [json.loads(line) for line in report.read_text().splitlines() if line]
    totals: dict[str, dict[str, int]] = defaultdict(lambda: defaultdict(int))
    for line in lines:
        surface = line.pop("surface")
        line.pop("seed", None)
        for key, value in line.items():
            totals[surface][key] += int(value)
    print(f"\n{len(seeds)} seeds, {time.monotonic() - started:.0f} s")
    print("| surface | mutants | outcomes |")
    print("|---|---:|---|")
    for surface, counts in sorted(totals.items()):
        outcomes = ", ".join(f"{k} {v}" for k, v in sorted(counts.items()) if k != "runs")
        print(f"| {surface} | {counts['runs']} | {outcomes} |")
    print(f"| total | {sum(c['runs'] for c in totals.values())} | |")
    print(f"failed test runs: {len(failures)}")
    for why in failures:
        print(f"  {why}")
    if args.json:
        rows = {surface: dict(counts) for surface, counts in totals.items()}
        args.json.write_text(json.dumps({"surfaces": rows, "failures": failures}, indent=2))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
