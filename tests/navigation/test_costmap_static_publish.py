"""The static layer's reading of map values (StaticLayer::interpretValue) and the published
cost translation (Costmap2DPublisher, costmap_2d Noetic)."""

from __future__ import annotations

import numpy as np

from workbench.msgs import Time
from workbench.navigation.costmap_grid import Costmap2D
from workbench.navigation.costmap_publish import COST_TRANSLATION, costmap_message, translate
from workbench.navigation.costmap_static import interpret_values

VALUES = np.array([-1, 0, 1, 50, 64, 65, 99, 100], dtype=np.int8)


def test_defaults_are_trinary_with_unknown_tracked():
    assert interpret_values(VALUES).tolist() == [255, 0, 0, 0, 0, 0, 0, 254]


def test_unknown_is_free_without_tracking_and_the_threshold_decides_lethal():
    out = interpret_values(VALUES, track_unknown_space=False, lethal_threshold=65)
    assert out.tolist() == [0, 0, 0, 0, 0, 254, 254, 254]
    # The threshold is clamped to 0..100: 150 acts as 100.
    assert interpret_values(VALUES, lethal_threshold=150).tolist()[-2:] == [0, 254]


def test_non_trinary_scales_values_to_the_threshold():
    out = interpret_values(VALUES, trinary_costmap=False)
    # value / 100 * 254, truncated: 1 -> 2, 50 -> 127, 64 -> 162, 65 -> 165, 99 -> 251
    assert out.tolist() == [255, 0, 2, 127, 162, 165, 251, 254]


def test_another_unknown_value_is_read_as_an_unsigned_byte():
    # unknown_cost_value 255 is -1 in the message's int8; 50 then means unknown
    assert interpret_values(VALUES, unknown_cost_value=255).tolist()[0] == 255
    assert interpret_values(VALUES, unknown_cost_value=50).tolist()[:4] == [254, 0, 0, 255]


def test_cost_translation_table():
    # 0 -> 0, 253 -> 99, 254 -> 100, 255 -> -1, 1..252 -> 1 + 97 * (c - 1) / 251
    assert COST_TRANSLATION[[0, 1, 2, 127, 252, 253, 254, 255]].tolist() == [
        0,
        1,
        1,
        49,
        98,
        99,
        100,
        -1,
    ]
    assert COST_TRANSLATION.dtype == np.int8
    assert np.all(np.diff(COST_TRANSLATION[1:253].astype(int)) >= 0)
    assert translate(np.array([[0, 254], [255, 253]], np.uint8)).tolist() == [[0, 100], [-1, 99]]


def test_the_message_has_the_grid_origin_and_row_major_data():
    costs = np.array([[0, 254, 255], [253, 100, 1]], np.uint8)
    msg = costmap_message(Costmap2D(costs, 0.1, -1.5, 2.0, "odom"), Time.from_sec(3.0))
    assert msg.header.frame_id == "odom" and msg.header.stamp.to_sec() == 3.0
    assert (msg.info.width, msg.info.height) == (3, 2)
    assert abs(msg.info.resolution - 0.1) < 1e-7
    assert abs(msg.info.origin.position.x + 1.5) < 1e-12
    assert abs(msg.info.origin.position.y - 2.0) < 1e-12  # (0.5 * res + 2) - 0.5 * res
    assert msg.info.origin.orientation.w == 1.0
    assert np.asarray(msg.data).tolist() == [0, 100, -1, 99, 39, 1]
