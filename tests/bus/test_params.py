"""The parameter server's ROS semantics."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.bus.params import ParameterError, ParameterServer


def test_set_get_tree():
    params = ParameterServer()
    params.set("/turtlesim/background_r", 150)
    params.set("/turtlesim/background_g", 86)
    assert params.get("/turtlesim") == {"background_r": 150, "background_g": 86}
    assert params.get("/") == {"turtlesim": {"background_r": 150, "background_g": 86}}
    params.set("/turtlesim", {"background_b": 255})  # a dict replaces the subtree
    assert params.names() == ["/turtlesim/background_b"]


def test_missing_and_delete():
    params = ParameterServer()
    with pytest.raises(ParameterError, match="/nope is not set"):
        params.get("/nope")
    with pytest.raises(KeyError):
        params.get("/nope")
    params.set("/a/b", 1)
    assert params.has("/a/b") and params.has("/a")
    params.delete("/a")
    assert not params.has("/a/b")
    with pytest.raises(ParameterError):
        params.delete("/a")


def test_values_are_yaml_types():
    params = ParameterServer()
    params.set("/v", np.array([1.0, 2.0]))
    assert params.get("/v") == [1.0, 2.0]
    with pytest.raises(ParameterError, match="not a YAML value"):
        params.set("/bad", object())
    with pytest.raises(ParameterError, match="None"):
        params.set("/none", None)


def test_get_returns_a_copy():
    params = ParameterServer()
    params.set("/list", [1, 2])
    params.get("/list").append(3)
    assert params.get("/list") == [1, 2]


def test_search_walks_up():
    params = ParameterServer()
    params.set("/robot_description", "<robot/>")
    params.set("/a/b/rate", 5)
    assert params.search("/a/b/c", "robot_description") == "/robot_description"
    assert params.search("/a/b", "rate") == "/a/b/rate"
    assert params.search("/x", "rate") is None
