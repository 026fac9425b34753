from __future__ import annotations

import numpy as np
import pytest

from workbench.planning.errors import TrajectoryError
from workbench.planning.timing import time_parameterize


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_timed_path_respects_limits_and_hits_the_ends(seed):
    rng = np.random.default_rng(seed)
    waypoints = rng.uniform(-2, 2, size=(4, 6))
    vlim = rng.uniform(0.5, 2.0, 6)
    alim = rng.uniform(1.0, 5.0, 6)
    traj = time_parameterize(waypoints, vlim, alim)
    t = np.linspace(0, traj.duration, 5000)
    q, qd, qdd = traj.sample(t)
    assert np.all(np.abs(qd) <= vlim + 1e-9)
    assert np.all(np.abs(qdd) <= alim + 1e-9)
    np.testing.assert_allclose(q[0], waypoints[0], atol=1e-9)
    np.testing.assert_allclose(q[-1], waypoints[-1], atol=1e-9)
    np.testing.assert_allclose(qd[0], 0, atol=1e-6)
    np.testing.assert_allclose(qd[-1], 0, atol=1e-6)
    # the slowest joint at its limits bounds the duration from below
    lower_bound = np.max(np.abs(waypoints[-1] - waypoints[0]) / vlim)
    assert traj.duration >= lower_bound


def test_faster_limits_give_a_shorter_trajectory():
    waypoints = np.array([[0.0, 0.0], [1.0, -1.0], [2.0, 0.5]])
    slow = time_parameterize(waypoints, np.full(2, 0.5), np.full(2, 1.0))
    fast = time_parameterize(waypoints, np.full(2, 2.0), np.full(2, 4.0))
    assert fast.duration < slow.duration / 2


def test_single_point_is_a_zero_length_trajectory():
    traj = time_parameterize(np.array([[0.1, 0.2], [0.1, 0.2]]), np.ones(2), np.ones(2))
    assert traj.duration == 0.0
    q, qd, _ = traj.sample([0.0, 1.0])
    np.testing.assert_allclose(q, [[0.1, 0.2], [0.1, 0.2]])
    assert not qd.any()


def test_missing_limits_are_an_error():
    with pytest.raises(TrajectoryError, match="finite positive velocity and acceleration"):
        time_parameterize(np.array([[0.0], [1.0]]), np.array([np.inf]), np.array([1.0]))
