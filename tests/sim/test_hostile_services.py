"""Hostile Gazebo ROS requests (``tests/data/hostile_services/cases.yaml``) get Gazebo's refusal.

One simulator runs for the module; every case is sent to it and must get exactly the reply
the corpus records (``success`` and ``status_message``), and afterwards the simulation must
still step and answer ``get_world_properties``.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
import yaml
from service_helpers import SERVICES, running_gazebo

from workbench.msgs import from_dict

CORPUS = Path(__file__).resolve().parents[1] / "data" / "hostile_services" / "cases.yaml"
CASES = yaml.safe_load(CORPUS.read_text())


@pytest.fixture(scope="module")
def gazebo():
    with running_gazebo() as running:
        yield running


def _expand(value: Any) -> Any:
    """``{x*N}`` in a string stands for N characters 'x'."""
    if isinstance(value, dict):
        return {key: _expand(item) for key, item in value.items()}
    if isinstance(value, list):
        return [_expand(item) for item in value]
    if isinstance(value, str):
        return re.sub(r"\{(.)\*(\d+)\}", lambda m: m.group(1) * int(m.group(2)), value)
    return value


def test_the_corpus_covers_every_kind_of_request():
    services = {case["service"] for case in CASES}
    for name in ("apply_body_wrench", "apply_joint_effort", "set_model_state", "spawn_urdf_model"):
        assert name in services
    assert len({case["name"] + case["service"] for case in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=[f"{c['service']}: {c['name']}" for c in CASES])
def test_a_hostile_request_gets_its_reply_and_the_simulation_steps_on(gazebo, case):
    request = from_dict(SERVICES[case["service"]].Request, _expand(case["request"]))
    reply = gazebo.call(case["service"], request)
    assert (reply.success, reply.status_message) == (case["success"], case["status_message"])
    gazebo.assert_steps(case["name"])
    gazebo.clean_up()
    gazebo.assert_steps(f"{case['name']}, then a reset")
