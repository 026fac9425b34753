"""The simulator's bounds (:mod:`workbench.sim.bounds`): what a world or spawn may ask for.

The hostile worlds themselves are in ``tests/data/hostile/worlds`` and the spawn requests
in ``test_spawn_hostile.py``; here, the rules the bounds follow and that real worlds
(a map traced into walls, the lab's shipped worlds) stay within them.
"""

from __future__ import annotations

import pytest

from workbench.errors import SimulationError
from workbench.sim import World
from workbench.sim.bounds import (
    MAX_STATIC_LINKS,
    MAX_WORLD_LINKS,
    check_step_size,
    model_links,
    namespace_problem,
    spawn_request_problem,
)
from workbench.sim.gazebo_sdf import sim_model_from_sdf
from workbench.sim.server import SERVER_PHYSICS
from workbench.sim.world_file import load_world, shipped_worlds


def _row(name: str, links: int, *, static: bool = False):
    body = "".join(
        f'<link name="l{i}"><pose>{0.2 * i} 0 0.05 0 0 0</pose><inertial><mass>1</mass>'
        "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>"
        for i in range(links)
    )
    text = f'<sdf version="1.6"><model name="{name}"><static>{str(static).lower()}</static>'
    return sim_model_from_sdf(text + body + "</model></sdf>", name=None, source="test")


def test_moving_links_are_bounded_for_the_whole_world_and_the_world_stays_as_it_was():
    world = World(**SERVER_PHYSICS)
    world.add_model(_row("a", 300))
    with pytest.raises(SimulationError) as caught:
        world.add_model(_row("b", 300))
    assert caught.value.message == (
        "model 'b' has 300 links; the world has 300, the simulator holds at most "
        f"{MAX_WORLD_LINKS} links of moving models"
    )
    assert world.model_names() == ["ground_plane", "a"]
    world.add_model(_row("walls", 600, static=True))  # static links count apart
    assert model_links(world.models["walls"].model.text) == 600


def test_a_map_traced_into_walls_stays_within_the_static_bound(repo_root, tmp_path):
    from workbench.sim.building import plan_from_image

    path = tmp_path / "intel.world"
    plan_from_image(repo_root / "mapping" / "intel_lab.yaml").save(path)
    world = load_world(path)
    links = sum(model_links(item.model.text) for item in world.models)
    assert MAX_WORLD_LINKS < links <= MAX_STATIC_LINKS


def test_the_shipped_worlds_are_far_inside_the_bounds():
    for name in shipped_worlds():
        world = load_world(name)
        assert len(world.models) <= 20
        assert sum(model_links(item.model.text) for item in world.models) <= 50


@pytest.mark.parametrize("step", [1e-300, 1e-5, 0.0, -0.001, 0.5, float("nan"), float("inf")])
def test_physics_steps_outside_100_us_to_100_ms_are_refused(step):
    with pytest.raises(SimulationError, match=r"must be in \[0.0001, 0.1\] s"):
        check_step_size(step, "<max_step_size>")


def test_spawn_requests_are_checked_before_their_model_is_read():
    box = '<robot name="b"><link name="l"/></robot>'
    assert spawn_request_problem("box", "/robot1", box) is None
    assert spawn_request_problem("", "", box) is None
    assert "has 100,000 characters" in spawn_request_problem("n" * 100_000, "", box)
    assert "'a\\nb' contains the control character" in spawn_request_problem("a\nb", "", box)
    assert namespace_problem("/ns/" + "n" * 300) == "has 304 characters; at most 256"
    assert namespace_problem("a b") == "contains ' ', which a ROS name cannot hold"
    chain = "<robot name='c'>" + "<link name='l'/>" * (MAX_WORLD_LINKS + 1) + "</robot>"
    assert spawn_request_problem("c", "", chain) == (
        f"the model has {MAX_WORLD_LINKS + 1} links; a spawned model has at most {MAX_WORLD_LINKS}"
    )


@pytest.mark.parametrize("step", [1e-4, 0.001, 0.008, 0.1])
def test_the_steps_worlds_use_are_accepted(step):
    check_step_size(step, "<max_step_size>")
