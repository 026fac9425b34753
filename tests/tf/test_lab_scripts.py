"""The manual's tf scripts (examples/tf) with turtlesim, as threads of one subprocess.

Each test runs ``run_lab_scripts.py`` in a fresh interpreter because rospy's
shutdown is process-wide. The scripts are the manual's code with only their
imports changed.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

HARNESS = Path(__file__).with_name("run_lab_scripts.py")
BROADCASTERS = [
    "turtle_tf_broadcaster.py:__name:=turtle1_tf_broadcaster,_turtle:=turtle1",
    "turtle_tf_broadcaster.py:__name:=turtle2_tf_broadcaster,_turtle:=turtle2",
]
CENTER = 5.544445  # where turtlesim puts turtle1


def run(seconds: float, drive: bool, *scripts: str) -> tuple[dict, str]:
    result = subprocess.run(
        [sys.executable, str(HARNESS), str(seconds), "1" if drive else "0", *scripts],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stderr[-2000:]
    out = json.loads(result.stdout.strip().splitlines()[-1])
    assert out["errors"] == [], out["errors"]
    return out, result.stdout + result.stderr


def distance(a, b) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


@pytest.mark.slow
def test_turtle2_follows_turtle1():
    """Experiment 4.3: the listener steers turtle2 onto turtle1 (which stands still here)."""
    # 10 s of wall time: enough for turtle2 to arrive even on a loaded 2-core machine
    out, _ = run(10, False, *BROADCASTERS, "turtle_tf_listener.py")
    t1, t2 = out["poses"]["turtle1"], out["poses"]["turtle2"]
    assert distance(t1, (CENTER, CENTER)) < 1e-6
    assert distance(t2, (4.0, 2.0)) > 2.5  # it left the spawn point
    assert distance(t1, t2) < 0.7


@pytest.mark.slow
def test_turtle2_follows_the_fixed_carrot():
    """Experiment 4a/4b: carrot1 is 2 m to turtle1's left; turtle2 goes there."""
    out, _ = run(
        10, False, *BROADCASTERS, "fixed_tf_broadcaster.py", "turtle_tf_listener_carrot.py"
    )
    t2 = out["poses"]["turtle2"]
    assert distance(t2, (CENTER, CENTER + 2.0)) < 0.7


@pytest.mark.slow
def test_moving_carrot_and_time_travel_listeners_run():
    """Experiment 4c and 5: the moving carrot and the 5-seconds-ago listeners run without errors."""
    out, _ = run(
        4,
        True,
        *BROADCASTERS,
        "dynamic_tf_broadcaster.py",
        "turtle_tf_listener_time_travel.py",
    )
    assert "turtle2" in out["poses"]  # spawned by the listener
    # during the first 5 s there is no 5 s history: turtle2 waits where it was spawned
    assert distance(out["poses"]["turtle2"], (4.0, 2.0)) < 1e-6


@pytest.mark.slow
def test_time_travel_full_follows_the_past_turtle1():
    """Experiment 5's answer: lookupTransformFull through /world after 5 s of history."""
    out, _ = run(8, True, *BROADCASTERS, "turtle_tf_listener_time_travel_full.py")
    t2 = out["poses"]["turtle2"]
    assert distance(t2, (4.0, 2.0)) > 0.5  # it started moving once history existed


def test_robot_setup_tf_prints_the_manual_line():
    """Additional Experiment 2: base_laser point (1, 0.2, 0) is (1.1, 0.2, 0.2) in base_link."""
    _, text = run(2.5, False, "robot_setup_tf/tf_broadcaster.py", "robot_setup_tf/tf_listener.py")
    assert "base_laser: (1.00, 0.20, 0.00) -----> base_link: (1.10, 0.20, 0.20) at time" in text
