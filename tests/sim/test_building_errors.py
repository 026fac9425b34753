"""Bad plans and images: one line naming the element and what to do, never a traceback."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping.pgm import write_pgm
from workbench.sim.building import PlanError, load_plan, plan_from_image


def _walls(*walls: str) -> str:
    return "walls:\n" + "".join(f"  - {w}\n" for w in walls)


BAD_PLANS = [
    (
        _walls("{name: a, start: [0, 0], end: [4, 0]}", "{name: b, start: [2, 2], end: [2, 2]}"),
        "level 'ground', wall 'b' has zero length: it starts and ends at (2, 2) "
        "(remove it or move one end)",
    ),
    (
        _walls("{name: a, start: [0, 0], end: [4, 0]}", "{name: b, start: [2, -1], end: [2, 1]}"),
        "level 'ground': wall 'a' and wall 'b' cross at (2, 0) "
        "(split the walls where they cross, so that they meet at end points)",
    ),
    (
        _walls("{name: z, points: [[0, 0], [4, 0], [4, 3], [2, -1]]}"),
        "level 'ground': wall 'z' crosses itself (segments 0 and 2) at (2.5, 0)",
    ),
    (
        _walls("{name: a, start: [0, 0], end: [4, 0]}", "{name: b, start: [3, 0], end: [6, 0]}"),
        "level 'ground': wall 'a' and wall 'b' overlap along the line through (3, 0)",
    ),
    (
        _walls(
            "{name: short, start: [0, 0], end: [1, 0], doors: [{name: d, at: 0.5, width: 1.2}]}"
        ),
        "level 'ground', wall 'short', door 'd' is 1.2 m wide but the wall is only 1 m long "
        "(make the opening narrower or the wall longer)",
    ),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0], windows: [{name: x, at: 2.8, width: 1}]}"),
        "window 'x' runs past the wall's end (from 2.3 to 3.3 m along a 3 m wall) "
        "(give 'at' between 0.5 and 2.5 m",
    ),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0], height: 2, doors: [{at: 1, height: 2.2}]}"),
        "door 'w_door_0' reaches 2.2 m but the wall is 2 m high",
    ),
    (
        _walls(
            "{name: w, start: [0, 0], end: [5, 0], doors: [{name: d, at: 1}], "
            "windows: [{name: v, at: 1.5}]}"
        ),
        "window 'v' overlaps door 'd' (from 1 to 1.45 m along the wall)",
    ),
    (
        _walls("{name: l, points: [[0, 0], [2, 0], [2, 2]], doors: [{name: d, at: 0.2}]}"),
        "level 'ground', wall 'l' (segment 0), door 'd' runs past the wall's end "
        "(from -0.25 to 0.65 m along a 2 m wall)",
    ),
    (_walls("{name: w, start: [0, 0], end: [3, 0], thicknes: 0.2}"), "unknown key 'thicknes'"),
    (_walls("{name: w, start: [0, 0]}"), "wall 'w' needs 'start' and 'end' (or 'points')"),
    (_walls("{name: w, start: [0, 0], end: [3, 'x']}"), "wall 'w': 'end' must be a point [x, y]"),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0], thickness: 0}"),
        "wall 'w': thickness must be a positive number of metres, got 0",
    ),
    (
        # the world file writes lengths to the micrometre: 1e-7 m would come out as 0
        _walls("{name: w, start: [0, 0], end: [3, 0], height: 0.0000001}"),
        "wall 'w': height must be at least 0.001 m, got 1e-07",
    ),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0]}", "{name: w, start: [3, 0], end: [3, 3]}"),
        "a wall and a wall are both named 'w' (rename one)",
    ),
    ("walls: []", "the plan has no walls"),
    (
        # the simulator refuses such a world: the plan is refused first
        "max_step_size: 1.0e-300\n" + _walls("{name: w, start: [0, 0], end: [3, 0]}"),
        "the plan: 'max_step_size' must be in [0.0001, 0.1] s, got 1e-300",
    ),
    ("image: map.pgm\nresolution: 0.05", "this is a map_server map, not a building plan"),
    ("- just a list", "the plan must be a mapping of keys to values, got list"),
    ("walls: [{start: [0, 0", "plan file is not valid YAML"),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0]}")
        + "stairs: [{from: ground, to: attic, start: [0, 0], length: 2}]",
        "no level named 'attic' (levels: ground)",
    ),
    (
        _walls("{name: w, start: [0, 0], end: [3, 0]}")
        + "furniture: [{name: t, type: sofa, at: [1, 1], size: [1, 1, 1]}]",
        "furniture 0: unknown type 'sofa'",
    ),
]


@pytest.mark.parametrize(("text", "message"), BAD_PLANS)
def test_bad_plans_are_one_line_naming_the_element(tmp_path, text, message):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(PlanError) as info:
        load_plan(path)
    line = info.value.one_line()
    assert "\n" not in line
    assert line.startswith(f"{path}")
    assert message in line


def _image(path, fill: int) -> None:
    write_pgm(path, np.full((40, 60), fill, dtype=np.uint8))


@pytest.mark.parametrize(
    ("fill", "message"),
    [
        (0, "every pixel is wall, so this is not a floor plan (a floor plan has dark walls"),
        (255, "no walls: no pixel is dark enough to be a wall, so this is not a floor plan"),
        (205, "no walls"),  # all unknown, as a map_server map before mapping
    ],
)
def test_images_that_are_not_floor_plans(tmp_path, fill, message):
    path = tmp_path / "blank.pgm"
    _image(path, fill)
    with pytest.raises(PlanError, match="not a floor plan|no walls") as info:
        plan_from_image(path, resolution=0.05)
    assert info.value.one_line().startswith(str(path)) and message in info.value.one_line()


def test_image_options_and_files(tmp_path):
    path = tmp_path / "plan.pgm"
    pixels = np.full((40, 60), 254, dtype=np.uint8)
    pixels[10:12, 5:50] = 0
    write_pgm(path, pixels)
    with pytest.raises(PlanError, match="the image's scale is unknown .*--resolution"):
        plan_from_image(path)
    with pytest.raises(PlanError, match="resolution must be a positive number"):
        plan_from_image(path, resolution=-1)
    with pytest.raises(PlanError, match="no walls left after dropping specks under 500 pixels"):
        plan_from_image(path, resolution=0.05, min_pixels=500)
    (tmp_path / "text.png").write_text("not an image")
    with pytest.raises(PlanError, match="not an image"):
        plan_from_image(tmp_path / "text.png", resolution=0.05)
    with pytest.raises(PlanError, match="not found"):
        plan_from_image(tmp_path / "missing.pgm", resolution=0.05)


def test_the_cli_builds_a_world_and_lists_the_shipped_ones(run_cli, repo_root, tmp_path):
    out = tmp_path / "room.world"
    result = run_cli("world", "build", repo_root / "mapping" / "plans" / "lab_room.yaml", "-o", out)
    assert result.returncode == 0, result.stderr
    assert "building 'lab_room': 1 level, 4 walls, 1 door" in result.stdout
    assert f"wrote {out}" in result.stdout and out.is_file()
    (tmp_path / "models").mkdir()
    folder = tmp_path / "models" / "lab_room"
    result = run_cli(
        "world", "build", repo_root / "mapping" / "demo_rooms.yaml", "-o", folder, "--model"
    )
    assert result.returncode == 0, result.stderr
    assert (folder / "model.config").is_file() and (folder / "model.sdf").is_file()
    listed = run_cli("world", "list")
    assert listed.returncode == 0
    for name in ("arena", "house", "lab_room", "empty"):
        assert f"\n{name} " in f"\n{listed.stdout}"


@pytest.mark.parametrize(
    ("plan", "extra", "message"),
    [
        (
            "walls: [{name: w, start: [1, 1], end: [1, 1]}]",
            [],
            "wall 'w' has zero length",
        ),
        (
            "walls: [{name: a, start: [0, 0], end: [2, 2]}, {name: b, start: [0, 2], end: [2, 0]}]",
            [],
            "wall 'a' and wall 'b' cross at (1, 1)",
        ),
        (
            "walls: [{name: w, start: [0, 0], end: [1, 0], doors: [{name: d, at: 0.5, width: 2}]}]",
            [],
            "door 'd' is 2 m wide but the wall is only 1 m long",
        ),
        (
            "walls: [{name: w, start: [0, 0], end: [1, 0]}]",
            ["--resolution", "0.1"],
            "are for images",
        ),
        ("black", ["--resolution", "0.05"], "every pixel is wall, so this is not a floor plan"),
        ("white", ["--resolution", "0.05"], "no walls: no pixel is dark enough"),
    ],
)
def test_the_cli_reports_bad_input_in_one_line(run_cli, tmp_path, plan, extra, message):
    if plan in ("black", "white"):
        path = tmp_path / f"{plan}.pgm"
        _image(path, 0 if plan == "black" else 255)
    else:
        path = tmp_path / "plan.yaml"
        path.write_text(plan)
    result = run_cli("world", "build", path, "-o", tmp_path / "out.world", *extra)
    assert result.returncode != 0
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith(f"workbench world: error: {path}")
    assert message in lines[0]
    assert not (tmp_path / "out.world").exists()


def _first_meeting_pair(walls):
    """The first pair (in order) that crosses or overlaps, checked one pair at a time."""
    from itertools import combinations

    from workbench.sim.building.checks import _segments_meet

    for a, b in combinations(range(len(walls)), 2):
        if _segments_meet(walls[a], walls[b]) is not None:
            return a, b
    return None


@pytest.mark.parametrize("seed", range(6))
def test_the_fast_crossing_check_finds_the_same_first_pair_as_checking_each_pair(seed):
    from workbench.sim.building import Wall
    from workbench.sim.building.checks import _candidate_pairs, _segments_meet

    rng = np.random.default_rng(seed)
    # end points on a coarse grid: walls that touch at ends, T-junctions, collinear
    # overlaps and parallel neighbours are all common, as in drawn plans
    points = rng.integers(0, 6, size=(60, 4)).astype(float) * 0.5
    walls = [
        Wall(name=f"w{i}", start=(p[0], p[1]), end=(p[2], p[3]))
        for i, p in enumerate(points)
        if (p[0], p[1]) != (p[2], p[3])
    ]
    for count in range(2, len(walls) + 1):  # every prefix: the first problem moves
        subset = walls[:count]
        fast = next(
            ((i, j) for i, j in _candidate_pairs(subset) if _segments_meet(subset[i], subset[j])),
            None,
        )
        assert fast == _first_meeting_pair(subset), count


def test_plans_past_their_bounds_are_refused_in_seconds(tmp_path):
    import json

    walls = [{"name": f"w{i}", "start": [0, i * 0.5], "end": [3, i * 0.5]} for i in range(5001)]
    path = tmp_path / "walls.json"
    path.write_text(json.dumps({"walls": walls}))
    with pytest.raises(PlanError, match="more than 5,000 walls"):
        load_plan(path)
    chain = {"walls": [{"name": "c", "points": [[i, i % 2] for i in range(5002)]}]}
    path.write_text(json.dumps(chain))
    with pytest.raises(PlanError, match="more than 5,000 walls"):
        load_plan(path)
    doors = [{"name": f"d{i}", "at": 0.5 + i, "width": 0.5} for i in range(2000)]
    path.write_text(
        json.dumps(
            {
                "walls": [
                    {
                        "name": "w",
                        "start": [0, 0],
                        "end": [3000, 0],
                        "doors": doors + [{"name": "late", "at": 0.6}],
                    }
                ]
            }
        )
    )
    with pytest.raises(PlanError, match="door 'late' overlaps door 'd0'"):
        load_plan(path)
