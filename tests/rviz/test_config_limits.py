"""The bounds of ``.rviz`` configs and of the Grid display, from Python (a notebook's API).

The hostile configs themselves, through ``workbench rviz``, are in
``tests/data/hostile/rviz/``; here: the bounds are exact (500 displays load, 501 do not),
``GridDisplay`` refuses what ``-d`` refuses, and Ctrl-C stops the reading of the largest
config the bounds let through.
"""

from __future__ import annotations

import math
import os
import signal
import threading

import pytest
from fuzz_helpers import bounded

from workbench.errors import ViewerError
from workbench.rviz.config import MAX_DISPLAYS, MAX_GROUP_DEPTH, load_config
from workbench.rviz.displays import MAX_GRID_CELLS, GridDisplay

HEAD = "Visualization Manager:\n  Global Options:\n    Fixed Frame: map\n  Displays:\n"


def _markers(count: int) -> str:
    return HEAD + "".join(
        f"    - {{Class: rviz/Marker, Name: m{i}, Marker Topic: m{i}}}\n" for i in range(count)
    )


def test_the_display_bound_is_exact(tmp_path):
    path = tmp_path / "many.rviz"
    path.write_text(_markers(MAX_DISPLAYS))
    assert len(load_config(path).displays) == MAX_DISPLAYS
    path.write_text(_markers(MAX_DISPLAYS + 1))
    with pytest.raises(ViewerError, match=f"lists more than {MAX_DISPLAYS} displays"):
        load_config(path)


def test_the_group_bound_is_exact(tmp_path):
    def nested(depth: int) -> str:
        group = "{Class: rviz/Group, Name: G, Displays: ["
        return HEAD + "    - " + group * depth + "{Class: rviz/TF}" + "]}" * depth + "\n"

    path = tmp_path / "groups.rviz"
    path.write_text(nested(MAX_GROUP_DEPTH))
    assert [spec.class_name for spec in load_config(path).displays] == ["TF"]
    path.write_text(nested(MAX_GROUP_DEPTH + 1))
    with pytest.raises(ViewerError, match=f"nested more than {MAX_GROUP_DEPTH} groups deep"):
        load_config(path)


@pytest.mark.parametrize(
    "cells, cell_size, message",
    [
        (MAX_GRID_CELLS + 1, 1.0, f"cells must be a whole number from 1 to {MAX_GRID_CELLS:,}"),
        (100_000_000, 1.0, "cells must be a whole number"),
        (0, 1.0, "cells must be a whole number"),
        (2.5, 1.0, "cells must be a whole number"),
        (10, math.nan, "cell_size must be a finite number above 0"),
        (10, 0.0, "cell_size must be a finite number above 0"),
    ],
)
def test_the_grid_display_refuses_what_a_config_may_not_ask(cells, cell_size, message):
    with pytest.raises(ViewerError, match=message):
        GridDisplay(cells=cells, cell_size=cell_size)


def test_the_grid_display_takes_its_bound():
    grid = GridDisplay(cells=MAX_GRID_CELLS, cell_size=0.5)
    assert (grid.cells, grid.cell_size) == (MAX_GRID_CELLS, 0.5)


def test_ctrl_c_stops_reading_the_largest_config_the_bounds_allow(tmp_path):
    # 1 MiB of YAML just under the element bound: the slowest config that is not refused
    # at once. Ctrl-C must reach the reader as KeyboardInterrupt (never swallowed or turned
    # into another error), however often it is read.
    path = tmp_path / "largest.rviz"
    path.write_text(HEAD + "    - [" + "1, " * 40_000 + "1]\n" + "#" * 700_000 + "\n")
    assert path.stat().st_size < 1024 * 1024
    assert load_config(path).displays == []
    interrupt = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    with bounded("reading the config until Ctrl-C"):
        interrupt.start()
        try:
            with pytest.raises(KeyboardInterrupt):
                while True:
                    load_config(path)
        finally:
            interrupt.cancel()
