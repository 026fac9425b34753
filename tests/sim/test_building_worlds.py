"""The shipped worlds made with the building editor: they load by name, a robot can drive in them."""

from __future__ import annotations

import math

import numpy as np
import pytest
from building_helpers import cell_of, clearance, occupancy, reachable, world_from_file

from workbench.sim.building import load_plan
from workbench.sim.world_file import load_world, shipped_worlds

BUILT = ("arena", "house", "lab_room")


@pytest.mark.parametrize("name", BUILT)
def test_each_shipped_world_is_its_plan_built_and_loads_by_name(repo_root, name, caplog):
    assert name in shipped_worlds()
    plan = load_plan(repo_root / "mapping" / "plans" / f"{name}.yaml")
    shipped = repo_root / "mapping" / "worlds" / f"{name}.world"
    assert shipped.read_text() == plan.to_sdf(), (
        f"rebuild it: workbench world build mapping/plans/{name}.yaml -o {shipped.name}"
    )
    world_file = load_world(name)
    assert world_file.name == name and world_file.ground_plane and world_file.plugins == []
    assert all(item.model.static for item in world_file.models)
    world = world_from_file(name, caplog)
    assert world.model_names()[0] == "ground_plane" and name in world.model_names()


@pytest.mark.parametrize("name", sorted(shipped_worlds()))
def test_every_shipped_world_loads_without_warnings(name, caplog):
    world = world_from_file(name, caplog)
    assert world.model_names()[0] == "ground_plane"


def test_workbench_sim_serves_a_built_world_by_name():
    from workbench.sim.gzserver import ServerOptions, build_server

    world, server, view = build_server(ServerOptions(world="house", view=False, fast=True))
    try:
        assert view is None
        assert {"house", "sofa", "dining_table", "bed"} <= set(world.model_names())
        server.run(until=0.05)
        assert world.time == pytest.approx(0.05)
    finally:
        server.stop()


def test_the_house_has_rooms_a_robot_can_drive_between(repo_root):
    plan = load_plan(repo_root / "mapping" / "plans" / "house.yaml")
    doors = [o for wall in plan.walls for o in wall.openings if o.kind == "door"]
    assert len(doors) == 6 and min(d.width for d in doors) >= 0.8
    assert plan.notes() == []
    assert [level.elevation for level in plan.levels] == [0.0] and plan.stairs == []
    blocked, xs, ys = occupancy(plan.pieces(), (-6.0, -5.0), (6.0, 5.0))
    # a robot 0.4 m across (a TurtleBot3 Waffle) from the origin, in the living room
    free = reachable(blocked, xs, ys, (0.0, 0.0), robot_radius=0.22)
    rooms = {
        "living room": (-2.5, -2.5),
        "kitchen": (3.0, -2.0),
        "bedroom": (-2.0, 2.0),
        "bathroom": (0.3, 1.8),
        "study": (2.5, 2.0),
        "garden, through the front door": (-2.0, -4.7),
        "garden, through the back door": (5.7, -2.5),
    }
    for room, point in rooms.items():
        assert free[cell_of(xs, ys, point)], f"cannot drive to the {room}"
    # the footprint is 10 m x 8 m
    walls = [p for p in plan.pieces() if not p.furniture]
    corners = [
        (p.pose[0] + sx * p.size[0] / 2 * abs(math.cos(p.pose[3])) + sx * p.size[1] / 2 * abs(math.sin(p.pose[3])),
         p.pose[1] + sy * p.size[0] / 2 * abs(math.sin(p.pose[3])) + sy * p.size[1] / 2 * abs(math.cos(p.pose[3])))
        for p in walls for sx in (-1, 1) for sy in (-1, 1)
    ]  # fmt: skip
    xs_, ys_ = [c[0] for c in corners], [c[1] for c in corners]
    assert max(xs_) - min(xs_) == pytest.approx(10.2) and max(ys_) - min(ys_) == pytest.approx(8.2)


def test_the_arena_is_closed_with_a_grid_of_pillars(repo_root, caplog):
    plan = load_plan(repo_root / "mapping" / "plans" / "arena.yaml")
    pillars = [p for p in plan.pieces() if p.shape == "cylinder"]
    assert sorted((p.pose[0], p.pose[1]) for p in pillars) == [
        (x, y) for x in (-1.1, 0.0, 1.1) for y in (-1.1, 0.0, 1.1)
    ]
    blocked, xs, ys = occupancy(plan.pieces(), (-3.0, -3.0), (3.0, 3.0), cell=0.025)
    free = reachable(blocked, xs, ys, (-1.6, -0.5), robot_radius=0.1)
    assert free[cell_of(xs, ys, (1.6, 0.5))]  # across the arena, between the pillars
    assert free[cell_of(xs, ys, (0.55, 0.55))]
    assert not free[cell_of(xs, ys, (2.8, 2.8))]  # the wall is closed
    world = world_from_file("arena", caplog)
    # 4 m across: the flat sides' inner faces are 3.98 - 0.1 m apart
    assert clearance(world, [0.0, 1.9, 0.2]) == pytest.approx(1.99186 - 0.05 - 1.9, abs=1e-4)
    assert clearance(world, [-1.6, -0.5, 0.2]) > 0.2


def test_the_lab_room_has_room_for_custom_bot(repo_root, caplog):
    plan = load_plan(repo_root / "mapping" / "plans" / "lab_room.yaml")
    world = world_from_file("lab_room", caplog)
    assert clearance(world, [0.0, 0.0, 0.1]) > 1.0  # where custom_bot spawns
    blocked, xs, ys = occupancy(plan.pieces(), (-3.5, -3.0), (3.5, 3.0))
    # custom_bot is 0.6 m x 0.3 m: a disc of 0.34 m covers it turning on the spot
    free = reachable(blocked, xs, ys, (0.0, 0.0), robot_radius=0.34)
    for point in [(2.2, 1.5), (-2.4, -1.5), (-2.4, 1.5), (2.4, -1.5), (1.5, -3.0)]:
        assert free[cell_of(xs, ys, point)], point
    inside = (np.abs(xs[None, :]) < 3) & (np.abs(ys[:, None]) < 2)
    assert free[inside].mean() > 0.4
