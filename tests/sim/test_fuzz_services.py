"""Seeded fuzzing of the Gazebo ROS API: every request gets a reply, and the simulation steps on.

Valid ``spawn_urdf_model``/``spawn_sdf_model``, ``set_model_state``, ``apply_body_wrench`` and
``apply_joint_effort`` requests are mutated (numbers made NaN, infinite, 1e308, tiny or at the
bounds; names made empty, 70,000 characters long or odd; values of the wrong type; the spawn's
model XML mutated byte by byte) and sent to one running simulator. Each mutant must end as

* a message the client refuses to build (a one-line :class:`~workbench.errors.WorkbenchError`),
* or a reply: ``success`` true, or false with a one-line Gazebo-style status;

never an exception on the server's side. After each, the simulation must still step and
answer ``get_world_properties``. Values within the bounds can still be more than a light body
takes: the physics then stops with one line naming the model, and a reset runs it again.
"""

from __future__ import annotations

import copy
import math
import random
import time
from typing import Any

from fuzz_helpers import TEXT_TOKENS, Mutator, bounded, check_one_line, fuzz_runs, fuzz_seed, report
from service_helpers import PATIENCE, running_gazebo
from sim_helpers import box_model

from workbench.errors import WorkbenchError
from workbench.msgs import from_dict
from workbench.msgs import gazebo_msgs as gm

NUMBERS: list[Any] = [math.nan, math.inf, -math.inf, 1e308, -1e308, 1e6, -1e6, 1e6 + 1]
NUMBERS += [1e4, 1e3, 1e-300, 0.0, -0.0, 5e-324, 2**63, -(2**31), 10**400, 3.5]
STRINGS: list[Any] = ["", "x" * 70000, "box", "box::body", "spin", "spinner::spin", "ground_plane"]
STRINGS += ["::", "box::", "world", "/map", "\x00", "é" * 100, "a\nb", "box::body::x"]
#: Names a spawn request does not get here: control characters, '::' and 70,000 characters
#: are the spawn name checks' (tests/sim/test_sim_spawning.py).
SPAWN_NAMES = [n for n in STRINGS if n.isprintable() and len(n) < 1000 and "::" not in n]
KEEP = ("ground_plane", "box", "spinner")
WRONG: list[Any] = [None, "abc", [1, 2], {"x": 1}, True, b"\xff"]

SPAWN_XML = box_model("fuzz", size=0.1, mass=0.5).text
SDF_XML = """<sdf version="1.6"><model name="m"><link name="l"><inertial><mass>1</mass>
<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
<collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
</link></model></sdf>"""

BASES: dict[str, tuple[Any, dict[str, Any]]] = {
    "spawn_urdf_model": (
        gm.SpawnModel,
        {
            "model_name": "fuzz",
            "model_xml": SPAWN_XML,
            "initial_pose": {"position": {"x": -2.0, "z": 0.5}, "orientation": {"w": 1.0}},
            "reference_frame": "",
        },
    ),
    "spawn_sdf_model": (
        gm.SpawnModel,
        {
            "model_name": "fuzz",
            "model_xml": SDF_XML,
            "initial_pose": {"position": {"x": -2.0, "z": 0.5}, "orientation": {"w": 1.0}},
        },
    ),
    "set_model_state": (
        gm.SetModelState,
        {
            "model_state": {
                "model_name": "box",
                "pose": {"position": {"z": 0.3}, "orientation": {"w": 1.0}},
                "twist": {"linear": {"x": 0.1}, "angular": {"z": 0.1}},
                "reference_frame": "world",
            }
        },
    ),
    "apply_body_wrench": (
        gm.ApplyBodyWrench,
        {
            "body_name": "box::body",
            "reference_frame": "",
            "reference_point": {"x": 0.0},
            "wrench": {"force": {"z": 1.0}, "torque": {"x": 0.0}},
            "start_time": {"secs": 0},
            "duration": {"nsecs": 10_000_000},
        },
    ),
    "apply_joint_effort": (
        gm.ApplyJointEffort,
        {"joint_name": "spin", "effort": 0.01, "duration": {"nsecs": 10_000_000}},
    ),
}

PREFIX = {
    "spawn_urdf_model": "SpawnModel: ",
    "spawn_sdf_model": "SpawnModel: ",
    "set_model_state": "SetModelState: ",
    "apply_body_wrench": "ApplyBodyWrench: ",
    "apply_joint_effort": "ApplyJointEffort: ",
}


def _leaves(data: Any, path: tuple = ()) -> list[tuple]:
    if isinstance(data, dict):
        return [leaf for key, value in data.items() for leaf in _leaves(value, (*path, key))]
    return [path]


def _set(data: dict[str, Any], path: tuple, value: Any) -> None:
    for key in path[:-1]:
        data = data[key]
    data[path[-1]] = value


def _fill(data: dict[str, Any], rng: random.Random) -> None:
    """Add fields the base leaves at zero, so that they can be mutated too."""
    for name in ("x", "y", "z"):
        for key in ("position",):
            pose = data.get("initial_pose") or data.get("model_state", {}).get("pose")
            if pose is not None:
                pose[key].setdefault(name, 0.0)
    wrench = data.get("wrench")
    if wrench is not None:
        for part in ("force", "torque"):
            for name in ("x", "y", "z"):
                wrench[part].setdefault(name, 0.0)


def _mutant(service: str, rng: random.Random, mutator: Mutator) -> tuple[dict[str, Any], str]:
    data = copy.deepcopy(BASES[service][1])
    _fill(data, rng)
    done = []
    for _ in range(rng.randint(1, 3)):
        path = rng.choice(_leaves(data))
        old = data
        for key in path:
            old = old[key]
        if path[-1] == "model_xml" and rng.random() < 0.7:
            text = mutator.mutate(str(old).encode()).decode("utf-8", "replace")
            _set(data, path, text)
            done.append("model_xml mutated")
            continue
        pool = STRINGS if isinstance(old, str) else NUMBERS
        if service.startswith("spawn") and path[-1] in ("model_name", "robot_namespace"):
            pool = SPAWN_NAMES
        value = rng.choice(WRONG) if rng.random() < 0.1 else rng.choice(pool)
        _set(data, path, value)
        done.append(f"{'.'.join(path)}={str(value)[:40]!r}")
    return data, "; ".join(done)


def _settle(gazebo: Any, seconds: float) -> None:
    """Wait until ``seconds`` of simulated time pass or the physics stops."""
    start = gazebo.sim_time()
    deadline = time.monotonic() + PATIENCE
    while gazebo.sim_time() < start + seconds and gazebo.server.error is None:
        assert time.monotonic() < deadline, "the simulation neither stepped nor stopped"
        time.sleep(0.005)


def test_mutated_requests_get_a_reply_and_the_simulation_steps_on():
    rng = random.Random(fuzz_seed(2811))
    mutator = Mutator(fuzz_seed(2812), TEXT_TOKENS)
    runs = fuzz_runs(200)
    outcomes = {"not_built": 0, "accepted": 0, "refused": 0, "physics_stopped": 0}
    with running_gazebo() as gazebo:
        for run in range(runs):
            service = rng.choice(sorted(BASES))
            data, what = _mutant(service, rng, mutator)
            label = f"mutant {run} ({service}: {what})"
            try:
                request = from_dict(BASES[service][0].Request, data)
            except WorkbenchError as error:
                check_one_line(error, label)
                outcomes["not_built"] += 1
                continue
            with bounded(label):
                reply = gazebo.call(service, request)
                assert isinstance(reply.success, bool), label
                status = reply.status_message
                assert "\n" not in status and "Traceback" not in status, f"{label}: {status!r}"
                if reply.success:
                    outcomes["accepted"] += 1
                else:
                    assert status.startswith(PREFIX[service]), f"{label}: {status!r}"
                    outcomes["refused"] += 1
                for name in gazebo.model_names():
                    if name not in KEEP:
                        deleted = gazebo.call(
                            "delete_model", gm.DeleteModel.Request(model_name=name)
                        )
                        assert deleted.success, f"{label}: {deleted.status_message}"
                _settle(gazebo, 0.03)  # the physics acts on what was accepted
                error = gazebo.server.error
                if error is not None:
                    assert "\n" not in error and error.startswith("model '"), f"{label}: {error}"
                    outcomes["physics_stopped"] += 1
                gazebo.clean_up()
                gazebo.assert_steps(label, seconds=0.01)
    report("gazebo_ros services", runs, **outcomes)
    assert outcomes["refused"] and outcomes["accepted"]
