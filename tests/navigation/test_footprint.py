"""Footprints as costmap_2d reads, pads and measures them (footprint.cpp, Noetic)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.navigation.costmap_errors import CostmapError
from workbench.navigation.footprint import (
    footprint_from_radius,
    footprint_string,
    inscribed_and_circumscribed,
    pad_footprint,
    parse_footprint,
    transform_footprint,
)

SQUARE = [[0.2, 0.2], [-0.2, 0.2], [-0.2, -0.2], [0.2, -0.2]]


def test_a_list_and_the_same_as_a_string_give_one_polygon():
    as_list = parse_footprint(SQUARE, "/move_base/local_costmap/footprint")
    as_text = parse_footprint("[[0.2, 0.2], [-0.2, 0.2], [-0.2, -0.2], [0.2, -0.2]]", "x")
    assert as_list == as_text == [(0.2, 0.2), (-0.2, 0.2), (-0.2, -0.2), (0.2, -0.2)]
    assert parse_footprint([[1, 0], [0, 1], [-1, -1]], "x") == [(1.0, 0.0), (0.0, 1.0), (-1, -1)]


@pytest.mark.parametrize(
    "value",
    [
        [[0.2, 0.2], [-0.2, 0.2]],  # two points
        [[0.2, 0.2], [-0.2, 0.2], [0.1]],  # not a pair
        [[0.2, 0.2], [-0.2, 0.2], ["a", 0.1]],  # not numbers
        [[0.2, 0.2], [-0.2, 0.2], [True, 0.1]],
        "[[0.2, 0.2], [-0.2, 0.2]",  # unreadable string
        0.3,
        "square",
    ],
)
def test_a_footprint_that_is_not_a_polygon_is_one_line_naming_the_parameter(value):
    with pytest.raises(CostmapError) as error:
        parse_footprint(value, "/move_base/local_costmap/footprint")
    text = str(error.value)
    assert "\n" not in text
    assert "parameter /move_base/local_costmap/footprint is not a polygon" in text


def test_padding_moves_vertices_away_from_the_axes():
    padded = pad_footprint([(0.2, 0.2), (-0.2, 0.0), (0.0, -0.3)], 0.01)
    np.testing.assert_allclose(padded, [(0.21, 0.21), (-0.21, 0.0), (0.0, -0.31)])


def test_radii_of_a_square_and_a_triangle():
    inscribed, circumscribed = inscribed_and_circumscribed([tuple(p) for p in SQUARE])
    assert inscribed == pytest.approx(0.2)
    assert circumscribed == pytest.approx(math.hypot(0.2, 0.2))
    # The two slanted edges pass 2 / sqrt(10) m from the centre, the vertex (-2, 0) is 2 m.
    assert inscribed_and_circumscribed([(1, -1), (1, 1), (-2, 0)]) == pytest.approx(
        (2 / math.sqrt(10), 2.0)
    )


def test_a_radius_becomes_a_16_gon_and_footprints_are_placed_and_written_back():
    circle = footprint_from_radius(0.105)
    assert len(circle) == 16
    assert circle[0] == pytest.approx((0.105, 0.0)) and circle[4] == pytest.approx((0.0, 0.105))
    placed = transform_footprint(1.0, 2.0, math.pi / 2, [(0.2, 0.1)])
    np.testing.assert_allclose(placed, [[0.9, 2.2]])
    assert footprint_string([(0.2, 0.2), (-0.25, 0.125)]) == "[[0.2,0.2],[-0.25,0.125]]"
