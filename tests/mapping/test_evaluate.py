"""Trajectory metrics and the odometry noise model used by the benchmark."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping.evaluate import (
    NOISE_LEVELS,
    absolute_trajectory_error,
    noisy_odometry,
    relations,
    relative_error,
)
from workbench.mapping.geometry import compose
from workbench.mapping.simulate import loop_trajectory


def test_zero_noise_reproduces_the_reference_and_noise_is_seeded():
    ref = loop_trajectory()
    np.testing.assert_allclose(noisy_odometry(ref, (0, 0, 0, 0), seed=1), ref, atol=1e-9)
    a = noisy_odometry(ref, NOISE_LEVELS["middle"], seed=4)
    b = noisy_odometry(ref, NOISE_LEVELS["middle"], seed=4)
    c = noisy_odometry(ref, NOISE_LEVELS["middle"], seed=5)
    np.testing.assert_array_equal(a, b)
    assert np.abs(a - c).max() > 1e-3


def test_noise_grows_with_the_level():
    ref = loop_trajectory()
    errors = [
        absolute_trajectory_error(noisy_odometry(ref, NOISE_LEVELS[level], seed=0), ref)
        for level in ("low", "middle", "high")
    ]
    assert errors[0] < errors[1] < errors[2]


def test_ate_ignores_a_rigid_offset_and_relative_error_ignores_it_too():
    ref = loop_trajectory()
    moved = compose(np.array([3.0, -1.0, 0.7])[None], ref)
    assert absolute_trajectory_error(moved, ref) == pytest.approx(0.0, abs=1e-9)
    rel = relative_error(moved, ref, relations(ref, 1.0))
    assert rel["trans_mean"] == pytest.approx(0.0, abs=1e-9)
    bent = ref.copy()
    bent[40:, 0] += 0.1  # a 10 cm jump between poses 39 and 40
    rel = relative_error(bent, ref, relations(ref, 1.0))
    assert rel["trans_mean"] > 0.0 and rel["pairs"] == len(relations(ref, 1.0))


def test_relations_pair_poses_a_fixed_path_distance_apart():
    ref = np.column_stack([np.arange(11) * 0.5, np.zeros(11), np.zeros(11)])
    assert relations(ref, 1.0)[:3] == [(0, 2), (1, 3), (2, 4)]
    assert relations(ref, 1.0)[-1] == (8, 10)
