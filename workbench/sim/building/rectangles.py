"""Cover the true cells of a boolean grid with few axis-aligned rectangles, exactly."""

from __future__ import annotations

import numpy as np

#: (row0, row1, col0, col1): rows row0..row1-1 and columns col0..col1-1.
Rectangle = tuple[int, int, int, int]


def rectangles(mask: np.ndarray) -> list[Rectangle]:
    """Disjoint rectangles whose union is exactly the true cells of ``mask`` (2-D).

    Runs of true cells along rows are merged with the same run in the next rows;
    the same is done along columns, and the answer with fewer rectangles wins
    (a horizontal wall is one run per row, a vertical one one run per column).
    """
    grid = np.asarray(mask, dtype=bool)
    if grid.ndim != 2:
        raise ValueError("mask must be 2-D")
    by_rows = _row_rectangles(grid)
    by_columns = [(c0, c1, r0, r1) for r0, r1, c0, c1 in _row_rectangles(grid.T)]
    return by_rows if len(by_rows) <= len(by_columns) else by_columns


def _row_rectangles(grid: np.ndarray) -> list[Rectangle]:
    height, width = grid.shape
    padded = np.zeros((height, width + 2), dtype=np.int8)
    padded[:, 1:-1] = grid
    steps = np.diff(padded, axis=1)  # +1 where a run starts, -1 one past its end
    starts_r, starts_c = np.nonzero(steps == 1)
    _, ends_c = np.nonzero(steps == -1)  # row-major order: paired with the starts
    done: list[Rectangle] = []
    open_runs: dict[tuple[int, int], int] = {}  # (col0, col1) -> first row
    index, count = 0, len(starts_r)
    for row in range(height + 1):
        runs: set[tuple[int, int]] = set()
        while index < count and starts_r[index] == row:
            runs.add((int(starts_c[index]), int(ends_c[index])))
            index += 1
        for run in [r for r in open_runs if r not in runs]:
            done.append((open_runs.pop(run), row, run[0], run[1]))
        for run in runs:
            open_runs.setdefault(run, row)
    return sorted(done)
