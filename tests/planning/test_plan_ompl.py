from __future__ import annotations

import numpy as np
import pytest

from workbench.planning.errors import NoPathError, UnknownPlannerError
from workbench.planning.ompl_planner import PLANNERS, plan, planner_name


def test_planner_names():
    assert planner_name("rrtconnect") == "RRTConnect"
    assert planner_name("RRTConnectkConfigDefault") == "RRTConnect"
    assert planner_name("RRT*") == "RRTstar"
    assert planner_name("bitstar") == "BITstar"
    with pytest.raises(UnknownPlannerError, match="unknown planner 'RRTConect'.*RRTConnect"):
        planner_name("RRTConect")


def _wall(q):
    # a wall at x in [-0.1, 0.1] with a gap at y > 0.6
    return not (abs(q[0]) < 0.1 and q[1] < 0.6)


def _segment_free(a, b):
    return all(_wall(a + (b - a) * s) for s in np.linspace(0, 1, 200))


@pytest.mark.parametrize("name", ["RRTConnect", "PRM", "RRTstar", "BITstar", "KPIECE1"])
def test_planners_go_around_a_wall(name):
    lower, upper = np.full(2, -1.0), np.full(2, 1.0)
    start, goal = np.array([-0.8, -0.8]), np.array([0.8, -0.8])
    result = plan(
        lower,
        upper,
        start,
        goal,
        _wall,
        motion_valid=_segment_free,
        planner=name,
        time_limit=1.0,
        seed=1,
    )
    assert result.planner == name
    np.testing.assert_allclose(result.path[0], start)
    np.testing.assert_allclose(result.path[-1], goal)
    for a, b in zip(result.path[:-1], result.path[1:], strict=True):
        assert _segment_free(a, b)
    assert np.max(result.path[:, 1]) > 0.6  # through the gap
    length = np.linalg.norm(np.diff(result.path, axis=0), axis=1).sum()
    raw = np.linalg.norm(np.diff(result.raw_path, axis=0), axis=1).sum()
    assert length <= raw + 1e-9


def test_ompl_discrete_validator_when_no_motion_callable():
    calls = []

    def valid(q):
        calls.append(q)
        return _wall(q)

    result = plan(
        np.full(2, -1.0),
        np.full(2, 1.0),
        np.array([-0.8, -0.8]),
        np.array([0.8, -0.8]),
        valid,
        resolution=0.005,
        time_limit=0.5,
    )
    assert len(result.path) >= 3
    assert len(calls) > 100


def test_no_path_within_the_time_limit():
    def closed(q):
        return not abs(q[0]) < 0.1

    with pytest.raises(NoPathError, match="no path within the time limit of 0.05 s"):
        plan(
            np.full(2, -1.0),
            np.full(2, 1.0),
            np.array([-0.8, 0.0]),
            np.array([0.8, 0.0]),
            closed,
            time_limit=0.05,
        )


def test_all_planner_names_exist_in_ompl():
    import ompl.geometric as og

    for name in PLANNERS:
        assert hasattr(og, name), name


def test_shortcut_never_lengthens_and_stays_valid():
    from workbench.planning.ompl_planner import shortcut

    path = np.array([[-0.8, -0.8], [-0.8, 0.0], [-0.5, 0.8], [0.0, 0.8], [0.5, 0.8], [0.8, -0.8]])
    out = shortcut(path, _segment_free)
    np.testing.assert_allclose(out[0], path[0])
    np.testing.assert_allclose(out[-1], path[-1])
    assert len(out) < len(path)
    for a, b in zip(out[:-1], out[1:], strict=True):
        assert _segment_free(a, b)

    def length(p):
        return np.linalg.norm(np.diff(p, axis=0), axis=1).sum()

    assert length(out) < length(path)
