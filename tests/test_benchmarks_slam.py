"""benchmarks/slam.py's helpers: a measured child process (CPU, peak memory, timeout) and the
per-method summary (median, spread, failed runs, ratios to workbench)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from benchmark_modules import benchmark_modules


@pytest.fixture(scope="module")
def modules():  # type: ignore[no-untyped-def]
    with benchmark_modules("child_process", "slam_tables") as modules:
        yield modules


def test_child_cpu_and_memory_are_its_own(modules, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    child_process, _ = modules
    work = "import sys; b = bytearray(200 * 2**20); sum(range(3 * 10**6)); print('done')"
    done = child_process.run_measured([sys.executable, "-c", work], tmp_path, timeout=600)
    assert (done.returncode, done.timed_out) == (0, False)
    assert done.peak_mb > 200
    assert done.cpu_s > 0
    assert (tmp_path / "stdout.txt").read_text() == "done\n"


def test_child_over_time_is_stopped(modules, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    child_process, _ = modules
    done = child_process.run_measured(
        [sys.executable, "-c", "import time; time.sleep(600)"], tmp_path, timeout=0.5
    )
    assert done.timed_out
    assert done.returncode == -9


def row(method: str, ate: float | None, cpu: float = 1.0, **extra):  # type: ignore[no-untyped-def]
    rel = None if ate is None else {"trans_mean": ate / 10, "rot_mean": 1.0}
    return {"method": method, "ate": ate, "rel_1m": rel, "cpu_s": cpu, "peak_mb": 100.0, **extra}


def test_summary_median_spread_failures_and_ratios(modules, capsys) -> None:  # type: ignore[no-untyped-def]
    _, tables = modules
    rows = [
        row("workbench", 0.1, cpu=10.0),
        row("workbench", 0.2, cpu=30.0),
        row("MRPT rbpf-slam", 0.5, cpu=40.0, rbpf_seed=0),
        row("MRPT rbpf-slam", None, status="timeout after 5 s", rbpf_seed=1),
        row("MRPT rbpf-slam", 1.5, cpu=60.0, rbpf_seed=2),
    ]
    ours, rbpf = tables.summarise(rows)
    assert (ours["runs"], ours["failed"], ours["ate_median"]) == (2, 0, pytest.approx(0.15))
    assert (rbpf["runs"], rbpf["failed"]) == (3, 1)
    assert (rbpf["ate_min"], rbpf["ate_median"], rbpf["ate_max"]) == (0.5, 1.0, 1.5)
    assert rbpf["ate_median_ratio_to_workbench"] == pytest.approx(1.0 / 0.15)
    assert rbpf["cpu_ratio_to_workbench"] == pytest.approx(50.0 / 20.0)
    tables.print_summary([ours, rbpf])
    lines = capsys.readouterr().out.splitlines()
    assert "1.000 [0.500-1.500]" in lines[2] and "(1 failed)" in lines[2]
    assert tables.label(rows[3]) == "MRPT rbpf-slam (1)"


def test_summary_groups_by_level(modules) -> None:  # type: ignore[no-untyped-def]
    _, tables = modules
    rows = [
        row("workbench", 0.1, level="low"),
        row("MRPT icp-slam", None, level="low", status="failed: exit code 1: boom"),
        row("workbench", 0.3, level="high"),
    ]
    summary = tables.summarise(rows, "level")
    assert [(s["level"], s["method"]) for s in summary] == [
        ("low", "workbench"),
        ("low", "MRPT icp-slam"),
        ("high", "workbench"),
    ]
    assert summary[1] == {"level": "low", "method": "MRPT icp-slam", "runs": 1, "failed": 1}
