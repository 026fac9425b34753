"""The building editor's image import: dark pixels become wall boxes at the image's resolution."""

from __future__ import annotations

import numpy as np
import pytest
from building_helpers import clearance, occupancy, world_from_file

from workbench.mapping.pgm import write_pgm
from workbench.sim.building import plan_from_image
from workbench.sim.building.rectangles import rectangles

#: Known walls in metres (x0, y0, x1, y1) on a 4 m x 3 m image at 0.02 m/pixel.
RESOLUTION = 0.02
WIDTH, HEIGHT = 200, 150
WALLS = [
    (0.0, 0.0, 4.0, 0.1),  # south
    (0.0, 2.9, 4.0, 3.0),  # north
    (0.0, 0.1, 0.1, 2.9),  # west
    (3.9, 0.1, 4.0, 2.9),  # east
    (2.0, 0.1, 2.08, 1.9),  # a partition with a gap above it
    (0.6, 1.2, 1.0, 1.6),  # a pillar
]


def _synthetic(path, walls=WALLS) -> np.ndarray:
    """Write a PGM with ``walls`` black on white; returns the true wall mask (rows top-down)."""
    mask = np.zeros((HEIGHT, WIDTH), dtype=bool)
    for x0, y0, x1, y1 in walls:
        c0, c1 = round(x0 / RESOLUTION), round(x1 / RESOLUTION)
        r0, r1 = HEIGHT - round(y1 / RESOLUTION), HEIGHT - round(y0 / RESOLUTION)
        mask[r0:r1, c0:c1] = True
    pixels = np.where(mask, 0, 254).astype(np.uint8)
    write_pgm(path, pixels)
    return mask


def test_rectangles_cover_a_mask_exactly_with_few_boxes():
    rng = np.random.default_rng(3)
    mask = rng.random((40, 50)) < 0.3
    mask[5:8, :] = True
    boxes = rectangles(mask)
    rebuilt = np.zeros_like(mask, dtype=int)
    for r0, r1, c0, c1 in boxes:
        rebuilt[r0:r1, c0:c1] += 1
    assert rebuilt.max() == 1  # disjoint
    np.testing.assert_array_equal(rebuilt.astype(bool), mask)
    # a vertical and a horizontal bar are one rectangle each
    bars = np.zeros((30, 30), dtype=bool)
    bars[2:28, 3:5] = True
    assert rectangles(bars) == [(2, 28, 3, 5)]
    assert rectangles(bars.T) == [(3, 5, 2, 28)]


def test_a_synthetic_plan_gives_walls_covering_its_rectangles(tmp_path):
    path = tmp_path / "plan.pgm"
    truth = _synthetic(path)
    plan = plan_from_image(path, resolution=RESOLUTION, height=2.0, origin=(1.0, -2.0))
    assert plan.name == "plan" and plan.traced
    pieces = plan.pieces()
    assert all(p.size[2] == pytest.approx(2.0) and p.pose[2] == pytest.approx(1.0) for p in pieces)
    # rasterise the boxes back at the same resolution, shifted back by the origin
    blocked, _, _ = occupancy(pieces, (1.0, -2.0), (1.0 + 4.0, -2.0 + 3.0), cell=RESOLUTION)
    expected = truth[::-1]  # the occupancy grid's rows run along +y
    iou = (blocked & expected).sum() / (blocked | expected).sum()
    assert iou > 0.9
    assert len(plan.walls) <= 10  # rectangles, not pixels
    # the partition is one wall of 8 cm from y = 0.1 to 1.9 (image coordinates + origin)
    partition = [w for w in plan.walls if abs(w.thickness - 0.08) < 1e-9]
    assert len(partition) == 1
    (wall,) = partition
    np.testing.assert_allclose(sorted([wall.start[1], wall.end[1]]), [-1.9, -0.1], atol=1e-9)
    np.testing.assert_allclose([wall.start[0], wall.end[0]], [3.04, 3.04], atol=1e-9)


def test_a_traced_plan_loads_in_the_simulator(tmp_path, caplog):
    path = tmp_path / "plan.pgm"
    _synthetic(path)
    world_path = tmp_path / "plan.world"
    plan_from_image(path, resolution=RESOLUTION).save(world_path)
    world = world_from_file(world_path, caplog)
    assert clearance(world, [2.04, 1.0, 1.0]) < 0  # inside the partition
    assert clearance(world, [2.04, 2.4, 1.0]) > 0.3  # the gap above it
    assert clearance(world, [0.8, 1.4, 0.5]) < 0  # the pillar


@pytest.mark.parametrize(
    ("name", "walls"), [("demo_rooms.yaml", (50, 400)), ("intel_lab.yaml", (500, 5000))]
)
def test_the_shipped_maps_convert(repo_root, tmp_path, name, walls):
    plan = plan_from_image(repo_root / "mapping" / name)
    assert walls[0] <= len(plan.walls) <= walls[1]
    # the map's origin places the walls where the map has them
    from workbench.mapping import load_map

    grid = load_map(repo_root / "mapping" / name)
    occupied = np.argwhere(grid.data >= 65)
    row, col = occupied[len(occupied) // 2]
    x = grid.origin[0] + (col + 0.5) * grid.resolution
    y = grid.origin[1] + (row + 0.5) * grid.resolution
    blocked, _, _ = occupancy(plan.pieces(), (x - 0.01, y - 0.01), (x + 0.01, y + 0.01), 0.01)
    assert blocked.all()
    text = plan.to_sdf()
    assert text.count("<collision") == len(plan.walls)


def test_the_pgm_of_a_map_converts_with_a_resolution(repo_root):
    plan = plan_from_image(repo_root / "mapping" / "demo_rooms.pgm", resolution=0.05)
    assert len(plan.walls) > 50
    despeckled = plan_from_image(
        repo_root / "mapping" / "intel_lab.pgm", resolution=0.1, min_pixels=5
    )
    assert len(despeckled.walls) < len(
        plan_from_image(repo_root / "mapping" / "intel_lab.yaml").walls
    )


def test_png_with_light_walls_and_negate(tmp_path):
    from PIL import Image

    pixels = np.zeros((50, 80), dtype=np.uint8)
    pixels[10:40, 20:24] = 255
    Image.fromarray(pixels).save(tmp_path / "negated.png")
    plan = plan_from_image(tmp_path / "negated.png", resolution=0.1, negate=True)
    ((wall),) = plan.walls
    assert wall.thickness == pytest.approx(0.4) and wall.length == pytest.approx(3.0)
