"""The inflation layer's costs: computeCost by hand, and the distance-transform inflation
against a step-by-step port of costmap_2d's InflationLayer::updateCosts wavefront
(plugins/inflation_layer.cpp, Noetic) on random grids."""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np
import pytest

from workbench.bus import Bus, Node
from workbench.navigation.costmap_inflation import InflationLayer, compute_cost, inflate
from workbench.navigation.costmap_layer import Layer, LayeredCostmap
from workbench.navigation.costmap_params import Params


def test_compute_cost_by_hand():
    # resolution 0.05, inscribed 0.2, cost_scaling_factor 10
    d = np.array([0, 1, 4, 4.1, 5, 6, 10, 20])
    expected = [
        254,  # the obstacle itself
        253,  # 0.05 <= 0.2
        253,  # 0.2 <= 0.2
        int(252 * math.exp(-10 * (4.1 * 0.05 - 0.2))),
        int(252 * math.exp(-10 * (0.25 - 0.2))),  # 252 * e^-0.5 = 152.8 -> 152
        int(252 * math.exp(-10 * (0.30 - 0.2))),  # 92.7 -> 92
        int(252 * math.exp(-10 * (0.50 - 0.2))),  # 12.5 -> 12
        int(252 * math.exp(-10 * (1.00 - 0.2))),  # 0.08 -> 0
    ]
    assert compute_cost(d, 0.05, 0.2, 10.0).tolist() == expected
    assert expected[4:8] == [152, 92, 12, 0]


def test_one_obstacle_inflates_to_the_radius_in_whole_cells():
    costs = np.zeros((21, 21), np.uint8)
    costs[10, 10] = 254
    inflate(costs, 0.1, 0.45, 0.15, 3.0)  # ceil(0.45 / 0.1) = 5 cells
    row = costs[10, 10:17].tolist()
    tail = [int(252 * math.exp(-3.0 * (k * 0.1 - 0.15))) for k in (2, 3, 4, 5)]
    assert row == [254, 253, *tail, 0]
    assert costs[10 + 3, 10 + 4] == int(252 * math.exp(-3.0 * (0.5 - 0.15)))  # 3-4-5
    assert costs[10 + 4, 10 + 4] == 0  # hypot(4, 4) = 5.66 cells > 5


def test_unknown_cells_take_only_inscribed_costs_unless_inflate_unknown():
    costs = np.full((1, 12), 255, np.uint8)
    costs[0, 0] = 254
    plain = costs.copy()
    inflate(plain, 0.1, 1.0, 0.25, 2.0)
    assert plain[0].tolist() == [254, 253, 253] + [255] * 9
    eager = costs.copy()
    inflate(eager, 0.1, 1.0, 0.25, 2.0, inflate_unknown=True)
    assert eager[0, :3].tolist() == [254, 253, 253]
    assert eager[0, 3] == int(252 * math.exp(-2.0 * (0.3 - 0.25)))
    assert (eager[0, 3:11] < 255).all()


def test_existing_higher_costs_stay():
    costs = np.zeros((1, 8), np.uint8)
    costs[0, 0] = 254
    costs[0, 4] = 200
    inflate(costs, 0.1, 0.6, 0.1, 10.0)
    assert costs[0, 4] == 200 and costs[0, 3] == int(252 * math.exp(-10 * 0.2))


def wavefront(costs, res, inflation_radius, inscribed, factor, inflate_unknown=False):
    """InflationLayer::updateCosts over the whole grid, cell by cell (reference)."""
    out = costs.copy()
    size_y, size_x = out.shape
    cell_radius = int(max(0.0, math.ceil(inflation_radius / res)))
    seen = np.zeros_like(out, dtype=bool)
    bins: dict[float, list] = defaultdict(list)
    for j, i in np.argwhere(out == 254):
        bins[0.0].append((i, j, i, j))
    current = -1.0
    while True:
        # std::map iteration: the next larger key (keys added below the current one are
        # never visited)
        pending = [d for d in bins if d > current]
        if not pending:
            break
        dist = current = min(pending)
        cells = bins[dist]
        k = 0
        while k < len(cells):  # cells appended at this distance are processed too
            mx, my, sx, sy = cells[k]
            k += 1
            if seen[my, mx]:
                continue
            seen[my, mx] = True
            cost = int(
                compute_cost(np.array([math.hypot(mx - sx, my - sy)]), res, inscribed, factor)[0]
            )
            old = int(out[my, mx])
            if old == 255 and (cost > 0 if inflate_unknown else cost >= 253):
                out[my, mx] = cost
            elif old != 255 or not (cost > 0 if inflate_unknown else cost >= 253):
                out[my, mx] = max(old, cost)
            for nx, ny in ((mx - 1, my), (mx, my - 1), (mx + 1, my), (mx, my + 1)):
                if 0 <= nx < size_x and 0 <= ny < size_y and not seen[ny, nx]:
                    d = math.hypot(nx - sx, ny - sy)
                    if d <= cell_radius:
                        bins[d].append((nx, ny, sx, sy))
    return out


def cells_differing(seed: int) -> int:
    """Inflate a random grid both ways; equal in all but a few cells, where the wavefront
    had settled for a farther obstacle than the nearest: costmap_2d's cost is lower there
    and ours the exact one."""
    rng = np.random.default_rng(seed)
    costs = np.zeros((30, 40), np.uint8)
    costs[rng.random(costs.shape) < 0.03] = 254
    costs[rng.random(costs.shape) < 0.05] = 255
    costs[5:25, 20] = 254  # a wall
    inscribed, radius, factor = 0.1 + 0.02 * seed, 0.35 + 0.05 * seed, 4.0 + seed
    ours = costs.copy()
    inflate(ours, 0.05, radius, inscribed, factor, inflate_unknown=bool(seed % 2))
    theirs = wavefront(costs, 0.05, radius, inscribed, factor, inflate_unknown=bool(seed % 2))
    differ = ours != theirs
    assert differ.mean() < 0.005, np.argwhere(differ)
    assert (ours[differ] > theirs[differ]).all()
    assert (theirs[differ] < 253).all()  # never in the inscribed radius
    return int(differ.sum())


@pytest.mark.parametrize("seed", range(6))
def test_distance_transform_inflation_matches_costmap_2ds_wavefront(seed):
    cells_differing(seed)


def test_the_wavefront_reference_differs_from_the_exact_distance_somewhere():
    counts = [cells_differing(seed) for seed in range(6)]
    assert counts[2] >= 1 and counts.count(0) >= 3, counts


class Marks(Layer):
    """A layer writing lethal cells (a stand-in for the obstacle layer)."""

    def __init__(self) -> None:
        super().__init__("marks")
        self.cells: list[tuple[int, int]] = []

    def update_costs(self, master, layered) -> None:
        for x, y in self.cells:
            master.costs[y, x] = 254


def test_the_layer_reinflates_when_obstacles_change_and_reuses_an_unchanged_result():
    bus = Bus()
    try:
        node = Node("move_base", bus=bus, disable_rosout=True)
        bus.params.set("/move_base/c/inflation_layer/inflation_radius", 0.3)
        layered = LayeredCostmap("map", rolling_window=False, track_unknown_space=False)
        layered.resize_map(30, 20, 0.05, 0.0, 0.0)
        marks = Marks()
        layered.add(marks)
        layered.add(
            InflationLayer("inflation_layer", Params(node, "/move_base/c/inflation_layer"), None)
        )
        layered.set_footprint([(0.1, 0.1), (-0.1, 0.1), (-0.1, -0.1), (0.1, -0.1)])
        for cells in ([(5, 5)], [(5, 5)], [(20, 12), (21, 12)], []):
            marks.cells = cells
            layered.update_map(0.0, 0.0, 0.0)
            expected = np.zeros((20, 30), np.uint8)
            for x, y in cells:
                expected[y, x] = 254
            inflate(expected, 0.05, 0.3, 0.1, 10.0)
            np.testing.assert_array_equal(layered.master.costs, expected)
        assert (layered.master.costs == 0).all()
    finally:
        bus.shutdown()


@pytest.mark.parametrize("seed", range(3))
def test_inflating_only_near_the_changes_equals_inflating_everything(seed):
    from workbench.navigation.costmap_inflation import inflate, inflate_changes

    rng = np.random.default_rng(seed)
    first = np.where(rng.random((80, 90)) < 0.03, 254, 0).astype(np.uint8)
    first[:5, :] = 255
    inflated = first.copy()
    inflate(inflated, 0.05, 0.5, 0.1, 3.0)
    second = first.copy()
    second[40:43, 10:12] = 254  # a new obstacle
    second[70, 85] = 0  # one cleared
    expected = second.copy()
    inflate(expected, 0.05, 0.5, 0.1, 3.0)
    assert np.array_equal(inflate_changes(first, inflated, second, 0.05, 0.5, 0.1, 3.0), expected)
    assert np.array_equal(inflate_changes(first, inflated, first, 0.05, 0.5, 0.1, 3.0), inflated)
