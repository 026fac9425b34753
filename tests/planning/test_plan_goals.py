from __future__ import annotations

import numpy as np
import pytest

from workbench.planning.errors import GoalError
from workbench.planning.goals import (
    JointGoal,
    NamedGoal,
    PositionGoal,
    RandomGoal,
    check_limits,
    parse_goal,
    random_valid_state,
)


def test_parse_goal_forms():
    assert parse_goal("home") == NamedGoal("home")
    assert parse_goal("random") == RandomGoal()
    assert parse_goal("q=0, 0.5,-1") == JointGoal((0.0, 0.5, -1.0))
    assert parse_goal("xyz=0.3,0.1,0.4") == PositionGoal((0.3, 0.1, 0.4))
    assert parse_goal("xyz=0.3,0.1,0.4,rpy=0,1.57,0") == PositionGoal(
        (0.3, 0.1, 0.4), (0.0, 1.57, 0.0)
    )


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("q=a,b", "comma-separated numbers"),
        ("xyz=1,2", "needs 3 numbers"),
        ("q=", "finite numbers"),
        ("q=nan,1", "finite numbers"),
        ("foo=1", "cannot read goal"),
        ("", "empty goal"),
    ],
)
def test_bad_goal_text(text, message):
    with pytest.raises(GoalError, match=message):
        parse_goal(text)


def test_check_limits_names_the_joint():
    check_limits(["a", "b"], np.array([0.0, 1.0]), np.array([-1, -1]), np.array([1, 1]), "goal")
    with pytest.raises(GoalError, match="joint 'b' = 1.5000 is outside its limits"):
        check_limits(["a", "b"], np.array([0.0, 1.5]), np.array([-1, -1]), np.array([1, 1]), "goal")


def test_random_valid_state_is_seeded_and_valid():
    def free(q):
        return np.linalg.norm(q) > 0.5

    a = random_valid_state(np.full(2, -1.0), np.full(2, 1.0), free, seed=3)
    b = random_valid_state(np.full(2, -1.0), np.full(2, 1.0), free, seed=3)
    np.testing.assert_array_equal(a, b)
    assert free(a)
    with pytest.raises(GoalError, match="no collision-free random state"):
        random_valid_state(np.zeros(2), np.ones(2), lambda q: False, seed=0, attempts=10)
