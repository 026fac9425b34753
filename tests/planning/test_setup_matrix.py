"""The self-collision matrix follows MoveIt's rules on a robot built to show each reason."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.planning.collision_matrix import (
    SelfCollisionProbe,
    compute_collision_matrix,
    default_state,
)


@pytest.fixture(scope="module")
def probe(data_dir):
    return SelfCollisionProbe(data_dir / "planning" / "matrix_test.urdf")


@pytest.fixture(scope="module")
def matrix(probe):
    return compute_collision_matrix(probe, samples=1000, seed=3)


def test_every_reason(matrix):
    r = matrix.reasons
    assert "hub" not in matrix.links  # no collision geometry, so not in the matrix
    assert r[("base", "boom")] == "Adjacent"  # through the geometry-less hub
    assert r[("base", "mount")] == "Adjacent"
    assert r[("base", "plate")] == "Default"
    assert r[("slider", "stop")] == "Always"
    assert r[("slider2", "stop2")] is None
    assert r[("base", "far")] == "Never"
    assert matrix.enabled() == [("slider2", "stop2")]
    assert matrix.summary() == {
        "Adjacent": 8,
        "Default": 1,
        "Always": 1,
        "Never": 25,
        "Check": 1,
        "Total": 36,
    }
    fraction = {(row["link1"], row["link2"]): row["collision_fraction"] for row in matrix.rows()}
    assert 0.35 < fraction[("slider2", "stop2")] < 0.65


def test_disabled_pairs_are_sorted_srdf_entries(matrix):
    disabled = matrix.disabled()
    assert len(disabled) == 35
    assert all(d.link1 < d.link2 for d in disabled)
    assert [(d.link1, d.link2) for d in disabled] == sorted((d.link1, d.link2) for d in disabled)


def test_seeded_and_repeatable(probe, matrix):
    again = compute_collision_matrix(probe, samples=1000, seed=3)
    assert again.reasons == matrix.reasons and again.counts == matrix.counts
    other = compute_collision_matrix(probe, samples=1000, seed=4)
    assert other.counts != matrix.counts


def test_probe_sees_filtered_pairs(probe):
    # Drake filters welded and adjacent bodies; the probe lifts those filters.
    q = default_state(probe.lower, probe.upper)
    pairs = probe.colliding_pairs(q)
    assert ("base", "plate") in pairs
    q_slide = q.copy()
    q_slide[probe.robot.joint_names.index("slide_joint")] = 0.5
    assert ("slider", "stop") in probe.colliding_pairs(q_slide)
    assert ("slider", "stop") not in pairs


def test_default_state_rule():
    lower = np.array([-1.0, 0.5, -np.inf, -2.0])
    upper = np.array([1.0, 1.5, np.inf, -1.0])
    assert default_state(lower, upper).tolist() == [0.0, 1.0, 0.0, -1.5]
