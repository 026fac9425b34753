"""The building editor from a YAML plan: walls split around openings, levels, stairs, furniture, SDF."""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml
from building_helpers import clearance, distances, world_from_file
from lxml import etree

from workbench.sim.building import BuildingPlan, load_plan, parse_colour, plan_from_dict

ROOM = """
name: room
height: 2.5
thickness: 0.2
walls:
  - name: south
    start: [0, 0]
    end: [6, 0]
    colour: [1, 0, 0]
    doors: [{name: door, at: 2, width: 1.0, height: 2.0}]
    windows: [{name: window, at: 4.5, width: 1.0, height: 1.0, sill: 0.8}]
  - {name: east, start: [6, 0], end: [6, 4]}
  - {name: north, start: [6, 4], end: [0, 4], colour: Blue}
  - {name: west, start: [0, 4], end: [0, 0]}
furniture:
  - {name: table, type: table, at: [3, 2], size: [1.2, 0.8, 0.75]}
  - {name: bin, type: cylinder, at: [5, 3], radius: 0.2, height: 0.6}
"""


def _plan(tmp_path, text: str = ROOM, name: str = "room.yaml") -> BuildingPlan:
    path = tmp_path / name
    path.write_text(text)
    return load_plan(path)


def _boxes(sdf: str, link: str) -> list[tuple[list[float], list[float]]]:
    """(size, pose) of every collision box of ``link``, in document order."""
    root = etree.fromstring(sdf.encode())
    (element,) = [e for e in root.iter("link") if e.get("name") == link]
    found = []
    for collision in element.iter("collision"):
        size = [float(v) for v in collision.findtext("geometry/box/size").split()]
        pose = [float(v) for v in collision.findtext("pose").split()]
        found.append((size, pose))
    return found


def test_a_wall_is_split_around_its_door_and_window(tmp_path):
    plan = _plan(tmp_path)
    sdf = plan.to_sdf()
    boxes = _boxes(sdf, "south")
    # square ends reach 0.1 m past both ends: the wall runs from x = -0.1 to 6.1
    expected = [
        ([1.6, 0.2, 2.5], [0.7, 0, 1.25]),  # -0.1 .. 1.5, full height
        ([1.0, 0.2, 0.5], [2.0, 0, 2.25]),  # above the door: 2.0 .. 2.5
        ([1.5, 0.2, 2.5], [3.25, 0, 1.25]),  # 2.5 .. 4.0, between the openings
        ([1.0, 0.2, 0.8], [4.5, 0, 0.4]),  # below the window's sill
        ([1.0, 0.2, 0.7], [4.5, 0, 2.15]),  # above the window: 1.8 .. 2.5
        ([1.1, 0.2, 2.5], [5.55, 0, 1.25]),  # 5.0 .. 6.1
    ]
    assert len(boxes) == len(expected)
    for (size, pose), (want_size, want_xyz) in zip(boxes, expected, strict=True):
        np.testing.assert_allclose(size, want_size, atol=1e-9)
        np.testing.assert_allclose(pose[:3], want_xyz, atol=1e-9)
        assert pose[3:] == [0, 0, 0]
    # a wall drawn from (6, 4) to (0, 4) points along -x
    ((size, pose),) = _boxes(sdf, "north")
    np.testing.assert_allclose(size, [6.2, 0.2, 2.5])
    np.testing.assert_allclose(pose, [3, 4, 1.25, 0, 0, math.pi], atol=1e-6)
    ((size, pose),) = _boxes(sdf, "east")
    np.testing.assert_allclose(pose, [6, 2, 1.25, 0, 0, math.pi / 2], atol=1e-6)


def test_the_building_is_static_and_coloured_and_furniture_are_models(tmp_path):
    root = etree.fromstring(_plan(tmp_path).to_sdf().encode())
    models = {m.get("name"): m for m in root.iter("model")}
    assert list(models) == ["room", "table", "bin"]
    assert all(m.findtext("static") == "true" for m in models.values())
    south = next(lk for lk in root.iter("link") if lk.get("name") == "south")
    assert {v.findtext("material/diffuse") for v in south.iter("visual")} == {"1 0 0 1"}
    north = next(lk for lk in root.iter("link") if lk.get("name") == "north")
    assert north.findtext("visual/material/diffuse") == "0 0 1 1"  # Gazebo/Blue
    assert len(list(models["table"].iter("collision"))) == 5  # a top on four legs
    assert models["bin"].find("link/collision/geometry/cylinder") is not None
    model = etree.fromstring(_plan(tmp_path).to_sdf("model").encode())
    assert model.tag == "sdf" and model.find("world") is None
    assert [m.get("name") for m in model.iter("model")] == ["room"]
    assert {lk.get("name") for lk in model.iter("link")} >= {"south", "table", "bin"}


def test_the_world_loads_and_drake_sees_the_walls_door_gap_and_window_sill(tmp_path, caplog):
    path = tmp_path / "room.world"
    _plan(tmp_path).save(path)
    world = world_from_file(path, caplog)
    assert set(world.models) == {"room", "table", "bin"}
    # inside the wall, beside the door
    assert distances(world, [1.0, 0.0, 1.0])["room::south_0"] < 0
    # the doorway: a robot of radius 0.45 m fits at any height up to 1.5 m
    for z in (0.1, 0.5, 1.0, 1.5):
        assert clearance(world, [2.0, 0.0, z]) >= 0.45
    # above the door, the lintel
    assert clearance(world, [2.0, 0.0, 2.2]) < 0
    # the window: wall below the sill, a hole in it, wall above it
    assert clearance(world, [4.5, 0.0, 0.4]) < 0
    assert clearance(world, [4.5, 0.0, 1.3]) >= 0.45
    assert clearance(world, [4.5, 0.0, 2.2]) < 0
    # the corners are closed
    assert clearance(world, [0.0, 0.0, 1.0]) < 0 and clearance(world, [6.0, 4.0, 1.0]) < 0
    # the table's top is at 0.75 m and its legs leave room under it
    assert distances(world, [3.0, 2.0, 0.74])["table::table_top"] < 0
    assert clearance(world, [3.0, 2.0, 0.3]) > 0.2


def test_levels_have_slabs_with_a_stairwell_and_stairs_climb_between_them(tmp_path, caplog):
    text = """
name: two_storey
levels:
  - name: ground
    walls:
      - name: outer
        points: [[0, 0], [6, 0], [6, 4], [0, 4]]
        closed: true
        doors: [{name: front, at: 3, width: 1.0}]
        windows: [{name: w1, at: 8, width: 1.2, sill: 0.9}]
  - name: first
    elevation: 2.5
    height: 2.4
    floor: {min: [0, 0], max: [6, 4], thickness: 0.2}
    walls:
      - {name: up_south, start: [0, 0], end: [6, 0]}
stairs:
  - {name: stairs, from: ground, to: first, start: [1, 1], direction: 0, width: 1.0,
     length: 3.0, steps: 10}
"""
    plan = _plan(tmp_path, text)
    assert [w.name for w in plan.walls] == ["outer_0", "outer_1", "outer_2", "outer_3", "up_south"]
    # 'at' runs along the chain: 8 m is 2 m up the east side
    assert plan.walls[1].openings[0].at == pytest.approx(2.0)
    path = tmp_path / "two.world"
    plan.save(path)
    world = world_from_file(path, caplog)
    room = "two_storey::"
    # the upper walls stand on the first level
    assert distances(world, [3.0, 0.0, 3.0])[room + "up_south_0"] < 0
    assert clearance(world, [3.0, 0.0, 2.45]) < 0  # inside the slab
    # the slab is 0.2 m thick under the first level, with a hole over the stairs
    assert clearance(world, [5.0, 3.0, 2.4]) < 0
    assert clearance(world, [3.0, 1.0, 2.4]) > 0
    # ten steps of 0.25 m: the last one reaches the first level
    steps = [d for name, d in distances(world, [3.9, 1.0, 2.49]).items() if "stairs_step" in name]
    assert min(steps) < 0
    assert clearance(world, [1.1, 1.0, 0.2]) < 0 and clearance(world, [1.1, 1.0, 0.3]) > 0
    # the window is 2 m along the east wall
    assert clearance(world, [6.0, 2.0, 1.4]) > 0.4 and clearance(world, [6.0, 2.0, 0.5]) < 0


def test_polyline_openings_may_not_reach_round_a_corner(tmp_path):
    text = "walls: [{name: l, points: [[0, 0], [4, 0], [4, 3]], doors: [{at: 3.8, width: 0.9}]}]"
    with pytest.raises(
        Exception, match=r"wall 'l': door 'l_door_0' reaches round the corner at \(4, 0\)"
    ):
        _plan(tmp_path, text)


def test_json_plans_and_plans_from_dicts_are_the_same(tmp_path):
    doc = yaml.safe_load(ROOM)
    import json

    from_json = _plan(tmp_path, json.dumps(doc), "room.json")
    from_dict = plan_from_dict(doc, name="room")
    assert from_json.pieces() == from_dict.pieces()
    assert from_json.summary() == (
        "building 'room': 1 level, 4 walls, 1 door, 1 window, 0 flights of stairs, "
        "2 pieces of furniture"
    )


def test_colours(tmp_path):
    assert parse_colour("#ff8000", "x") == pytest.approx((1.0, 128 / 255, 0.0, 1.0))
    assert parse_colour("Gazebo/Wood", "x") == parse_colour("wood", "x")
    assert parse_colour([0.1, 0.2, 0.3, 0.5], "x") == (0.1, 0.2, 0.3, 0.5)
    with pytest.raises(Exception, match="colour 'plaid' is not"):
        parse_colour("plaid", "wall 'w'")


def test_narrow_doors_are_noted(tmp_path):
    text = "walls: [{name: w, start: [0, 0], end: [3, 0], doors: [{name: d, at: 1, width: 0.6}]}]"
    assert _plan(tmp_path, text).notes() == ["door 'd' of wall 'w' is 0.6 m wide (under 0.8 m)"]
