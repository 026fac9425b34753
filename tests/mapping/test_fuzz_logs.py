"""Seeded fuzzing of laser logs (CARMEN text and gzip): read, and map what was read.

Every mutation must give a log (with one warning per skipped line) or one LogError line, and
the scans it gives must map, or be refused with one MappingError line: no ValueError from
scipy, no negative array size, no hang.
"""

from __future__ import annotations

import gzip
import math

from fuzz_helpers import TEXT_TOKENS, Mutator, WriteWatch, bounded, check_one_line, run_cli_checked

from workbench.errors import MappingError
from workbench.mapping import SlamConfig, build_map, read_log, run_slam

RUNS = 300

LOG_TOKENS = [
    *TEXT_TOKENS,
    b" nan ",
    b" inf ",
    b" -1e308 ",
    b" 1e12 ",
    b"FLASER 1000000000 ",
    b"ROBOTLASER1 0 ",
    b"PARAM robot_frontlaser_offset nan\n",
    b"\n",
]


def _seed_log() -> bytes:
    lines = ["PARAM robot_frontlaser_offset 0.1\n"]
    for i in range(12):
        ranges = " ".join(f"{2.0 + 0.3 * math.sin(k / 9.0):.3f}" for k in range(180))
        x, t = 0.05 * i, 10.0 + 0.2 * i
        lines.append(f"ODOM {x} 0 0 0 0 0 {t} host {t}\n")
        lines.append(f"FLASER 180 {ranges} {x} 0 0 {x} 0 0 {t} host {t}\n")
    return "".join(lines).encode()


def test_mutated_logs(tmp_path):
    seed = _seed_log()
    mutator = Mutator(seed=10, tokens=LOG_TOKENS)
    watch = WriteWatch(tmp_path)
    read = refused = mapped = 0
    for run in range(RUNS):
        data = mutator.mutate(seed, rounds=1 + run % 3)
        path = tmp_path / (f"log{run % 4}.log.gz" if run % 5 == 0 else f"log{run % 4}.log")
        path.write_bytes(gzip.compress(data, mtime=0) if path.suffix == ".gz" else data)
        with bounded(f"log mutation {run}"):
            try:
                log = read_log(path)
                read += 1
                assert all("\n" not in warning for warning in log.warnings)
            except MappingError as error:
                check_one_line(error, f"log mutation {run}")
                refused += 1
                continue
            if run % 10:
                continue
            try:  # a few all the way to a map: the numbers that got through must map
                result = run_slam(log.scans[:6], SlamConfig())
                build_map(log.scans[:6], result.poses, 0.05, 30.0)
                mapped += 1
            except MappingError as error:
                check_one_line(error, f"mapping mutation {run}")
    watch.check()
    assert read > 50 and refused > 5 and mapped > 3, (read, refused, mapped)


def test_mutated_logs_through_the_command_line(tmp_path):
    seed = _seed_log()
    mutator = Mutator(seed=1010, tokens=LOG_TOKENS)
    watch = WriteWatch(tmp_path)
    for run in range(3):
        path = tmp_path / f"cli{run}.log"
        path.write_bytes(mutator.mutate(seed, rounds=2))
        run_cli_checked(
            ["slam", str(path), "--out", str(tmp_path / f"map{run}"), "--quiet"], cwd=tmp_path
        )
    watch.check()
