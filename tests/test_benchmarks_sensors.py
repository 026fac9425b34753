"""benchmarks/sensors.py's accuracy checks, small: lidar and depth against closed-form geometry,
the TurtleBot3's encoder odometry over a metre."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

pytest.importorskip("pydrake")

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"


@pytest.fixture(scope="module")
def bench():  # type: ignore[no-untyped-def]
    sys.path.insert(0, str(BENCHMARKS))
    try:
        spec = importlib.util.spec_from_file_location("bench_sensors", BENCHMARKS / "sensors.py")
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        yield module
    finally:
        sys.path.remove(str(BENCHMARKS))


def test_every_beam_within_a_centimetre(bench) -> None:  # type: ignore[no-untyped-def]
    lidar = bench.lidar_accuracy()
    assert lidar["beams_hit"] == lidar["beams"] == 720
    assert lidar["within_1cm"] == 720
    assert lidar["max_error_m"] < 1e-6


def test_depth_pixels_off_silhouettes_within_a_centimetre(bench) -> None:  # type: ignore[no-untyped-def]
    depth = bench.depth_accuracy()
    assert depth["max_error_off_silhouettes_m"] < 0.01
    assert depth["within_1cm"] >= 0.999 * depth["pixels"]


def test_burger_encoder_odometry_follows_the_truth(bench) -> None:  # type: ignore[no-untyped-def]
    row = bench.odometry_drift(bench.BURGER, 1.0)
    assert row["final_drift_m"] < 0.05
    assert row["odometry_vs_kinematics_max_m"] < 0.01
    assert abs(row["wheel_over_true_path"] - 1.0) < 0.01
